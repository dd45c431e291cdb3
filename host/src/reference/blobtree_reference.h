// boreas: the double-precision reference of a BlobTree tree's field (Galbraith, MacMurchy
// and Wyvill 2004 sec. 3.1-3.6), written from the definitions, apart from the float code
// in cl/shared/blobtree_field.h, so that tests comparing the two catch a slip in either.
#pragma once

#include <glm/glm.hpp>

#include "blobtree/blobtree_model.h"

namespace boreas::impl::reference {

// The iso-value: the surface is F = 1/2.
constexpr double kBlobIso = 0.5;

// A point in a primitive's unbent frame: t along the skeleton from the base (m, < 0
// before it, > length after it), c0 across it towards u_direction (for a bent primitive:
// outwards from the arc's centre) and c1 towards axis x c0's direction.
struct BlobLocal {
  double t = 0.0;
  double c0 = 0.0;
  double c1 = 0.0;
};

// Undoes Barr's bend: within the arc's angle, t is the arc length to the point's angle
// around the arc's centre and c0 its distance from the centre less the radius; beyond
// either end the frame of that end continues rigidly. The ends' regions meet on the
// bisector behind the centre (the fold of the bend, see the .cpp).
BlobLocal blob_local(const BlobPrimitive& prim, const glm::dvec3& p);

// The skeleton's point at arc length s in [0, length] (on the axis, the cone's spine).
glm::dvec3 blob_skeleton_point(const BlobPrimitive& prim, double s);

// The distance from base to the skeleton's end: 2 (L / angle) sin(angle / 2) when bent.
double blob_chord_length(const BlobPrimitive& prim);

// Distance from (t, r), r >= 0 the distance from the axis, to the solid skeleton cone of
// the given length and base radius (0 inside it).
double blob_cone_distance(double t, double r, double length, double cone_radius);

// Wyvill's fall-off (1 - d^2/R^2)^3 for d < R, else 0.
double blob_falloff(double d, double influence);

// |dg/dd| on the primitive's own surface, d = iso_distance: PCM's k for this member.
double blob_surface_slope(const BlobPrimitive& prim);

// One primitive's fall-off g(d) (without its weight); `distance` gets d, the distance to
// the skeleton in the unbent frame.
double blob_primitive_field(const BlobPrimitive& prim, const glm::dvec3& p,
                            double* distance = nullptr);

// Gascuel's expansion h(r) on the propagation region of width w, peak M at w/2, slope k
// at 0; 0 for r >= w.
double blob_pcm_expansion(double r, double w, double peak, double slope);

// The union of the deformed members prims[begin, end) of one PCM group at p (>= 0).
double blob_pcm_group_field(const BlobModel& m, int begin, int end, const glm::dvec3& p);

// A cut's cutter field in [0, 1]: 1/2 on its faces, ramping over `ramp` across them.
double blob_cutter(const BlobCut& cut, const glm::dvec3& p);

// F at p: every group's field summed, then, if the model has cuts, min(F, 1 - max
// cutter). Naive: every primitive and every cut is evaluated.
double blob_field(const BlobModel& m, const glm::dvec3& p);

// grad F by central differences of step h (m).
glm::dvec3 blob_gradient(const BlobModel& m, const glm::dvec3& p, double h);

// Texture coordinates at p: each positive-weight primitive with g > 0 contributes its own
// (u, v), weighted by g. u = the angle atan2(c1, c0) / 2 pi in [0, 1); v = v0 + v_scale t.
// (0, 0) where no primitive reaches p.
glm::dvec2 blob_uv(const BlobModel& m, const glm::dvec3& p);

}  // namespace boreas::impl::reference
