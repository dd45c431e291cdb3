// boreas: the camera, shared by every vertex shader of the frame. In the shadow pass
// (BOREAS_SHADOW_PASS) u_view_proj is the sun's projection and the fragment shaders only
// keep depth (and the leaves' alpha test).
uniform mat4 u_view_proj;  // world -> clip

// Stochastic simplification (RenderSettings::thinning; Cook, Halstead, Planck and Ryu,
// "Stochastic simplification of aggregate detail"), shared by leaf.vert, branch.vert and
// meadow.vert: an element too small for the pass to resolve is kept with a probability,
// by a hash of its index so the same ones stay from frame to frame, and the kept ones are
// drawn larger by as much, so the expected coverage stays.
uniform vec3 u_eye;            // m: the camera
uniform float u_pixel_angle;   // radians per pixel of the camera, vertically
uniform float u_shadow_texel;  // m: a texel of the shadow map (or of an impostor's frame)
uniform int u_thinning;        // RenderSettings::thinning

// A uniform number in [0, 1) from an index (an integer hash: the same on every driver,
// unlike fract(sin(x))).
float index_hash(int i) {
  uint h = uint(i) * 747796405u + 2891336453u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  h = (h >> 22u) ^ h;
  return float(h >> 8u) * (1.0 / 16777216.0);
}

// Metres a pixel spans at p; in the shadow pass a shadow-map texel and in the impostors'
// baking a texel of the frame, the same everywhere (both views are orthographic).
float pixel_footprint(vec3 p) { return max(distance(p, u_eye), 1e-3) * u_pixel_angle; }

float footprint_at(vec3 p) {
#if defined(BOREAS_SHADOW_PASS) || defined(BOREAS_BAKE_PASS)
  return u_shadow_texel;
#else
  return pixel_footprint(p);
#endif
}

// The probability of keeping an element that is `resolved` times what the pass resolves
// (1 and more: kept), at least min_keep; 1 with thinning off.
float keep_probability(float resolved, float min_keep) {
  return u_thinning == 0 ? 1.0 : clamp(resolved, min_keep, 1.0);
}
