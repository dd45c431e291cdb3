// boreas command: the checks export-mesh and blobtree make before anything is built.
#include "cli/mesh_command_checks.h"

#include <cmath>
#include <sstream>
#include <string>

#include "cli/cli_error.h"
#include "cli/mesh_output.h"

namespace boreas::render {
namespace {

// "12:0.4" -> {12, 0.4}; the option's name and the text in the error.
std::vector<double> numbers_of(const std::string& option, const std::string& text, size_t least,
                               size_t most, const char* form) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ':')) {
    char* end = nullptr;
    double v = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(v))
      throw CliError(kExitBadInput, option + ": '" + text + "' is not " + form);
    values.push_back(v);
  }
  if (values.size() < least || values.size() > most)
    throw CliError(kExitBadInput, option + ": '" + text + "' is not " + form);
  return values;
}

int32_t branch_of(const std::string& option, const std::string& text, double v) {
  if (v < 0.0 || v > 1e9 || v != std::floor(v))
    throw CliError(kExitBadInput,
                   option + ": '" + text + "': the branch must be a whole number >= 0");
  return static_cast<int32_t>(v);
}

void check_scale(double scale) {
  if (!(std::isfinite(scale) && scale > 0.0 && scale <= 1000.0))
    throw CliError(kExitBadInput, "--scale: must be in (0, 1000] (got " + cli_number(scale) + ")");
}

}  // namespace

MeshFormat check_export_options(const ExportOptions& options) {
  MeshFormat format = checked_mesh_format(options.out);
  check_mesh_output_path(options.out);
  if (!(std::isfinite(options.time) && options.time >= 0.0 && options.time <= kMaxExportTime)) {
    throw CliError(kExitBadInput, "--time: must be in [0, " + cli_number(kMaxExportTime) +
                                      "] s (got " + cli_number(options.time) + ")");
  }
  check_scale(options.scale);
  return format;
}

BlobTreeInputs check_blobtree_options(const BlobTreeCommandOptions& options) {
  BlobTreeInputs inputs;
  inputs.format = checked_mesh_format(options.out);
  check_mesh_output_path(options.out);
  check_scale(options.scale);
  if (options.junctions != "pcm" && options.junctions != "blend")
    throw CliError(kExitBadInput,
                   "--junctions: must be pcm or blend (got '" + options.junctions + "')");
  for (const std::string& c : options.cuts) {
    std::vector<double> v = numbers_of("--cut", c, 2, 2, "BRANCH:AT (e.g. 12:0.4)");
    inputs.cuts.push_back(boreas_blobtree_cut{branch_of("--cut", c, v[0]), float(v[1])});
  }
  for (const std::string& s : options.scars) {
    std::vector<double> v =
        numbers_of("--scar", s, 2, 3, "BRANCH:STUB or BRANCH:STUB:DEPTH (e.g. 7:0.1:0.5)");
    inputs.scars.push_back(boreas_blobtree_scar{branch_of("--scar", s, v[0]), float(v[1]),
                                                float(v.size() > 2 ? v[2] : 0.5)});
  }
  return inputs;
}

}  // namespace boreas::render
