// boreas: underbrush components (Endo et al.) as the vertex kernel strips them
// (boreas_meadow_enqueue_vertices): BOREAS_MEADOW_VERTEX_STRIDE vertices per component,
// position, normal and uv, left and right border vertices alternating (even: left, u 0).
// Drawn as indexed triangle strips, one per component with a primitive restart between
// them; the part of a strip past its count repeats the tip, so it makes only empty
// triangles. The component's colors come from a static buffer.
//
// Two things are done here that the kernel's strip does not:
// - Coverage at a distance. A blade narrower than a pixel aliases into dots and gaps.
//   A component w pixels wide (w < 1; its widest joint, measured once at rest) is kept
//   with probability w (a hash of its index, so the same ones stay from frame to frame)
//   and the kept ones are drawn 1/w times wider: the expected area covered is that of the true blades, and every
//   drawn blade is about a pixel wide. Below kMinKeep the widening stops (at 1/kMinKeep)
//   and coverage falls off with distance, as the LOD culls anyway.
// - A curved cross-section. A blade is not a flat card: its normal is tilted toward each
//   border by kCurl (about 30 degrees at the edge, interpolated across), so the sun lights
//   one flank more than the other, as on a rounded or keeled leaf.
// The shadow pass thins by the same rule with its own texel (the map is orthographic, so
// one width in metres for all): a 5 mm blade on a 6 cm texel is kept with probability 0.1
// and cast 10 times wider, so the expected shadow is the blades' while the rasterizer sees
// a tenth of them (Cook et al., "Stochastic simplification of aggregate detail", keep the
// expected area the same way). It has no normals to curl.
#include "frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

layout(std430, binding = 4) readonly buffer ComponentStyle { float component_style[]; };
layout(std430, binding = 5) readonly buffer MeadowVertices { float meadow_vertex[]; };

const int kVerticesPerComponent = 18;  // BOREAS_MEADOW_VERTEX_STRIDE
const int kStyleFloats = 8;  // albedo, transmittance, widest (m), unused
const float kMinKeep = 0.1;
const float kCurl = 0.6;

out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
flat out vec3 v_albedo;
flat out vec3 v_transmittance;

vec3 vertex_position(int i) {
  return vec3(meadow_vertex[8 * i], meadow_vertex[8 * i + 1], meadow_vertex[8 * i + 2]);
}

void main() {
  int c = gl_VertexID / kVerticesPerComponent;
  v_uv = a_uv;
#ifdef BOREAS_SHADOW_PASS
  v_normal = a_normal;
  v_albedo = vec3(0.0);
  v_transmittance = vec3(0.0);
  float keep = keep_probability(component_style[kStyleFloats * c + 6] / footprint_at(a_position), kMinKeep);
  if (index_hash(c) >= keep) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_position = a_position;
    return;
  }
  vec3 partner = vertex_position(gl_VertexID ^ 1);
  vec3 middle = 0.5 * (a_position + partner);
  v_position = middle + (a_position - middle) / keep;
  gl_Position = u_view_proj * vec4(v_position, 1.0);
#else
  int s = kStyleFloats * c;
  v_albedo = vec3(component_style[s], component_style[s + 1], component_style[s + 2]);
  v_transmittance = vec3(component_style[s + 3], component_style[s + 4], component_style[s + 5]);
  float width = component_style[s + 6];  // m
  float keep = keep_probability(width / footprint_at(vertex_position(c * kVerticesPerComponent)), kMinKeep);
  if (index_hash(c) >= keep) {
    // Thinned out: every vertex of the strip outside the clip volume, so nothing is drawn.
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_position = a_position;
    v_normal = a_normal;
    return;
  }
  vec3 partner = vertex_position(gl_VertexID ^ 1);
  vec3 middle = 0.5 * (a_position + partner);
  vec3 half_across = a_position - middle;
  vec3 position = middle + half_across / keep;
  float across_length = length(half_across);
  vec3 outward = across_length > 0.0 ? half_across / across_length : vec3(0.0);
  v_position = position;
  v_normal = normalize(a_normal + kCurl * outward);
  gl_Position = u_view_proj * vec4(position, 1.0);
#endif
}
