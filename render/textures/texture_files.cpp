// boreas textures: writing and reading the texture set's folder through OpenImageIO.
#include "textures/texture_files.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <future>
#include <string>
#include <system_error>
#include <vector>

#include "textures/leaf_kinds.h"

namespace boreas::render {
namespace {

namespace fs = std::filesystem;

double srgb_encode(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

uint8_t to_unorm8(double x) { return uint8_t(std::lround(std::clamp(x, 0.0, 1.0) * 255.0)); }

// How a channel is stored in an 8-bit file.
enum class Encoding { kLinear, kSrgb, kSignedUnit };

uint8_t encode8(double x, Encoding e) {
  switch (e) {
    case Encoding::kSrgb:
      return to_unorm8(srgb_encode(x));
    case Encoding::kSignedUnit:
      return to_unorm8(0.5 + 0.5 * x);
    case Encoding::kLinear:
      break;
  }
  return to_unorm8(x);
}

// Copies src (channels per texel, row 0 at v = 0) into file order (top row at v = 1),
// converting each value with convert(value, channel).
template <class T, class Convert>
std::vector<T> to_file_rows(const std::vector<float>& src, int width, int height, int channels,
                            Convert&& convert) {
  std::vector<T> out(src.size());
  size_t row = size_t(width) * channels;
  for (int y = 0; y < height; ++y) {
    const float* from = &src[size_t(height - 1 - y) * row];
    T* to = &out[size_t(y) * row];
    for (size_t k = 0; k < row; ++k) to[k] = convert(from[k], int(k % channels));
  }
  return out;
}

void write_image(const fs::path& folder, const char* name, int width, int height, int channels,
                 OIIO::TypeDesc type, const void* pixels) {
  fs::path path = folder / name;
  // The temporary name keeps the extension (OpenImageIO picks the format by it) and holds
  // the process id, so two processes saving into one folder do not write the same file.
  fs::path partial = folder / (path.stem().string() + ".partial-" + std::to_string(::getpid()) +
                               path.extension().string());
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw TextureError(path.string() + ": cannot write: " + OIIO::geterror());
  OIIO::ImageSpec spec(width, height, channels, type);
  if (type == OIIO::TypeDesc::FLOAT) {
    spec.attribute("compression", "zip");
    // OpenEXR files get the time of writing (capDate) unless one is given: an empty one
    // keeps a set's bytes a function of its seed alone (the same seed wrote different
    // bytes across a second boundary, caught by TextureFiles.SameSeedWritesTheSameBytes).
    spec.attribute("DateTime", "");
  }
  // The albedo's colour is not premultiplied by its alpha (the mask), and must be stored as
  // it is: OpenImageIO would otherwise divide it by alpha, losing it where alpha is 0.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(partial.string(), spec) || !out->write_image(type, pixels) || !out->close()) {
    std::string why = out->geterror();
    std::error_code ignored;
    fs::remove(partial, ignored);
    throw TextureError(path.string() + ": cannot write: " + why);
  }
  std::error_code ec;
  fs::rename(partial, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(partial, ignored);
    throw TextureError(path.string() +
                       ": cannot move the finished file into place: " + ec.message());
  }
}

void write_8bit(const fs::path& folder, const char* name, const std::vector<float>& src, int width,
                int height, int channels, const Encoding (&encodings)[4]) {
  auto bytes = to_file_rows<uint8_t>(src, width, height, channels,
                                     [&](float x, int c) { return encode8(x, encodings[c]); });
  write_image(folder, name, width, height, channels, OIIO::TypeDesc::UINT8, bytes.data());
}

void check_size(const char* what, const std::vector<float>& v, int width, int height,
                int channels) {
  if (width < 1 || height < 1 || v.size() != size_t(width) * height * channels) {
    throw TextureError(std::string("save_texture_set: ") + what + " has " +
                       std::to_string(v.size()) + " values, but " + std::to_string(width) + " x " +
                       std::to_string(height) + " texels need " +
                       std::to_string(size_t(std::max(width, 0)) * std::max(height, 0) * channels));
  }
}

// An image read back in memory order (row 0 at v = 0), as floats: integer formats scaled to
// 0..1, float formats as stored.
struct LoadedImage {
  int width = 0;
  int height = 0;
  std::vector<float> pixels;
};

LoadedImage read_image(const fs::path& folder, const char* name, int channels, const char* layout) {
  fs::path path = folder / name;
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    throw TextureError(path.string() + ": missing; a texture set folder holds leaf_albedo.png, " +
                       "leaf_normal.png, leaf_thickness.png, leaf_hl2.exr, " +
                       "leaf_translucency.png, bark_albedo.png and bark_normal.png");
  }
  // Colour is read as stored, not multiplied by alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) throw TextureError(path.string() + ": unreadable: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels != channels) {
    throw TextureError(path.string() + ": has " + std::to_string(spec.nchannels) +
                       " channels, expected " + std::to_string(channels) + " (" + layout + ")");
  }
  LoadedImage image;
  image.width = spec.width;
  image.height = spec.height;
  size_t row = size_t(spec.width) * channels;
  std::vector<float> file_rows(row * spec.height);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, file_rows.data())) {
    throw TextureError(path.string() + ": unreadable: " + in->geterror());
  }
  image.pixels.resize(file_rows.size());
  for (int y = 0; y < spec.height; ++y) {
    std::copy_n(&file_rows[size_t(spec.height - 1 - y) * row], row, &image.pixels[size_t(y) * row]);
  }
  return image;
}

void require_same_size(const fs::path& folder, const char* name, const LoadedImage& image,
                       const char* reference_name, const LoadedImage& reference,
                       const char* group) {
  if (image.width != reference.width || image.height != reference.height) {
    throw TextureError((folder / name).string() + ": is " + std::to_string(image.width) + " x " +
                       std::to_string(image.height) + ", but " + reference_name + " is " +
                       std::to_string(reference.width) + " x " + std::to_string(reference.height) +
                       "; the " + group + " images must all be one size");
  }
}

void decode_srgb(std::vector<float>& pixels, int channels, int color_channels) {
  for (size_t i = 0; i < pixels.size(); ++i) {
    if (int(i % channels) < color_channels) pixels[i] = float(srgb_decode(pixels[i]));
  }
}

// Stored 0.5 + 0.5 n, quantized: back to unit vectors.
void decode_normals(std::vector<float>& pixels) {
  for (size_t i = 0; i + 2 < pixels.size(); i += 3) {
    double x = 2.0 * pixels[i] - 1.0, y = 2.0 * pixels[i + 1] - 1.0, z = 2.0 * pixels[i + 2] - 1.0;
    double length = std::sqrt(x * x + y * y + z * z);
    if (length < 1e-6) {
      x = 0.0, y = 0.0, z = 1.0, length = 1.0;
    }
    pixels[i] = float(x / length);
    pixels[i + 1] = float(y / length);
    pixels[i + 2] = float(z / length);
  }
}

}  // namespace

TextureSet generate_texture_set(const LeafTextureParams& leaf, const BarkTextureParams& bark) {
  return TextureSet{generate_leaf_textures(leaf), generate_bark_textures(bark), {}};
}

void add_leaf_kinds(TextureSet& set, const std::vector<std::string>& kinds,
                    const LeafTextureParams& leaf) {
  const std::vector<LeafKind> all = leaf_kinds(leaf);
  std::vector<const LeafKind*> wanted;
  for (const std::string& name : kinds) {
    auto kind =
        std::find_if(all.begin(), all.end(), [&](const LeafKind& k) { return k.name == name; });
    if (kind == all.end()) {
      std::string list;
      for (const LeafKind& k : all) list += (list.empty() ? "" : ", ") + k.name;
      throw TextureError("unknown leaf kind '" + name + "' (the kinds are " + list + ")");
    }
    bool have = name == "broadleaf" ||
                std::any_of(set.kind_leaves.begin(), set.kind_leaves.end(),
                            [&](const KindLeafTextures& k) { return k.kind == name; }) ||
                std::find(wanted.begin(), wanted.end(), &*kind) != wanted.end();
    if (!have) wanted.push_back(&*kind);
  }
  // A kind takes about a third of a second at 512 x 512: each on its own thread (four
  // kinds at most).
  std::vector<std::future<LeafTextureSet>> pending;
  for (const LeafKind* kind : wanted) {
    pending.push_back(
        std::async(std::launch::async, [kind] { return generate_leaf_textures(kind->params); }));
  }
  for (size_t i = 0; i < wanted.size(); ++i) {
    set.kind_leaves.push_back(KindLeafTextures{wanted[i]->name, pending[i].get()});
  }
}

void save_texture_set(const TextureSet& set, const fs::path& folder) {
  const LeafTextureSet& leaf = set.leaf;
  const BarkTextureSet& bark = set.bark;
  check_size("leaf albedo", leaf.albedo, leaf.width, leaf.height, 4);
  check_size("leaf normal", leaf.normal, leaf.width, leaf.height, 3);
  check_size("leaf thickness_mm", leaf.thickness_mm, leaf.width, leaf.height, 1);
  check_size("leaf hl2", leaf.hl2, leaf.width, leaf.height, 3);
  check_size("leaf translucency", leaf.translucency, leaf.width, leaf.height, 3);
  check_size("bark albedo", bark.albedo, bark.width, bark.height, 3);
  check_size("bark normal", bark.normal, bark.width, bark.height, 3);

  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw TextureError(folder.string() + ": cannot create the folder: " + ec.message());

  using E = Encoding;
  write_8bit(folder, kLeafAlbedoFile, leaf.albedo, leaf.width, leaf.height, 4,
             {E::kSrgb, E::kSrgb, E::kSrgb, E::kLinear});
  write_8bit(folder, kLeafNormalFile, leaf.normal, leaf.width, leaf.height, 3,
             {E::kSignedUnit, E::kSignedUnit, E::kSignedUnit, E::kLinear});
  auto codes =
      to_file_rows<uint16_t>(leaf.thickness_mm, leaf.width, leaf.height, 1, [](float mm, int) {
        return uint16_t(std::clamp(std::lround(mm / kThicknessMmPerCode), 0L, 65535L));
      });
  write_image(folder, kLeafThicknessFile, leaf.width, leaf.height, 1, OIIO::TypeDesc::UINT16,
              codes.data());
  auto hl2 =
      to_file_rows<float>(leaf.hl2, leaf.width, leaf.height, 3, [](float c, int) { return c; });
  write_image(folder, kLeafHl2File, leaf.width, leaf.height, 3, OIIO::TypeDesc::FLOAT, hl2.data());
  write_8bit(folder, kLeafTranslucencyFile, leaf.translucency, leaf.width, leaf.height, 3,
             {E::kSrgb, E::kSrgb, E::kSrgb, E::kLinear});
  write_8bit(folder, kBarkAlbedoFile, bark.albedo, bark.width, bark.height, 3,
             {E::kSrgb, E::kSrgb, E::kSrgb, E::kLinear});
  write_8bit(folder, kBarkNormalFile, bark.normal, bark.width, bark.height, 3,
             {E::kSignedUnit, E::kSignedUnit, E::kSignedUnit, E::kLinear});
}

TextureSet load_texture_set(const fs::path& folder) {
  LoadedImage albedo = read_image(folder, kLeafAlbedoFile, 4, "RGBA: albedo and coverage");
  LoadedImage normal = read_image(folder, kLeafNormalFile, 3, "RGB: tangent-space normal");
  LoadedImage thickness = read_image(folder, kLeafThicknessFile, 1, "one grey channel: thickness");
  LoadedImage hl2 = read_image(folder, kLeafHl2File, 3, "RGB: three HL2 coefficients");
  LoadedImage translucency = read_image(folder, kLeafTranslucencyFile, 3, "RGB: transmittance");
  LoadedImage bark_albedo = read_image(folder, kBarkAlbedoFile, 3, "RGB: albedo");
  LoadedImage bark_normal = read_image(folder, kBarkNormalFile, 3, "RGB: tangent-space normal");
  for (auto [name, image] :
       {std::pair{kLeafNormalFile, &normal}, std::pair{kLeafThicknessFile, &thickness},
        std::pair{kLeafHl2File, &hl2}, std::pair{kLeafTranslucencyFile, &translucency}}) {
    require_same_size(folder, name, *image, kLeafAlbedoFile, albedo, "leaf");
  }
  require_same_size(folder, kBarkNormalFile, bark_normal, kBarkAlbedoFile, bark_albedo, "bark");

  decode_srgb(albedo.pixels, 4, 3);
  decode_normals(normal.pixels);
  // The thickness file is read as 0..1 of its full scale, whatever its bit depth.
  for (float& t : thickness.pixels) t = float(t * 65535.0 * kThicknessMmPerCode);
  decode_srgb(translucency.pixels, 3, 3);
  decode_srgb(bark_albedo.pixels, 3, 3);
  decode_normals(bark_normal.pixels);

  TextureSet set;
  set.leaf.width = albedo.width;
  set.leaf.height = albedo.height;
  set.leaf.albedo = std::move(albedo.pixels);
  set.leaf.normal = std::move(normal.pixels);
  set.leaf.thickness_mm = std::move(thickness.pixels);
  set.leaf.hl2 = std::move(hl2.pixels);
  set.leaf.translucency = std::move(translucency.pixels);
  set.bark.width = bark_albedo.width;
  set.bark.height = bark_albedo.height;
  set.bark.albedo = std::move(bark_albedo.pixels);
  set.bark.normal = std::move(bark_normal.pixels);
  return set;
}

}  // namespace boreas::render
