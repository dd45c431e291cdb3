// boreas render: the frame's passes (renderer.h).
#include "gl/renderer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <string>
#include <tuple>

#include "gl/frustum_cull.h"
#include "gl/impostor_math.h"
#include "gl/tree_table.h"
#include "gl/tree_view.h"

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
  kImpostorAlbedoUnit = 12,
  kImpostorNormalUnit = 13,
  kImpostorLeafUnit = 14,
};

const std::string kImpostorDefines = "#define BOREAS_IMPOSTOR_FRAMES " + std::to_string(kImpostorFrames) +
                                     "\n#define BOREAS_IMPOSTOR_FRAME_TEXELS " +
                                     std::to_string(kImpostorFrameTexels) + "\n";

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
  if (!(settings.impostor_distance >= 0.0f && std::isfinite(settings.impostor_distance))) {
    throw std::invalid_argument("renderer: impostor_distance must be finite and >= 0 (got " +
                                std::to_string(settings.impostor_distance) + ")");
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
  Program bark_bake{{{GL_VERTEX_SHADER, "branch.vert"}, {GL_FRAGMENT_SHADER, "bark.frag"}},
                    "#define BOREAS_BAKE_PASS 1\n"};
  Program leaf_bake{{{GL_VERTEX_SHADER, "leaf.vert"}, {GL_FRAGMENT_SHADER, "leaf.frag"}},
                    "#define BOREAS_BAKE_PASS 1\n"};
  Program tree_ranges{{{GL_COMPUTE_SHADER, "tree_ranges.comp"}}};
  Program impostor_thinning{{{GL_COMPUTE_SHADER, "impostor_thinning.comp"}}, "#define BOREAS_BAKE_PASS 1\n"};
  Program impostor{{{GL_VERTEX_SHADER, "impostor.vert"}, {GL_FRAGMENT_SHADER, "impostor.frag"}},
                   kImpostorDefines};
  Program impostor_shadow{{{GL_VERTEX_SHADER, "impostor.vert"}, {GL_FRAGMENT_SHADER, "impostor.frag"}},
                          kImpostorDefines + "#define BOREAS_SHADOW_PASS 1\n"};
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
  tree_table_ = std::make_unique<TreeTable>();
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
  real("u_impostor_distance", settings_.impostor_distance);
  real("u_impostor_handover", kImpostorHandover);
  integer("u_impostors_baked", baked_templates_ > 0 ? 1 : 0);
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

template <typename Body>
void Renderer::timed_part(const GeometryPass& pass, const char* name, Body&& body) {
  if (!settings_.time_parts) {
    body();
    return;
  }
  if (!part_query_) {
    GLuint q = 0;
    glCreateQueries(GL_TIME_ELAPSED, 1, &q);
    part_query_ = GlObject(q, [](unsigned id) { glDeleteQueries(1, &id); });
  }
  auto cpu_now = [] {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
  };
  glFinish();  // what came before is not this part's CPU time
  const double cpu_start = cpu_now();
  glBeginQuery(GL_TIME_ELAPSED, part_query_.id());
  body();
  glEndQuery(GL_TIME_ELAPSED);
  GLuint64 ns = 0;
  glGetQueryObjectui64v(part_query_.id(), GL_QUERY_RESULT, &ns);
  const std::string part = std::string(pass.shadow ? "shadow " : "scene ") + name;
  part_seconds_[part] += double(ns) * 1e-9;
  part_seconds_["cpu " + part] += cpu_now() - cpu_start;
}

void Renderer::draw_geometry(const FrameGeometry& g, bool shadow_pass) {
  const glm::mat4 camera_vp =
      camera_.view_projection(float(settings_.width) / float(settings_.height));
  const GeometryPass pass{camera_vp, shadow_pass ? light_view_proj_ : camera_vp, shadow_pass,
                          light_.sun_dir, ground_.y};
  timed_part(pass, "branches", [&] { draw_branches(g, pass); });
  timed_part(pass, "leaves", [&] { draw_leaves(g, pass); });
  timed_part(pass, "impostors", [&] { draw_impostors(g, pass); });
  timed_part(pass, "imported trees", [&] {
    draw_mesh_trunks(g, pass);
    draw_mesh_leaves(g, pass);
  });
  timed_part(pass, "underbrush", [&] { draw_meadows(g, pass); });
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

boreas_tree_view_def Renderer::tree_view(const Camera& camera, const FrameGeometry& g) const {
  TreeViewInputs in;
  in.aspect = float(settings_.width) / float(settings_.height);
  in.image_height = settings_.height;
  in.thinning = settings_.thinning;
  // Past the handover's end a tree is its impostor alone: the call writes its record there
  // and nothing else; within the handover it writes the tree in full (tree_ranges.comp
  // adds its impostor).
  if (baked_templates_ > 0) in.impostor_distance = settings_.impostor_distance * (1.0f + kImpostorHandover);
  if (settings_.shadow_map_size > 0) {
    in.toward_sun = light_.sun_dir;
    in.shadow_height = std::max(g.bounds_max.y - g.bounds_min.y, 0.0f);  // the lowest point as the ground
  }
  return camera_tree_view(camera, in);
}

void Renderer::write_tree_commands(const FrameGeometry& g) {
  const TreeTable& t = *tree_table_;
  const int n = g.tree_ranges != 0 ? std::min(g.tree_range_capacity, t.trees()) : t.trees();
  t.reset_commands();
  if (n == 0) return;
  const Program& program = programs_->tree_ranges;
  program.use();
  const glm::mat4 camera_vp = camera_.view_projection(float(settings_.width) / float(settings_.height));
  set_frame_uniforms(program, camera_vp);
  glUniformMatrix4fv(program.uniform("u_camera_view_proj"), 1, GL_FALSE, glm::value_ptr(camera_vp));
  glUniform1i(program.uniform("u_from_ranges"), g.tree_ranges != 0 ? 1 : 0);
  glUniform1i(program.uniform("u_range_capacity"), g.tree_range_capacity);
  glUniform1i(program.uniform("u_ids"), t.ids());
  glUniform1i(program.uniform("u_branch_draws"), t.branch_draws());
  glUniform1i(program.uniform("u_leaf_draws"), t.leaf_draws());
  glUniform1i(program.uniform("u_trees"), t.trees());
  glUniform1f(program.uniform("u_ground_y"), ground_.y);
  glUniform1f(program.uniform("u_shadow_texel"), shadow_texel(g));  // the map's, drawn next
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, g.branch_records);
  t.bind();
  if (g.tree_ranges != 0) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 21, g.tree_ranges);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 22, g.tree_indirect);
  }
  glDispatchCompute(GLuint((n + 63) / 64), 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

Renderer::TreeDrawCounts Renderer::tree_draw_counts(bool shadow_pass) const {
  const TreeTable& t = *tree_table_;
  TreeDrawCounts out;
  auto sum = [&](unsigned buffer, int commands, int words) {
    std::vector<GLuint> c(size_t(std::max(commands, 0)) * size_t(words));
    if (c.empty()) return 0ll;
    glGetNamedBufferSubData(buffer, GLintptr((shadow_pass ? c.size() : 0) * sizeof(GLuint)),
                            GLsizeiptr(c.size() * sizeof(GLuint)), c.data());
    long long n = 0;
    for (size_t i = 1; i < c.size(); i += size_t(words)) n += c[i];
    return n;
  };
  out.branches = sum(t.branch_commands(), t.branch_draws(), 5);
  out.leaves = sum(t.leaf_commands(), t.leaf_draws(), 4);
  GLuint handover[8] = {};
  glGetNamedBufferSubData(t.handover_commands(), 0, sizeof handover, handover);
  out.handover_impostors = handover[shadow_pass ? 5 : 1];
  return out;
}

void Renderer::draw_branches(const FrameGeometry& g, const GeometryPass& pass) {
  const TreeTable& t = *tree_table_;
  if (g.branch_records == 0 || t.branch_draws() == 0) return;
  use_program(programs_->bark, programs_->bark_shadow, pass);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, g.branch_records);
  glBindVertexArray(t.vertex_array());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, t.branch_commands());
  const size_t first = pass.shadow ? size_t(t.branch_draws()) * 5 * sizeof(GLuint) : 0;
  glEnable(GL_CULL_FACE);
  glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, reinterpret_cast<const void*>(first), t.branch_draws(), 0);
  glDisable(GL_CULL_FACE);
}

void Renderer::draw_leaves(const FrameGeometry& g, const GeometryPass& pass) {
  const TreeTable& t = *tree_table_;
  if (g.leaf_records == 0 || g.leaf_static == 0 || t.leaf_draws() == 0) return;
  use_program(programs_->leaf, programs_->leaf_shadow, pass);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, g.leaf_records);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, g.leaf_static);
  glBindVertexArray(t.vertex_array());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, t.leaf_commands());
  const size_t first = pass.shadow ? size_t(t.leaf_draws()) * 4 * sizeof(GLuint) : 0;
  // Instanced strips, not one long triangle list: on llvmpipe the list (six vertices a
  // leaf, the index from gl_VertexID) draws 40 % slower.
  glMultiDrawArraysIndirect(GL_TRIANGLE_STRIP, reinterpret_cast<const void*>(first), t.leaf_draws(), 0);
}

void Renderer::draw_impostors(const FrameGeometry& g, const GeometryPass& pass) {
  const TreeTable& t = *tree_table_;
  if (baked_templates_ == 0 || settings_.impostor_distance <= 0.0f || t.trees() == 0) return;
  const Program& program = use_program(programs_->impostor, programs_->impostor_shadow, pass);
  glUniform3fv(program.uniform("u_toward_sun"), 1, glm::value_ptr(pass.sun_dir));
  glBindTextureUnit(kImpostorAlbedoUnit, impostor_albedo_.id());
  glBindTextureUnit(kImpostorNormalUnit, impostor_normal_.id());
  glUniform1i(program.uniform("u_impostor_albedo"), kImpostorAlbedoUnit);
  glUniform1i(program.uniform("u_impostor_normal"), kImpostorNormalUnit);
  glBindTextureUnit(kImpostorLeafUnit, impostor_leaf_.id());
  glUniform1i(program.uniform("u_impostor_leaf"), kImpostorLeafUnit);
  glUniform1i(program.uniform("u_world_template_count"), t.world_templates());
  const bool coverage = !pass.shadow && msaa_fbo_.id() != 0;
  glUniform1i(program.uniform("u_alpha_to_coverage"), coverage ? 1 : 0);
  if (coverage) glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  t.bind();
  glBindVertexArray(empty_vao_.id());
  // The call's impostors, as many as it wrote (its indirect buffer's third command).
  if (g.tree_impostors != 0 && g.tree_indirect != 0) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 15, g.tree_impostors);
    glUniform1i(program.uniform("u_first_record"), 0);
    glUniform1i(program.uniform("u_world_templates"), 1);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, g.tree_indirect);
    glDrawArraysIndirect(GL_TRIANGLE_STRIP, reinterpret_cast<const void*>(size_t(BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND) * sizeof(GLuint)));
  }
  // The trees handing over, the pass's list.
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 15, t.handover_records());
  glUniform1i(program.uniform("u_first_record"), pass.shadow ? t.trees() : 0);
  glUniform1i(program.uniform("u_world_templates"), 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, t.handover_commands());
  glDrawArraysIndirect(GL_TRIANGLE_STRIP, reinterpret_cast<const void*>(size_t(pass.shadow ? 4 : 0) * sizeof(GLuint)));
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
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

// The bark's and leaves' textures, on their units (the scene pass and the impostor bake).
void Renderer::bind_vegetation_textures() const {
  glBindTextureUnit(kBarkAlbedoUnit, textures_.bark_albedo.id());
  glBindTextureUnit(kBarkNormalUnit, textures_.bark_normal.id());
  glBindTextureUnit(kLeafAlbedoUnit, textures_.leaf_albedo.id());
  glBindTextureUnit(kLeafNormalUnit, textures_.leaf_normal.id());
  glBindTextureUnit(kLeafHl2Unit, textures_.leaf_hl2.id());
  glBindTextureUnit(kLeafTranslucencyUnit, textures_.leaf_translucency.id());
}

void Renderer::make_impostor_atlas(const FrameGeometry& g, int templates) {
  int levels = 1;  // down to a texel a frame, so no mip level mixes two frames
  while ((kImpostorFrameTexels >> (levels - 1)) > 1) ++levels;
  for (auto [atlas, format] : {std::pair{&impostor_albedo_, GL_RGBA8}, std::pair{&impostor_normal_, GL_RGBA8},
                               std::pair{&impostor_leaf_, GL_R8}}) {
    *atlas = make_texture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(atlas->id(), levels, format, kImpostorAtlasTexels, kImpostorAtlasTexels, templates);
    glTextureParameteri(atlas->id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(atlas->id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(atlas->id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(atlas->id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  impostor_depth_ = make_target(GL_DEPTH_COMPONENT32F, kImpostorAtlasTexels, kImpostorAtlasTexels);
  // The thinning's lists, as long as the largest tree baked.
  size_t branches = 1, leaves = 1;
  for (int t = 0; t < tree_table_->trees() && t < int(g.trees.size()); ++t) {
    const TreeTable::TreeDraws& d = tree_table_->draws_of(t);
    size_t n = 0;
    for (int e : d.branch_entries) n += size_t(tree_table_->instances(e));
    branches = std::max(branches, n);
    if (d.leaf_entry >= 0) leaves = std::max(leaves, size_t(tree_table_->instances(d.leaf_entry)));
  }
  for (auto [list, n] : {std::pair{&bake_branches_, branches}, std::pair{&bake_leaves_, leaves}}) {
    *list = make_buffer();
    glNamedBufferStorage(list->id(), GLsizeiptr(n * sizeof(GLint)), nullptr, 0);
  }
  bake_commands_ = make_buffer();
  glNamedBufferStorage(bake_commands_.id(), 5 * 5 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
  impostor_fbo_ = make_framebuffer();
  glNamedFramebufferTexture(impostor_fbo_.id(), GL_DEPTH_ATTACHMENT, impostor_depth_.id(), 0);
  const GLenum all[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glNamedFramebufferDrawBuffers(impostor_fbo_.id(), 3, all);
}

std::vector<int> Renderer::templates_seen_far(const FrameGeometry& g, const std::vector<glm::vec3>& eyes) const {
  std::vector<char> far(g.impostor_templates.size(), eyes.empty() ? 1 : 0);
  // A tree begins to change at the impostor distance; a little nearer is already worth it.
  const float reach = 0.9f * settings_.impostor_distance;
  for (const TreeInstance& t : g.trees) {
    if (t.impostor_template < 0 || far[size_t(t.impostor_template)]) continue;
    for (const glm::vec3& eye : eyes)
      if (glm::distance(eye, t.position) >= reach) far[size_t(t.impostor_template)] = 1;
  }
  std::vector<int> out;
  for (size_t i = 0; i < far.size(); ++i)
    if (far[i] && settings_.impostor_distance > 0.0f) out.push_back(int(i));
  return out;
}

void Renderer::bake_impostors(const FrameGeometry& g, const std::vector<glm::vec3>& eyes) {
  tree_table_->sync(g);
  baked_templates_ = 0;
  const int n = int(g.impostor_templates.size());
  const std::vector<int> wanted = templates_seen_far(g, eyes);
  if (wanted.empty() || g.branch_records == 0) return;
  make_impostor_atlas(g, n);
  glBindFramebuffer(GL_FRAMEBUFFER, impostor_fbo_.id());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  bind_vegetation_textures();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, g.branch_records);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, g.leaf_records);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, g.leaf_static);
  tree_table_->bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 17, bake_commands_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 18, bake_branches_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 19, bake_leaves_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, bake_commands_.id());
  glBindVertexArray(tree_table_->vertex_array());
  for (int t : wanted) bake_template(g, t);
  tree_table_->mark_baked(wanted);
  glGenerateTextureMipmap(impostor_albedo_.id());
  glGenerateTextureMipmap(impostor_normal_.id());
  glGenerateTextureMipmap(impostor_leaf_.id());
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  baked_templates_ = int(wanted.size());
}

void Renderer::bake_template(const FrameGeometry& g, int index) {
  const ImpostorTemplate& m = g.impostor_templates[size_t(index)];
  const TreeInstance& tree = g.trees[size_t(m.tree)];
  const TreeTable::TreeDraws& draws = tree_table_->draws_of(m.tree);
  glNamedFramebufferTextureLayer(impostor_fbo_.id(), GL_COLOR_ATTACHMENT0, impostor_albedo_.id(), 0, index);
  glNamedFramebufferTextureLayer(impostor_fbo_.id(), GL_COLOR_ATTACHMENT1, impostor_normal_.id(), 0, index);
  glNamedFramebufferTextureLayer(impostor_fbo_.id(), GL_COLOR_ATTACHMENT2, impostor_leaf_.id(), 0, index);
  check_complete(impostor_fbo_, "impostor");
  const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  for (int attachment = 0; attachment < 3; ++attachment)
    glClearNamedFramebufferfv(impostor_fbo_.id(), GL_COLOR, attachment, clear);
  glClearNamedFramebufferfi(impostor_fbo_.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
  const glm::mat4 to_template = tree_placement_inverse(tree.position, tree.rotation, tree.scale);
  const glm::mat4 to_world = tree_placement(tree.position, tree.rotation, tree.scale);
  const glm::mat3 normal_to_template = glm::mat3(to_template) * tree.scale;  // the turn alone
  // Metres of the tree a texel of a frame spans: the thinning's footprint (frame.glsl).
  const float texel_m = 2.0f * m.radius * tree.scale / float(kImpostorFrameTexels);
  const int first_branch = thin_for_bake(m.tree, texel_m, m.rest_branch_shift);
  const int levels = int(draws.branch_entries.size());
  for (int i = 0; i < kImpostorFrames; ++i) {
    for (int j = 0; j < kImpostorFrames; ++j) {
      glViewport(i * kImpostorFrameTexels, j * kImpostorFrameTexels, kImpostorFrameTexels, kImpostorFrameTexels);
      const glm::vec3 d = impostor_frame_direction(i, j);
      const glm::mat4 vp = impostor_frame_view_projection(d, m.center, m.radius) * to_template;
      // Far along the frame's direction: every leaf sees it from the frame's side.
      const glm::vec3 eye = glm::vec3(to_world * glm::vec4(m.center + d * (1000.0f * m.radius), 1.0f));
      for (const Program* program : {&programs_->bark_bake, &programs_->leaf_bake}) {
        program->use();
        set_frame_uniforms(*program, vp);
        glUniform3fv(program->uniform("u_eye"), 1, glm::value_ptr(eye));
        glUniform1f(program->uniform("u_shadow_texel"), texel_m);
        glUniform1i(program->uniform("u_bake_first_branch"), first_branch);
        glUniform1i(program->uniform(program == &programs_->bark_bake ? "u_bake_branch_shift" : "u_bake_leaf_shift"),
                    program == &programs_->bark_bake ? m.rest_branch_shift : m.rest_leaf_shift);
        glUniformMatrix3fv(program->uniform("u_bake_to_template"), 1, GL_FALSE, glm::value_ptr(normal_to_template));
        if (program == &programs_->bark_bake) {
          glEnable(GL_CULL_FACE);
          glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr, levels, 5 * sizeof(GLuint));
          glDisable(GL_CULL_FACE);
        } else if (draws.leaf_entry >= 0) {
          glDrawArraysIndirect(GL_TRIANGLE_STRIP, reinterpret_cast<const void*>(4 * 5 * sizeof(GLuint)));
        }
      }
    }
  }
}

int Renderer::thin_for_bake(int tree, float texel_m, int branch_shift) {
  // The bake's commands with no instances yet: one per level of branches, then the leaves.
  const TreeTable::TreeDraws& draws = tree_table_->draws_of(tree);
  GLuint commands[5][5] = {};
  int first_branch = 0, branches = 0;
  glm::ivec4 entries(-1);
  for (size_t k = 0; k < draws.branch_entries.size() && k < 4; ++k) {
    const int e = draws.branch_entries[k];
    commands[k][0] = GLuint(tree_table_->index_count(e));
    commands[k][2] = GLuint(tree_table_->first_index(e));
    commands[k][4] = GLuint(e);
    entries[int(k)] = e;
    if (k == 0) first_branch = tree_table_->first_record(e);
    branches += tree_table_->instances(e);
  }
  commands[4][0] = 4;
  commands[4][3] = GLuint(std::max(draws.leaf_entry, 0));
  glNamedBufferSubData(bake_commands_.id(), 0, sizeof commands, commands);
  const Program& program = programs_->impostor_thinning;
  program.use();
  set_frame_uniforms(program, glm::mat4(1.0f));
  glUniform1f(program.uniform("u_shadow_texel"), texel_m);
  glUniform1i(program.uniform("u_bake_first_branch"), first_branch);
  glUniform1i(program.uniform("u_bake_branches"), branches);
  glUniform1i(program.uniform("u_bake_branch_shift"), branch_shift);
  glUniform1i(program.uniform("u_bake_leaf_entry"), draws.leaf_entry);
  glUniform4iv(program.uniform("u_bake_branch_entries"), 1, glm::value_ptr(entries));
  const int leaves = draws.leaf_entry >= 0 ? tree_table_->instances(draws.leaf_entry) : 0;
  glDispatchCompute(GLuint((std::max(branches, leaves) + 63) / 64), 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  return first_branch;
}

namespace {

// The radius of the shadow map's view: the bounding sphere of what casts shadows.
float shadow_radius(const FrameGeometry& g) { return 0.5f * glm::length(g.bounds_max - g.bounds_min) + 1.0f; }

}  // namespace

float Renderer::shadow_texel(const FrameGeometry& g) const {
  return settings_.shadow_map_size > 0 ? 2.0f * shadow_radius(g) / float(settings_.shadow_map_size) : 0.0f;
}

void Renderer::draw_shadow_map(const FrameGeometry& g) {
  // An orthographic view from the sun that holds the bounding sphere of what casts shadows.
  glm::vec3 center = 0.5f * (g.bounds_min + g.bounds_max);
  float radius = shadow_radius(g);
  glm::vec3 toward_sun = light_.sun_dir.y > 0.01f ? light_.sun_dir : glm::vec3(0.0f, 1.0f, 0.0f);
  glm::vec3 up = std::abs(toward_sun.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  glm::mat4 view = glm::lookAt(center + toward_sun * (2.0f * radius), center, up);
  glm::mat4 projection = glm::ortho(-radius, radius, -radius, radius, 0.5f * radius, 3.5f * radius);
  light_view_proj_ = projection * view;
  glm::mat4 to_texture = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
  light_matrix_ = to_texture * light_view_proj_;
  shadow_texel_m_ = shadow_texel(g);

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
  tree_table_->sync(geometry);
  {
    const glm::mat4 vp = camera.view_projection(float(settings_.width) / float(settings_.height));
    const GeometryPass scene{vp, vp, false, light_.sun_dir, ground.y};
    timed_part(scene, "tree commands", [&] { write_tree_commands(geometry); });
  }
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
  bind_vegetation_textures();
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
