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
// The outlines follow the field guides' descriptions; the colors are chosen to read as
// those descriptions (not measured spectra), by the reflectance and transmittance of a
// 0.2 mm lamina.
//
// Every kind keeps the broadleaf's layout on the texture (petiole start, blade base and tip,
// widest half-width), so that one quad mapping serves all: a leaf's aspect comes from its
// species' LeafScaleX, its outline from its kind.
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

// The leaf kind a tree of this species has when its scene does not choose one: the kind
// named after a built-in species (quaking_aspen -> aspen, ca_black_oak -> oak,
// weeping_willow -> willow, black_tupelo -> tupelo), matched on a species file's stem too
// (".../weeping_willow.xml"); broadleaf for any other.
std::string default_leaf_kind(const std::string& species);

}  // namespace boreas::render
