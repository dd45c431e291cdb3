// boreas render: the frame's passes (renderer.h).
#include "gl/renderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <string>
#include <tuple>

#include "gl/frustum_cull.h"

namespace boreas::render {

namespace {

constexpr int kMeadowVerticesPerComponent = 18;  // BOREAS_MEADOW_VERTEX_STRIDE
constexpr GLuint kRestartIndex = 0xFFFFFFFFu;
// The tone mapper's white point: exposed luminance that maps to white.
constexpr float kWhite = 4.0f;
// Bloom spreads what lies above half the white point: the highlights that already clip.
constexpr float kBloomThreshold = 0.5f * kWhite;
// Light shafts add this share of the mean sky radiance along the line to the sun: about
// what a light haze (turbidity 2 to 3) scatters toward the camera over the tens of metres
// a grove spans, chosen against frames rather than measured.
constexpr float kShaftStrength = 0.06f;

// Texture units.
enum Unit : int {
  kHdrUnit = 0,
  kBarkAlbedoUnit = 1,
  kBarkNormalUnit = 2,
  kLeafAlbedoUnit = 3,
  kLeafNormalUnit = 4,
  kLeafHl2Unit = 5,
  kLeafTranslucencyUnit = 6,
  kShadowUnit = 7,
  kDepthUnit = 8,
  kPostUnit = 9,
  kBloomUnit = 10,
  kShaftsUnit = 11,
};

void check_side(const char* what, int value, int low, int high) {
  if (value < low || value > high) {
    throw std::invalid_argument(std::string("renderer: ") + what + " must be in [" + std::to_string(low) + ", " +
                                std::to_string(high) + "] (got " + std::to_string(value) + ")");
  }
}

void check_settings(const RenderSettings& settings) {
  check_side("width", settings.width, 16, 8192);
  check_side("height", settings.height, 16, 8192);
  if (settings.shadow_map_size != 0)
    check_side("shadow_map_size", settings.shadow_map_size, 64, 8192);
  check_side("msaa_samples", settings.msaa_samples, 1, 16);
  if (!(settings.exposure > 0.0f && std::isfinite(settings.exposure))) {
    throw std::invalid_argument("renderer: exposure must be finite and > 0");
  }
  if (!(settings.bloom >= 0.0f && settings.bloom <= 1.0f)) {
    throw std::invalid_argument("renderer: bloom must be in [0, 1] (got " +
                                std::to_string(settings.bloom) + ")");
  }
  if (!(settings.light_shafts >= 0.0f && settings.light_shafts <= 100.0f)) {
    throw std::invalid_argument("renderer: light_shafts must be in [0, 100] (got " +
                                std::to_string(settings.light_shafts) + ")");
  }
}

GlObject make_target(GLenum format, int width, int height) {
  GlObject t = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), 1, format, width, height);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

void check_complete(const GlObject& fbo, const char* what) {
  GLenum status = glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char text[96];
    std::snprintf(text, sizeof text, "renderer: the %s framebuffer is incomplete (status 0x%x)", what, status);
    throw std::runtime_error(text);
  }
}

// Reverses the row order (OpenGL's first row is the bottom one; images start at the top).
template <typename T>
void flip_rows(std::vector<T>& values, size_t row, int rows) {
  for (int y = 0; y < rows / 2; ++y) {
    std::swap_ranges(values.begin() + ptrdiff_t(size_t(y) * row), values.begin() + ptrdiff_t(size_t(y + 1) * row),
                     values.begin() + ptrdiff_t(size_t(rows - 1 - y) * row));
  }
}

}  // namespace

struct Renderer::Programs {
  Program bark{{{GL_VERTEX_SHADER, "branch.vert"}, {GL_FRAGMENT_SHADER, "bark.frag"}}};
  Program bark_shadow{{{GL_VERTEX_SHADER, "branch.vert"}, {GL_FRAGMENT_SHADER, "bark.frag"}},
                      "#define BOREAS_SHADOW_PASS 1\n"};
  Program leaf{{{GL_VERTEX_SHADER, "leaf.vert"}, {GL_FRAGMENT_SHADER, "leaf.frag"}}};
  Program leaf_shadow{{{GL_VERTEX_SHADER, "leaf.vert"}, {GL_FRAGMENT_SHADER, "leaf.frag"}},
                      "#define BOREAS_SHADOW_PASS 1\n"};
  Program mesh_bark{{{GL_VERTEX_SHADER, "mesh_bark.vert"}, {GL_FRAGMENT_SHADER, "bark.frag"}}};
  Program mesh_bark_shadow{{{GL_VERTEX_SHADER, "mesh_bark.vert"}, {GL_FRAGMENT_SHADER, "bark.frag"}},
                           "#define BOREAS_SHADOW_PASS 1\n"};
  Program mesh_leaf{{{GL_VERTEX_SHADER, "mesh_leaf.vert"}, {GL_FRAGMENT_SHADER, "leaf.frag"}}};
  Program mesh_leaf_shadow{{{GL_VERTEX_SHADER, "mesh_leaf.vert"}, {GL_FRAGMENT_SHADER, "leaf.frag"}},
                           "#define BOREAS_SHADOW_PASS 1\n"};
  Program meadow{{{GL_VERTEX_SHADER, "meadow.vert"}, {GL_FRAGMENT_SHADER, "meadow.frag"}}};
  Program meadow_shadow{{{GL_VERTEX_SHADER, "meadow.vert"}, {GL_FRAGMENT_SHADER, "meadow.frag"}},
                        "#define BOREAS_SHADOW_PASS 1\n"};
  Program ball{{{GL_VERTEX_SHADER, "ball.vert"}, {GL_FRAGMENT_SHADER, "ball.frag"}}};
  Program ball_shadow{{{GL_VERTEX_SHADER, "ball.vert"}, {GL_FRAGMENT_SHADER, "ball.frag"}},
                      "#define BOREAS_SHADOW_PASS 1\n"};
  Program terrain{{{GL_VERTEX_SHADER, "terrain.vert"}, {GL_FRAGMENT_SHADER, "terrain.frag"}}};
  Program sky{{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "sky.frag"}}};
  Program tonemap{{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "tonemap.frag"}}};
  Program post_downsample{
      {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "post_downsample.frag"}}};
  Program post_blur{
      {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "post_blur.frag"}}};
  Program post_shafts{
      {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "post_shafts.frag"}}};
};

Renderer::Renderer(const RenderSettings& settings, const TextureSet& textures, const SkyParams& sky)
    : settings_(settings), textures_(textures), sky_(sky) {
  check_settings(settings);
  programs_ = std::make_unique<Programs>();
  set_sky(sky);
  make_scene_targets();
  make_post_targets();
  ldr_color_ = make_target(GL_RGBA8, settings.width, settings.height);
  ldr_fbo_ = make_framebuffer();
  glNamedFramebufferTexture(ldr_fbo_.id(), GL_COLOR_ATTACHMENT0, ldr_color_.id(), 0);
  check_complete(ldr_fbo_, "tone-mapped");
  if (settings.shadow_map_size > 0) make_shadow_map();
  make_vertex_arrays();
}

void Renderer::make_scene_targets() {
  hdr_color_ = make_target(GL_RGBA16F, settings_.width, settings_.height);
  depth_ = make_target(GL_DEPTH_COMPONENT32F, settings_.width, settings_.height);
  hdr_fbo_ = make_framebuffer();
  glNamedFramebufferTexture(hdr_fbo_.id(), GL_COLOR_ATTACHMENT0, hdr_color_.id(), 0);
  glNamedFramebufferTexture(hdr_fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  check_complete(hdr_fbo_, "HDR");
  {
    GLint most = 0;  // the driver's most samples per pixel
    glGetIntegerv(GL_MAX_SAMPLES, &most);
    settings_.msaa_samples = std::max(1, std::min(settings_.msaa_samples, int(most)));
  }
  if (settings_.msaa_samples > 1) {
    const int samples = settings_.msaa_samples;
    msaa_color_ = make_texture(GL_TEXTURE_2D_MULTISAMPLE);
    glTextureStorage2DMultisample(msaa_color_.id(), samples, GL_RGBA16F, settings_.width,
                                  settings_.height, GL_TRUE);
    msaa_depth_ = make_texture(GL_TEXTURE_2D_MULTISAMPLE);
    glTextureStorage2DMultisample(msaa_depth_.id(), samples, GL_DEPTH_COMPONENT32F, settings_.width,
                                  settings_.height, GL_TRUE);
    msaa_fbo_ = make_framebuffer();
    glNamedFramebufferTexture(msaa_fbo_.id(), GL_COLOR_ATTACHMENT0, msaa_color_.id(), 0);
    glNamedFramebufferTexture(msaa_fbo_.id(), GL_DEPTH_ATTACHMENT, msaa_depth_.id(), 0);
    check_complete(msaa_fbo_, "multisampled HDR");
  }
}

void Renderer::make_post_targets() {
  const int w = std::max(1, settings_.width / 4), h = std::max(1, settings_.height / 4);
  auto quarter = [&] {
    GlObject t = make_target(GL_RGBA16F, w, h);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return t;
  };
  post_bloom_ = quarter();
  post_sky_ = quarter();
  post_scratch_ = quarter();
  post_shafts_ = quarter();
  post_input_fbo_ = make_framebuffer();
  glNamedFramebufferTexture(post_input_fbo_.id(), GL_COLOR_ATTACHMENT0, post_bloom_.id(), 0);
  glNamedFramebufferTexture(post_input_fbo_.id(), GL_COLOR_ATTACHMENT1, post_sky_.id(), 0);
  const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(post_input_fbo_.id(), 2, both);
  check_complete(post_input_fbo_, "post-effect input");
  for (auto [fbo, target] :
       {std::pair{&post_bloom_fbo_, &post_bloom_}, std::pair{&post_scratch_fbo_, &post_scratch_},
        std::pair{&post_shafts_fbo_, &post_shafts_}}) {
    *fbo = make_framebuffer();
    glNamedFramebufferTexture(fbo->id(), GL_COLOR_ATTACHMENT0, target->id(), 0);
    check_complete(*fbo, "post effect");
  }
}

void Renderer::make_shadow_map() {
  shadow_depth_ = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(shadow_depth_.id(), 1, GL_DEPTH_COMPONENT32F, settings_.shadow_map_size,
                     settings_.shadow_map_size);
  // Hardware comparison with bilinear weights: each of the six taps is a 2x2 PCF.
  glTextureParameteri(shadow_depth_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(shadow_depth_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(shadow_depth_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(shadow_depth_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  // Outside the map nothing casts a shadow.
  glTextureParameteri(shadow_depth_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTextureParameteri(shadow_depth_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTextureParameterfv(shadow_depth_.id(), GL_TEXTURE_BORDER_COLOR, border);
  shadow_fbo_ = make_framebuffer();
  glNamedFramebufferTexture(shadow_fbo_.id(), GL_DEPTH_ATTACHMENT, shadow_depth_.id(), 0);
  glNamedFramebufferDrawBuffer(shadow_fbo_.id(), GL_NONE);
  glNamedFramebufferReadBuffer(shadow_fbo_.id(), GL_NONE);
  check_complete(shadow_fbo_, "shadow map");
}

void Renderer::make_vertex_arrays() {
  empty_vao_ = make_vertex_array();
  meadow_vao_ = make_vertex_array();
  const GLuint vao = meadow_vao_.id();
  const GLuint offsets[3] = {0, 12, 24};
  const GLint sizes[3] = {3, 3, 2};
  for (GLuint a = 0; a < 3; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
    glVertexArrayAttribBinding(vao, a, 0);
  }
}

Renderer::~Renderer() = default;

void Renderer::set_sky(const SkyParams& sky) {
  sky_ = SkyModel(sky);
  light_ = scene_light(sky_);
  // The sky is drawn in kcd/m^2 like everything else: the exposure comes in the tone mapper.
  sky_uniforms_ = sky_.uniforms(1.0);
}

float Renderer::exposure() const { return automatic_exposure(light_) * settings_.exposure; }

void Renderer::set_frame_uniforms(const Program& program, const glm::mat4& view_proj) const {
  const GLuint p = program.id();
  auto vec3 = [&](const char* name, const glm::vec3& v) { glProgramUniform3fv(p, program.uniform(name), 1, glm::value_ptr(v)); };
  auto integer = [&](const char* name, int v) { glProgramUniform1i(p, program.uniform(name), v); };
  auto real = [&](const char* name, float v) { glProgramUniform1f(p, program.uniform(name), v); };
  glProgramUniformMatrix4fv(p, program.uniform("u_view_proj"), 1, GL_FALSE, glm::value_ptr(view_proj));
  vec3("u_eye", camera_.eye);
  real("u_pixel_angle",
       2.0f * std::tan(glm::radians(camera_.fov_deg) * 0.5f) / float(settings_.height));
  real("u_shadow_texel", shadow_texel_m_);
  integer("u_thinning", settings_.thinning ? 1 : 0);
  vec3("u_sun_dir", light_.sun_dir);
  vec3("u_sun_irradiance", light_.sun_irradiance);
  vec3("u_sky_irradiance", light_.sky_irradiance);
  vec3("u_ground_irradiance", light_.ground_irradiance);
  glProgramUniformMatrix4fv(p, program.uniform("u_light_matrix"), 1, GL_FALSE, glm::value_ptr(light_matrix_));
  const bool shadows = settings_.shadow_map_size > 0;
  integer("u_shadow_map", kShadowUnit);
  integer("u_shadows", shadows ? 1 : 0);
  if (shadows) {
    real("u_shadow_radius", 1.5f / float(settings_.shadow_map_size));
    real("u_shadow_offset", 1.5f * shadow_texel_m_);
    real("u_shadow_bias", 1e-4f);
  }
  integer("u_translucency", settings_.translucency ? 1 : 0);
  integer("u_bark_albedo", kBarkAlbedoUnit);
  integer("u_bark_normal", kBarkNormalUnit);
  integer("u_leaf_albedo", kLeafAlbedoUnit);
  integer("u_leaf_normal", kLeafNormalUnit);
  integer("u_leaf_hl2", kLeafHl2Unit);
  integer("u_leaf_translucency", kLeafTranslucencyUnit);
  real("u_bark_tile", kBarkTileM);
  real("u_blade_base_v", BOREAS_LEAF_BLADE_BASE_V);
  real("u_blade_tip_v", BOREAS_LEAF_BLADE_TIP_V);
  real("u_blade_half_width", BOREAS_LEAF_BLADE_HALF_WIDTH);
  // sky.glsl's uniforms (terrain and sky).
  const SkyUniforms& s = sky_uniforms_;
  glProgramUniform3fv(p, program.uniform("u_sky_perez"), 5, glm::value_ptr(s.perez[0]));
  vec3("u_sky_zenith", s.zenith);
  vec3("u_sky_inv_f0", s.inv_f0);
  vec3("u_sky_sun_dir", s.sun_dir);
  real("u_sky_scale", s.scale);
  vec3("u_sky_disc_dir", s.disc_dir);
  vec3("u_sky_disc_radiance", s.disc_radiance);
  real("u_sky_disc_cos_radius", s.disc_cos_radius);
}

const Renderer::BranchGrid& Renderer::branch_grid(int rings, int sides) {
  auto key = std::make_pair(rings, sides);
  auto found = branch_grids_.find(key);
  if (found != branch_grids_.end()) return found->second;
  // Two counter-clockwise triangles per quad, seen from outside (boreas_tree_get_mesh).
  std::vector<GLuint> indices;
  const GLuint row = GLuint(sides + 1);
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < sides; ++s) {
      GLuint a = GLuint(r) * row + GLuint(s), b = a + 1, c = a + row + 1, d = a + row;
      indices.insert(indices.end(), {a, b, c, a, c, d});
    }
  }
  GlObject buffer = make_buffer();
  glNamedBufferStorage(buffer.id(), GLsizeiptr(indices.size() * sizeof(GLuint)), indices.data(), 0);
  return branch_grids_.emplace(key, BranchGrid{std::move(buffer), int(indices.size())}).first->second;
}

void Renderer::ensure_meadow_indices(int components) {
  if (components <= meadow_index_components_) return;
  std::vector<GLuint> indices;
  indices.reserve(size_t(components) * (kMeadowVerticesPerComponent + 1));
  for (int c = 0; c < components; ++c) {
    for (int k = 0; k < kMeadowVerticesPerComponent; ++k) indices.push_back(GLuint(c * kMeadowVerticesPerComponent + k));
    indices.push_back(kRestartIndex);
  }
  meadow_indices_ = make_buffer();
  glNamedBufferStorage(meadow_indices_.id(), GLsizeiptr(indices.size() * sizeof(GLuint)), indices.data(), 0);
  meadow_index_components_ = components;
}

// One pass of draw_geometry: its view-projection, and what it may skip.
struct Renderer::GeometryPass {
  glm::mat4 camera_vp;  // the camera's, in either pass
  glm::mat4 vp;         // the pass's: the camera's, or the sun's in the shadow pass
  bool shadow = false;
  glm::vec3 sun_dir{0.0f, 1.0f, 0.0f};
  float ground_y = 0.0f;

  // What is out of this pass's frustum is skipped; in the shadow pass also what cannot
  // shadow anything the camera sees (its box swept away from the sun to the ground lies
  // outside the camera's frustum).
  bool skip(const glm::vec3& lo, const glm::vec3& hi) const {
    if (box_outside_frustum(vp, lo, hi)) return true;
    return shadow && shadow_outside_frustum(camera_vp, lo, hi, sun_dir, ground_y);
  }
};

void Renderer::draw_geometry(const FrameGeometry& g, bool shadow_pass) {
  const glm::mat4 camera_vp =
      camera_.view_projection(float(settings_.width) / float(settings_.height));
  const GeometryPass pass{camera_vp, shadow_pass ? light_view_proj_ : camera_vp, shadow_pass,
                          light_.sun_dir, ground_.y};
  draw_branches(g, pass);
  draw_leaves(g, pass);
  draw_mesh_trunks(g, pass);
  draw_mesh_leaves(g, pass);
  draw_meadows(g, pass);
  draw_balls(g, pass);
  glBindVertexArray(0);
}

const Program& Renderer::use_program(const Program& lit, const Program& shadow,
                                     const GeometryPass& pass) const {
  const Program& program = pass.shadow ? shadow : lit;
  program.use();
  set_frame_uniforms(program, pass.vp);
  return program;
}

void Renderer::draw_branches(const FrameGeometry& g, const GeometryPass& pass) {
  if (g.branch_records == 0 || g.branch_draws.empty()) return;
  const Program& program = use_program(programs_->bark, programs_->bark_shadow, pass);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, g.branch_records);
  glBindVertexArray(empty_vao_.id());
  glEnable(GL_CULL_FACE);
  for (const BranchDraw& d : g.branch_draws) {
    if (d.count <= 0 || pass.skip(d.bounds_min, d.bounds_max)) continue;
    const BranchGrid& grid = branch_grid(d.rings, d.sides);
    glVertexArrayElementBuffer(empty_vao_.id(), grid.indices.id());
    glUniform1i(program.uniform("u_first_record"), d.first_record);
    glUniform1i(program.uniform("u_rings"), d.rings);
    glUniform1i(program.uniform("u_sides"), d.sides);
    glUniform3fv(program.uniform("u_crown_center"), 1, glm::value_ptr(d.crown_center));
    glUniform3fv(program.uniform("u_crown_radius"), 1, glm::value_ptr(d.crown_radius));
    glDrawElementsInstanced(GL_TRIANGLES, grid.index_count, GL_UNSIGNED_INT, nullptr, d.count);
  }
  glDisable(GL_CULL_FACE);
}

void Renderer::draw_leaves(const FrameGeometry& g, const GeometryPass& pass) {
  if (g.leaf_records == 0 || g.leaf_static == 0 || g.leaf_count <= 0) return;
  const Program& program = use_program(programs_->leaf, programs_->leaf_shadow, pass);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, g.leaf_records);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, g.leaf_static);
  glBindVertexArray(empty_vao_.id());
  const GLint first_leaf = program.uniform("u_first_leaf");
  if (g.leaf_draws.empty()) {
    glUniform1i(first_leaf, 0);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, g.leaf_count);
  }
  for (const LeafDraw& d : g.leaf_draws) {
    if (d.count <= 0 || pass.skip(d.bounds_min, d.bounds_max)) continue;
    // gl_InstanceID starts at 0 whatever the base instance (GLSL 4.50): the first leaf
    // goes in a uniform. Instanced strips, not one long triangle list: on llvmpipe the
    // list (six vertices a leaf, the index from gl_VertexID) draws 40 % slower.
    glUniform1i(first_leaf, d.first);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, d.count);
  }
}

void Renderer::draw_mesh_trunks(const FrameGeometry& g, const GeometryPass& pass) {
  if (g.mesh_trunk_positions == 0 || g.mesh_trunk_static == 0 || g.mesh_trunk_indices == 0) return;
  // The model's winding is its own: no culling.
  const Program& program = use_program(programs_->mesh_bark, programs_->mesh_bark_shadow, pass);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, g.mesh_trunk_positions);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, g.mesh_trunk_static);
  glVertexArrayElementBuffer(empty_vao_.id(), g.mesh_trunk_indices);
  glBindVertexArray(empty_vao_.id());
  for (const MeshTrunkDraw& d : g.mesh_trunk_draws) {
    if (d.index_count <= 0) continue;
    glUniform3fv(program.uniform("u_crown_center"), 1, glm::value_ptr(d.crown_center));
    glUniform3fv(program.uniform("u_crown_radius"), 1, glm::value_ptr(d.crown_radius));
    glDrawElements(GL_TRIANGLES, d.index_count, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(size_t(d.first_index) * sizeof(GLuint)));
  }
}

void Renderer::draw_mesh_leaves(const FrameGeometry& g, const GeometryPass& pass) {
  if (g.mesh_leaf_vertices == 0 || g.mesh_leaf_static == 0 || g.mesh_leaf_indices == 0 ||
      g.mesh_leaf_index_count <= 0)
    return;
  use_program(programs_->mesh_leaf, programs_->mesh_leaf_shadow, pass);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, g.mesh_leaf_vertices);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, g.mesh_leaf_static);
  glVertexArrayElementBuffer(empty_vao_.id(), g.mesh_leaf_indices);
  glBindVertexArray(empty_vao_.id());
  glDrawElements(GL_TRIANGLES, g.mesh_leaf_index_count, GL_UNSIGNED_INT, nullptr);
}

void Renderer::draw_meadows(const FrameGeometry& g, const GeometryPass& pass) {
  if (g.meadow_vertices == 0 || g.meadow_styles == 0 || g.meadow_components <= 0) return;
  use_program(programs_->meadow, programs_->meadow_shadow, pass);
  ensure_meadow_indices(g.meadow_components);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, g.meadow_styles);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, g.meadow_vertices);  // the strip's partners
  glVertexArrayVertexBuffer(meadow_vao_.id(), 0, g.meadow_vertices, 0, 8 * sizeof(float));
  glVertexArrayElementBuffer(meadow_vao_.id(), meadow_indices_.id());
  glBindVertexArray(meadow_vao_.id());
  glEnable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
  constexpr int kIndicesPerComponent = kMeadowVerticesPerComponent + 1;  // and the restart
  if (g.meadow_draws.empty()) {
    glDrawElements(GL_TRIANGLE_STRIP, g.meadow_components * kIndicesPerComponent, GL_UNSIGNED_INT,
                   nullptr);
  }
  for (const MeadowDraw& d : g.meadow_draws) {
    if (d.count <= 0 || pass.skip(d.bounds_min, d.bounds_max)) continue;
    glDrawElements(
        GL_TRIANGLE_STRIP, d.count * kIndicesPerComponent, GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(size_t(d.first) * kIndicesPerComponent * sizeof(GLuint)));
  }
  glDisable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
}

void Renderer::draw_balls(const FrameGeometry& g, const GeometryPass& pass) {
  if (g.balls.empty()) return;
  const Program& program = use_program(programs_->ball, programs_->ball_shadow, pass);
  const int count = int(std::min<size_t>(g.balls.size(), 64));
  constexpr int kSegments = 24;
  glUniform4fv(program.uniform("u_balls"), count, glm::value_ptr(g.balls[0]));
  glUniform1i(program.uniform("u_segments"), kSegments);
  glBindVertexArray(empty_vao_.id());
  glEnable(GL_CULL_FACE);
  glDrawArraysInstanced(GL_TRIANGLES, 0, 6 * kSegments * (kSegments / 2), count);
  glDisable(GL_CULL_FACE);
}

void Renderer::draw_shadow_map(const FrameGeometry& g) {
  // An orthographic view from the sun that holds the bounding sphere of what casts shadows.
  glm::vec3 center = 0.5f * (g.bounds_min + g.bounds_max);
  float radius = 0.5f * glm::length(g.bounds_max - g.bounds_min) + 1.0f;
  glm::vec3 toward_sun = light_.sun_dir.y > 0.01f ? light_.sun_dir : glm::vec3(0.0f, 1.0f, 0.0f);
  glm::vec3 up = std::abs(toward_sun.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  glm::mat4 view = glm::lookAt(center + toward_sun * (2.0f * radius), center, up);
  glm::mat4 projection = glm::ortho(-radius, radius, -radius, radius, 0.5f * radius, 3.5f * radius);
  light_view_proj_ = projection * view;
  glm::mat4 to_texture = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
  light_matrix_ = to_texture * light_view_proj_;
  shadow_texel_m_ = 2.0f * radius / float(settings_.shadow_map_size);

  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_.id());
  glViewport(0, 0, settings_.shadow_map_size, settings_.shadow_map_size);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  glBindTextureUnit(kShadowUnit, 0);
  draw_geometry(g, true);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::draw(const Camera& camera, const FrameGeometry& geometry, const Ground& ground) {
  camera_ = camera;
  ground_ = ground;
  if (settings_.shadow_map_size > 0) draw_shadow_map(geometry);

  const bool msaa = msaa_fbo_.id() != 0;
  begin_scene_pass(msaa ? msaa_fbo_.id() : hdr_fbo_.id());
  const glm::mat4 view_proj =
      camera.view_projection(float(settings_.width) / float(settings_.height));
  draw_ground(view_proj, ground);
  draw_geometry(geometry, false);
  draw_sky(view_proj);
  if (msaa) {
    // The resolve: each pixel the mean of its samples' radiance (and one sample's depth,
    // for the light shafts' sky mask).
    glBlitNamedFramebuffer(msaa_fbo_.id(), hdr_fbo_.id(), 0, 0, settings_.width, settings_.height,
                           0, 0, settings_.width, settings_.height,
                           GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  }
  const bool post = settings_.bloom > 0.0f || settings_.light_shafts > 0.0f;
  if (post) draw_post_effects(view_proj);
  draw_tone_mapping(post);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::begin_scene_pass(unsigned scene_fbo) {
  glBindFramebuffer(GL_FRAMEBUFFER, scene_fbo);
  glViewport(0, 0, settings_.width, settings_.height);
  const float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glClearNamedFramebufferfv(scene_fbo, GL_COLOR, 0, clear);
  glClearNamedFramebufferfi(scene_fbo, GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glBindTextureUnit(kBarkAlbedoUnit, textures_.bark_albedo.id());
  glBindTextureUnit(kBarkNormalUnit, textures_.bark_normal.id());
  glBindTextureUnit(kLeafAlbedoUnit, textures_.leaf_albedo.id());
  glBindTextureUnit(kLeafNormalUnit, textures_.leaf_normal.id());
  glBindTextureUnit(kLeafHl2Unit, textures_.leaf_hl2.id());
  glBindTextureUnit(kLeafTranslucencyUnit, textures_.leaf_translucency.id());
  glBindTextureUnit(kShadowUnit, shadow_depth_.id());
}

void Renderer::draw_ground(const glm::mat4& view_proj, const Ground& ground) {
  const Program& program = programs_->terrain;
  program.use();
  set_frame_uniforms(program, view_proj);
  glUniform4fv(program.uniform("u_ground_rect"), 1, glm::value_ptr(ground.rect));
  glUniform1f(program.uniform("u_ground_y"), ground.y);
  glUniform1f(program.uniform("u_haze_distance"), ground.haze_distance);
  const int rects = int(std::min<size_t>(ground.meadow_rects.size(), 16));
  glUniform1i(program.uniform("u_meadow_count"), rects);
  if (rects > 0)
    glUniform4fv(program.uniform("u_meadow_rects"), rects, glm::value_ptr(ground.meadow_rects[0]));
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

void Renderer::draw_sky(const glm::mat4& view_proj) {
  // The sky where nothing else was drawn: at the far plane, depth test LEQUAL.
  const Program& program = programs_->sky;
  program.use();
  set_frame_uniforms(program, view_proj);
  glm::mat4 inverse = glm::inverse(view_proj);
  glUniformMatrix4fv(program.uniform("u_inverse_view_proj"), 1, GL_FALSE, glm::value_ptr(inverse));
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

void Renderer::draw_tone_mapping(bool post) {
  glBindFramebuffer(GL_FRAMEBUFFER, ldr_fbo_.id());
  glDisable(GL_DEPTH_TEST);
  const Program& program = programs_->tonemap;
  program.use();
  glBindTextureUnit(kHdrUnit, hdr_color_.id());
  glUniform1i(program.uniform("u_hdr"), kHdrUnit);
  glUniform1f(program.uniform("u_exposure"), exposure());
  glUniform1f(program.uniform("u_white"), kWhite);
  glUniform1i(program.uniform("u_post"), post ? 1 : 0);
  glBindTextureUnit(kBloomUnit, post_bloom_.id());
  glBindTextureUnit(kShaftsUnit, post_shafts_.id());
  glUniform1i(program.uniform("u_bloom"), kBloomUnit);
  glUniform1i(program.uniform("u_shafts"), kShaftsUnit);
  glUniform1f(program.uniform("u_bloom_strength"), settings_.bloom);
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void Renderer::draw_post_effects(const glm::mat4& view_proj) {
  const int w = std::max(1, settings_.width / 4), h = std::max(1, settings_.height / 4);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(empty_vao_.id());
  glViewport(0, 0, w, h);
  const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  {
    const Program& program = programs_->post_downsample;
    program.use();
    glBindFramebuffer(GL_FRAMEBUFFER, post_input_fbo_.id());
    glBindTextureUnit(kHdrUnit, hdr_color_.id());
    glBindTextureUnit(kDepthUnit, depth_.id());
    glUniform1i(program.uniform("u_hdr"), kHdrUnit);
    glUniform1i(program.uniform("u_depth"), kDepthUnit);
    glm::mat4 inverse = glm::inverse(view_proj);
    glUniformMatrix4fv(program.uniform("u_inverse_view_proj"), 1, GL_FALSE,
                       glm::value_ptr(inverse));
    glUniform3fv(program.uniform("u_sun_dir"), 1, glm::value_ptr(light_.sun_dir));
    glUniform1f(program.uniform("u_exposure"), exposure());
    glUniform1f(program.uniform("u_threshold"), kBloomThreshold);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  if (settings_.bloom > 0.0f) {
    // Across into the scratch target, then along back into the bloom target.
    const Program& program = programs_->post_blur;
    program.use();
    glUniform1i(program.uniform("u_source"), kPostUnit);
    for (auto [from, to, step] : {std::tuple{&post_bloom_, &post_scratch_fbo_, glm::ivec2(1, 0)},
                                  std::tuple{&post_scratch_, &post_bloom_fbo_, glm::ivec2(0, 1)}}) {
      glBindFramebuffer(GL_FRAMEBUFFER, to->id());
      glBindTextureUnit(kPostUnit, from->id());
      glUniform2i(program.uniform("u_step"), step.x, step.y);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
  }
  // The sun's place on the screen; behind the camera there are no shafts to see.
  glm::vec4 sun = view_proj * glm::vec4(camera_.eye + light_.sun_dir * 1.0e4f, 1.0f);
  glClearNamedFramebufferfv(post_shafts_fbo_.id(), GL_COLOR, 0, black);
  if (settings_.light_shafts > 0.0f && sun.w > 0.0f) {
    const Program& program = programs_->post_shafts;
    program.use();
    glBindFramebuffer(GL_FRAMEBUFFER, post_shafts_fbo_.id());
    glBindTextureUnit(kPostUnit, post_sky_.id());
    glUniform1i(program.uniform("u_sky"), kPostUnit);
    glUniform2f(program.uniform("u_sun_uv"), 0.5f + 0.5f * sun.x / sun.w,
                0.5f + 0.5f * sun.y / sun.w);
    glUniform1f(program.uniform("u_strength"), kShaftStrength * settings_.light_shafts);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glViewport(0, 0, settings_.width, settings_.height);
}

std::vector<uint8_t> Renderer::read_rgb8() const {
  const size_t row = size_t(settings_.width) * 3;
  std::vector<uint8_t> pixels(row * size_t(settings_.height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(ldr_color_.id(), 0, GL_RGB, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
  flip_rows(pixels, row, settings_.height);
  return pixels;
}

std::vector<float> Renderer::read_hdr_rgb() const {
  std::vector<float> pixels(size_t(settings_.width) * size_t(settings_.height) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(hdr_color_.id(), 0, GL_RGB, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
  flip_rows(pixels, size_t(settings_.width) * 3, settings_.height);
  const float k = exposure();
  for (float& v : pixels) v *= k;
  return pixels;
}

void Renderer::present(int window_width, int window_height) const {
  glBlitNamedFramebuffer(ldr_fbo_.id(), 0, 0, 0, settings_.width, settings_.height, 0, 0, window_width, window_height,
                         GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

}  // namespace boreas::render
