// boreas textures: the built-in leaf kinds, one drawn leaf per species look: an outline
// (leaf_shape.h) and the lamina's optics (thin_slab.h) for each of
//   broadleaf  the generic ovate, serrate leaf (every tree without a kind of its own, and
//              imported trees);
//   aspen      Populus tremuloides: nearly round, finely toothed, truncate base, short tip,
//              a light yellow-green;
//   oak        Quercus kelloggii (California black oak): three deep lobes a side and a
//              terminal one, each with bristle-tipped teeth, a dark glossy green;
//   willow     Salix babylonica: lanceolate, long-pointed, finely serrate, grey-green;
//   tupelo     Nyssa sylvatica: elliptic to obovate, entire margin, dark and glossy.
// The outlines are cl/shared/leaf_outline.h's (shared with the rays); the colors are chosen to read as
// those descriptions (not measured spectra), by the reflectance and transmittance of a
// 0.2 mm lamina.
//
// Every kind keeps one layout on the texture (leaf_shape.h), so that one quad mapping serves
// all: a leaf's aspect comes from its species' LeafScaleX, its outline from its kind. A
// kind's place in leaf_kinds() is its outline's row (BOREAS_LEAF_OUTLINE_*). Which kind a
// tree wears is the scene's choice (render/scene/leaf_choice.h).
#pragma once

#include <string>
#include <vector>

#include "textures/leaf_textures.h"

namespace boreas::render {

struct LeafKind {
  std::string name;
  LeafTextureParams params;  // at base's size and seed (leaf_kinds)
};

// The kinds above, broadleaf first, each made from base (size, seed, thicknesses) with its
// own shape and optics.
std::vector<LeafKind> leaf_kinds(const LeafTextureParams& base = {});

// The names of leaf_kinds(), in order.
std::vector<std::string> leaf_kind_names();

}  // namespace boreas::render
