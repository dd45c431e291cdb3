/* boreas: a leaf's outline on its quad, shared by the renderer's leaf textures and the rays
 * (issue 37: a ray through a notch of an oak leaf misses). Compiles as OpenCL C and as C/C++,
 * at width 1 only, in float; the renderer draws its textures from the same table with a
 * double twin (render/textures/leaf_shape.cpp).
 *
 * Texture coordinates: u across the leaf (midrib at u = 0.5), v along it from the stem end
 * of the quad (v = 0) to the tip (v = 1); the quad is square in texture units. Every kind
 * keeps one layout (petiole start, blade base and tip, widest half-width), so one quad
 * mapping serves all kinds. Along the blade t = (v - v_start(|x|)) / (tip_v - v_start(|x|))
 * runs from the base (0) to the tip (1), x = u - 0.5, and the blade is where |x| < h(t):
 *   h(t)          = half_width t^p (1 - t)^q / max over t of the same (widest at
 *                   t = p / (p + q)), times the lobes' sinuses and the serration's teeth;
 *   v_start(|x|)  = blade_base_v - notch_depth (1 - exp(-(|x| / notch_half_width)^2)), so
 *                   the basal lobes reach below the petiole's attachment point.
 * The petiole is a strip petiole_half_width either side of the midrib from petiole_start_v
 * (a rounded end) up into the blade.
 *
 * Math without libm builtins on CPUs (shared/notes: pocl-performance): powers as exp2 of
 * logs, the cosine as fast_math's sin_cycle, floor as a truncation (its argument is never
 * negative), and no early returns. */
#ifndef BOREAS_CL_SHARED_LEAF_OUTLINE_H
#define BOREAS_CL_SHARED_LEAF_OUTLINE_H

#include "shared/fast_math.h"

/* The outline kinds, the rows of boreas_leaf_outlines below (the public
 * boreas_leaf_outline enum is these plus one, with 0 for "by species"). */
#define BOREAS_LEAF_OUTLINE_BROADLEAF 0 /* generic ovate, serrate, notched base */
#define BOREAS_LEAF_OUTLINE_ASPEN 1     /* Populus tremuloides: round, fine teeth */
#define BOREAS_LEAF_OUTLINE_OAK 2       /* Quercus kelloggii: three deep lobes a side */
#define BOREAS_LEAF_OUTLINE_WILLOW 3    /* Salix babylonica: lanceolate, long tip */
#define BOREAS_LEAF_OUTLINE_TUPELO 4    /* Nyssa sylvatica: obovate, entire margin */
#define BOREAS_LEAF_OUTLINE_COUNT 5

/* The layout every kind shares, texture units. */
#define BOREAS_LEAF_PETIOLE_START_V 0.02f /* stem end of the petiole */
#define BOREAS_LEAF_BLADE_BASE_V 0.15f    /* petiole meets blade, on the midrib */
#define BOREAS_LEAF_BLADE_TIP_V 0.97f
#define BOREAS_LEAF_BLADE_HALF_WIDTH 0.30f /* the widest point's distance from the midrib */
#define BOREAS_LEAF_PETIOLE_HALF_WIDTH 0.008f

/* What makes a kind's outline (its veins and optics are the renderer's). */
typedef struct BoreasLeafOutline {
  float base_exponent;    /* p: below 1 rounds the base */
  float tip_exponent;     /* q: above 1 draws the tip out */
  float notch_depth;      /* how far the basal lobes reach below the blade base, texture units */
  float notch_half_width; /* texture units */
  float serration;        /* depth of the margin's teeth, fraction of the half-width */
  float teeth;            /* per side, along t */
  /* Lobes (an oak's): the sinuses between them sit at t = k / lobes (k = 1, 2, ...), each a
   * raised-cosine cut sinus_width of a lobe's period wide and lobe_depth of the half-width
   * deep at its bottom. lobes = 3.5 gives three lobes a side and a terminal one; 0 none. */
  float lobes;
  float lobe_depth;  /* 0..0.95 */
  float sinus_width; /* 0..1 */
} BoreasLeafOutline;

/* The table's storage, and the address space of a pointer into it. */
#ifdef __OPENCL_C_VERSION__
#define BOREAS_LEAF_TABLE __constant
#define BOREAS_LEAF_ROW __constant
#else
#define BOREAS_LEAF_TABLE static const
#define BOREAS_LEAF_ROW const
#endif

/* The kinds' outlines, written once: the rays read them here, the renderer's textures
 * through render/textures/leaf_kinds.cpp. The shapes follow the field guides' descriptions. */
BOREAS_LEAF_TABLE BoreasLeafOutline boreas_leaf_outlines[BOREAS_LEAF_OUTLINE_COUNT] = {
    /* p, q, notch_depth, notch_half_width, serration, teeth, lobes, lobe_depth, sinus_width */
    /* broadleaf: ovate, widest below the middle, a heart-shaped notch at the base */
    {0.55f, 1.25f, 0.035f, 0.05f, 0.025f, 26.0f, 0.0f, 0.0f, 0.6f},
    /* aspen: widest at 0.4 of the blade, a broad rounded base, a short tip, small teeth */
    {0.35f, 0.55f, 0.0f, 0.05f, 0.04f, 18.0f, 0.0f, 0.0f, 0.6f},
    /* oak: wide round sinuses leave pointed lobes with a few coarse bristle-tipped teeth */
    {0.8f, 0.8f, 0.0f, 0.05f, 0.12f, 14.0f, 3.5f, 0.55f, 0.85f},
    /* willow: a tapering base and a long, drawn-out tip, finely serrate */
    {1.0f, 1.8f, 0.0f, 0.05f, 0.03f, 40.0f, 0.0f, 0.0f, 0.6f},
    /* tupelo: widest past the middle (obovate), entire margin */
    {1.2f, 0.9f, 0.0f, 0.05f, 0.0f, 26.0f, 0.0f, 0.0f, 0.6f},
};

/* The math the outline calls: polynomials on the host, fast_math's per-device choice in
 * kernels. */
#ifdef __OPENCL_C_VERSION__
#define BOREAS_LEAF_EXP2(x) boreas_exp2(x)
#define BOREAS_LEAF_LOG2(x) boreas_log2(x)
#define BOREAS_LEAF_SIN_CYCLE(u) boreas_sin_cycle(u)
#else
#define BOREAS_LEAF_EXP2(x) boreas_poly_exp2(x)
#define BOREAS_LEAF_LOG2(x) boreas_poly_log2(x)
#define BOREAS_LEAF_SIN_CYCLE(u) boreas_poly_sin_cycle(u)
#endif

/* ---- The quad ------------------------------------------------------------------------ */

/* A leaf record has its blade's base b, unit axis a, unit normal n, and the leaf its length
 * L and width W (m); across = cross(a, n). The renderer's point for texture (u, v) is
 *   b + a (v - base_v) L / (tip_v - base_v) + across (u - 0.5) W / (2 half_width),
 * so a point at offsets (along, across) from b, m, has the texture coordinates below. */
BOREAS_FN void boreas_leaf_uv(float along, float across, float length, float width, float* u,
                              float* v) {
  *v = BOREAS_LEAF_BLADE_BASE_V +
       along * (BOREAS_LEAF_BLADE_TIP_V - BOREAS_LEAF_BLADE_BASE_V) / length;
  *u = 0.5f + across * (2.0f * BOREAS_LEAF_BLADE_HALF_WIDTH) / width;
}

/* The offsets from b (m, along a and across) of the renderer's point for (u, v); the quad's
 * corners are (u, v) in {0, 1} x {0, 1}. */
BOREAS_FN void boreas_leaf_offsets(float u, float v, float length, float width, float* along,
                                   float* across) {
  *along = (v - BOREAS_LEAF_BLADE_BASE_V) * length /
           (BOREAS_LEAF_BLADE_TIP_V - BOREAS_LEAF_BLADE_BASE_V);
  *across = (u - 0.5f) * width / (2.0f * BOREAS_LEAF_BLADE_HALF_WIDTH);
}

/* ---- The outline ---------------------------------------------------------------------- */

/* Hermite step from 0 at e0 to 1 at e1 (GLSL's smoothstep). */
BOREAS_FN float boreas_leaf_smoothstep(float e0, float e1, float x) {
  float t = BOREAS_CLAMP((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

/* v where the blade starts at distance ax from the midrib (the notch's basal lobes). */
BOREAS_FN float boreas_leaf_blade_start_v(BOREAS_LEAF_ROW BoreasLeafOutline* o, float ax) {
  float q = ax / o->notch_half_width;
  /* exp(-q^2) = 2^(-q^2 log2(e)) */
  float fall = BOREAS_LEAF_EXP2(-q * q * 1.44269504088896341f);
  return BOREAS_LEAF_BLADE_BASE_V - o->notch_depth * (1.0f - fall);
}

/* The blade's half-width at blade parameter t, teeth and sinuses included; 0 outside
 * 0 < t < 1. t^p (1 - t)^q over its peak is taken as one exp2 of logs. */
BOREAS_FN float boreas_leaf_half_width(BOREAS_LEAF_ROW BoreasLeafOutline* o, float t) {
  float p = o->base_exponent, q = o->tip_exponent;
  float tc = BOREAS_CLAMP(t, 1e-6f, 1.0f - 1e-6f);
  float t_max = p / (p + q);
  float log_peak = p * BOREAS_LEAF_LOG2(t_max) + q * BOREAS_LEAF_LOG2(1.0f - t_max);
  float log_w = p * BOREAS_LEAF_LOG2(tc) + q * BOREAS_LEAF_LOG2(1.0f - tc) - log_peak;
  float w = BOREAS_LEAF_BLADE_HALF_WIDTH * BOREAS_LEAF_EXP2(log_w);
  /* Distance (in lobe periods) to the nearest sinus; the cut follows a raised cosine across
   * the sinus, cos(pi d / h) = sin(2 pi (1/4 - d / (2 h))), h = half the sinus width. */
  float phase = tc * o->lobes;
  float d = BOREAS_FABS(phase - BOREAS_RINT(phase));
  float sinus_half = 0.5f * o->sinus_width;
  float c = BOREAS_LEAF_SIN_CYCLE(0.25f - 0.5f * d / (sinus_half + 1e-30f));
  float cut = o->lobe_depth * 0.5f * (1.0f + c);
  w *= d < sinus_half ? 1.0f - cut : 1.0f;
  /* Teeth point towards the tip: the margin rises slowly along t, then drops. */
  float tooth_phase = tc * o->teeth;
  float tooth = 1.0f - (tooth_phase - (float)(int)tooth_phase);
  float fade =
      boreas_leaf_smoothstep(0.08f, 0.25f, tc) * (1.0f - boreas_leaf_smoothstep(0.85f, 0.97f, tc));
  w *= 1.0f - o->serration * tooth * fade;
  return (t > 0.0f && t < 1.0f) ? w : 0.0f;
}

/* Whether (ax = |u - 0.5|, v) lies on the petiole: a strip with a rounded stem end. */
BOREAS_FN int boreas_leaf_in_petiole(float ax, float v) {
  const float r = BOREAS_LEAF_PETIOLE_HALF_WIDTH;
  float below = BOREAS_LEAF_PETIOLE_START_V + r - v;
  int in_strip = ax < r && v <= BOREAS_LEAF_BLADE_BASE_V + r;
  int in_end = below <= 0.0f || ax * ax + below * below < r * r;
  return in_strip && in_end;
}

/* Whether (u, v) lies on the blade or the petiole of kind outline
 * (0 <= outline < BOREAS_LEAF_OUTLINE_COUNT). A pure function of its arguments. */
BOREAS_FN int boreas_leaf_outline_inside(int outline, float u, float v) {
  BOREAS_LEAF_ROW BoreasLeafOutline* o = &boreas_leaf_outlines[outline];
  float ax = BOREAS_FABS(u - 0.5f);
  float start = boreas_leaf_blade_start_v(o, ax);
  float t = (v - start) / (BOREAS_LEAF_BLADE_TIP_V - start);
  return boreas_leaf_in_petiole(ax, v) || ax < boreas_leaf_half_width(o, t);
}

#endif
