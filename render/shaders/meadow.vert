// boreas: underbrush components (Endo et al.) as the vertex kernel strips them
// (boreas_meadow_enqueue_vertices): BOREAS_MEADOW_VERTEX_STRIDE vertices per component,
// position, normal and uv. Drawn as indexed triangle strips, one per component with a
// primitive restart between them; the part of a strip past its count repeats the tip, so
// it makes only empty triangles. The component's colors come from a static buffer.
#include "frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

layout(std430, binding = 4) readonly buffer ComponentStyle { float component_style[]; };

const int kVerticesPerComponent = 18;  // BOREAS_MEADOW_VERTEX_STRIDE

out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
flat out vec3 v_albedo;
flat out vec3 v_transmittance;

void main() {
  int c = gl_VertexID / kVerticesPerComponent;
  v_albedo = vec3(component_style[6 * c], component_style[6 * c + 1], component_style[6 * c + 2]);
  v_transmittance = vec3(component_style[6 * c + 3], component_style[6 * c + 4], component_style[6 * c + 5]);
  v_position = a_position;
  v_normal = a_normal;
  v_uv = a_uv;
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
