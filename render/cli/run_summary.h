// boreas command: <out>/summary.json, what a run did and how long each stage took, for
// people and for scripts (the tests read it). Its fields are listed in render/SCENES.md.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "cli/stage_times.h"
#include "scene/scene.h"

namespace boreas::render {

struct FrameStats {
  int index = 0;
  double time = 0.0;        // s, simulated time the frame shows
  std::string file;         // relative to the output folder
  float max_speed = 0.0f;   // m/s over the slice's pixels
  float mean_speed = 0.0f;  // m/s over the slice's pixels (solid ones count as 0)
  float max_sway = 0.0f;    // m: the farthest any branch end stands from its rest pose
};

struct TreeStats {
  std::string species;  // as the library was given it (files resolved)
  float position[3] = {0.0f, 0.0f, 0.0f};
  int branches = 0;
  int leaves = 0;
};

struct RunSummary {
  std::string scene_name;
  std::string scene_source;  // the file, or "built-in default"
  boreas_device_info device{};
  RunSettings run;
  long long steps = 0;
  double sim_time = 0.0;  // s
  std::vector<FrameStats> frames;
  std::vector<TreeStats> trees;  // empty: no trees, and no max_sway in the frame stats
  std::string contact_sheet;  // relative to the output folder
  StageTimes times;
};

nlohmann::ordered_json summary_json(const RunSummary& summary);

// Writes summary_json() to path; throws CliError (exit 3) when it cannot.
void write_summary(const std::string& path, const RunSummary& summary);

}  // namespace boreas::render
