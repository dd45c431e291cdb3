// boreas textures: the texture set's folder. A set is written as, and read back from, a
// folder of images with fixed names, so that a user can replace generated textures with
// painted or photographed ones:
//
//   leaf_albedo.png        RGBA 8-bit: RGB sRGB-encoded albedo, A the coverage mask (linear)
//   leaf_normal.png        RGB 8-bit: tangent-space normal as 0.5 + 0.5 n
//   leaf_thickness.png     grey 16-bit: thickness in units of 0.1 micrometre
//                          (mm = code * 1e-4, at most 6.5535 mm)
//   leaf_hl2.exr           RGB 32-bit float: the three HL2 coefficients (may be negative)
//   leaf_translucency.png  RGB 8-bit: sRGB-encoded transmittance at normal incidence
//   bark_albedo.png        RGB 8-bit: sRGB-encoded albedo
//   bark_normal.png        RGB 8-bit: tangent-space normal as 0.5 + 0.5 n
//
// Images are stored upright, as an image viewer shows them: the top row is v = 1 (the leaf's
// tip), so the normal's green channel points up the picture (the OpenGL convention). In
// memory row 0 is v = 0; saving and loading flip the rows. The loader converts any bit depth
// OpenImageIO reads (a 16-bit albedo is fine) and checks channel counts and that the leaf
// images, and the bark images, are each of one size. Each file is written under a temporary
// name in the folder and renamed into place, so a reader never sees half a file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "textures/bark_textures.h"
#include "textures/leaf_textures.h"
#include "textures/texture_error.h"

namespace boreas::render {

// A leaf kind's maps (leaf_kinds.h), for the trees whose scene gives them that kind.
struct KindLeafTextures {
  std::string kind;
  LeafTextureSet maps;  // of the set's leaf's size and layout
};

struct TextureSet {
  LeafTextureSet leaf;  // every tree without maps of its own kind, and imported trees
  BarkTextureSet bark;
  // Generated only (a folder holds one leaf): trees of a kind without maps here use leaf.
  std::vector<KindLeafTextures> kind_leaves;
};

inline constexpr const char* kLeafAlbedoFile = "leaf_albedo.png";
inline constexpr const char* kLeafNormalFile = "leaf_normal.png";
inline constexpr const char* kLeafThicknessFile = "leaf_thickness.png";
inline constexpr const char* kLeafHl2File = "leaf_hl2.exr";
inline constexpr const char* kLeafTranslucencyFile = "leaf_translucency.png";
inline constexpr const char* kBarkAlbedoFile = "bark_albedo.png";
inline constexpr const char* kBarkNormalFile = "bark_normal.png";
// Thickness per code of leaf_thickness.png.
inline constexpr double kThicknessMmPerCode = 1e-4;

TextureSet generate_texture_set(const LeafTextureParams& leaf = {},
                                const BarkTextureParams& bark = {});

// Adds to set the maps of each named leaf kind (leaf_kinds.h) it lacks, made from leaf
// (size and seed) with the kind's shape and optics, on up to two threads. "broadleaf" is the
// set's leaf itself and adds nothing. Throws TextureError naming an unknown kind.
void add_leaf_kinds(TextureSet& set, const std::vector<std::string>& kinds,
                    const LeafTextureParams& leaf = {});

// Writes the seven images into folder, creating it if needed, and replacing files of the
// same names. Throws TextureError naming the file that could not be written.
void save_texture_set(const TextureSet& set, const std::filesystem::path& folder);

// Reads the seven images from folder. Throws TextureError naming the file that is missing,
// unreadable, has the wrong number of channels or a size that disagrees with the others.
TextureSet load_texture_set(const std::filesystem::path& folder);

}  // namespace boreas::render
