// boreas render tests: the GLSL branch deformer (render/shaders/branch_deform.glsl) sweeps
// the same surface as the OpenCL deformer (cl/shared/tree_math.h, boreas_tree_get_mesh),
// from the branch records the interop buffer carries.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "gl/program.h"
#include "interop/gl_context.h"
#include "interop/shared_buffer.h"
#include "support/small_world.h"
#include "support/temp_dir.h"

namespace boreas::render {
namespace {

// *capped: how many of the tree's branch records carry a tip cap (boreas_cl.h's float 25);
// *beaded, if given: how many carry beads (bulge depth, float 20), and *phased how many of
// those a bulge phase (float 26: pieces ending short of their stem's tip).
void expect_glsl_matches_opencl(const char* species, int* capped, int* beaded = nullptr,
                                int* phased = nullptr) {
  interop::GlContext gl(interop::GlContextDef{64, 64, false, "boreas deformer test", false});
  boreas_world world = nullptr;
  ASSERT_EQ(test::create_small_windy_world(&world, 14.0f), BOREAS_OK) << boreas_last_error();
  boreas_tree_def td = boreas_default_tree_def();
  td.species = species;
  boreas_tree_id tree{};
  ASSERT_EQ(boreas_world_add_tree(world, &td, &tree), BOREAS_OK) << boreas_last_error();
  for (int s = 0; s < 20; ++s) ASSERT_EQ(boreas_world_step(world, 1.0f / 30.0f), BOREAS_OK);

  // The OpenCL deformer's vertices, level after level, each a (rings+1) x (sides+1) grid.
  int nv = 0, ni = 0;
  ASSERT_EQ(boreas_tree_get_mesh(world, tree, nullptr, 0, &nv, nullptr, 0, &ni), BOREAS_OK);
  std::vector<boreas_vertex> want(static_cast<size_t>(nv));
  std::vector<uint32_t> indices(static_cast<size_t>(ni));
  ASSERT_EQ(boreas_tree_get_mesh(world, tree, want.data(), nv, &nv, indices.data(), ni, &ni), BOREAS_OK);
  int nb = 0;
  ASSERT_EQ(boreas_tree_get_branches(world, tree, nullptr, 0, &nb), BOREAS_OK);
  std::vector<boreas_branch> branches(static_cast<size_t>(nb));
  ASSERT_EQ(boreas_tree_get_branches(world, tree, branches.data(), nb, &nb), BOREAS_OK);

  boreas_cl_objects cl{};
  ASSERT_EQ(boreas_world_get_cl(world, &cl), BOREAS_OK);
  interop::SharedBuffer records(interop::Strategy::copy, cl.context, cl.queue,
                                size_t(nb) * BOREAS_BRANCH_RECORD_FLOATS * sizeof(float));
  records.begin_write();
  ASSERT_EQ(boreas_tree_enqueue_branch_records(world, tree, records.cl(), 0), BOREAS_OK);
  records.end_write();
  std::vector<float> record_floats(size_t(nb) * BOREAS_BRANCH_RECORD_FLOATS);
  glGetNamedBufferSubData(records.gl(), 0, GLsizeiptr(record_floats.size() * sizeof(float)), record_floats.data());
  *capped = 0;
  for (int b = 0; b < nb; ++b) *capped += record_floats[size_t(b) * BOREAS_BRANCH_RECORD_FLOATS + 25] > 0.0f;
  if (beaded && phased) {
    *beaded = *phased = 0;
    for (int b = 0; b < nb; ++b) {
      const float* r = &record_floats[size_t(b) * BOREAS_BRANCH_RECORD_FLOATS];
      *beaded += r[20] > 0.0f;
      *phased += r[20] > 0.0f && r[26] > 0.0f;
    }
  }

  GLuint probe = 0;
  glCreateBuffers(1, &probe);
  glNamedBufferData(probe, GLsizeiptr(size_t(nv) * 6 * sizeof(float)), nullptr, GL_DYNAMIC_READ);
  Program program({{GL_VERTEX_SHADER, "deform_probe.vert"}});
  program.use();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, records.gl());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, probe);
  glEnable(GL_RASTERIZER_DISCARD);
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  glBindVertexArray(vao);
  int first_record = 0, out_first = 0;
  for (int level = 0; level < 4; ++level) {
    const int count = int(std::count_if(branches.begin(), branches.end(),
                                        [&](const boreas_branch& b) { return b.level == level; }));
    if (count == 0) continue;
    const int rings = td.levels[level].rings, sides = td.levels[level].sides;
    glUniform1i(program.uniform("u_first_record"), first_record);
    glUniform1i(program.uniform("u_rings"), rings);
    glUniform1i(program.uniform("u_sides"), sides);
    glUniform1i(program.uniform("u_out_first"), out_first);
    glDrawArrays(GL_POINTS, 0, count * (rings + 1) * (sides + 1));
    first_record += count;
    out_first += count * (rings + 1) * (sides + 1);
  }
  ASSERT_EQ(out_first, nv);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> got(size_t(nv) * 6);
  glGetNamedBufferSubData(probe, 0, GLsizeiptr(got.size() * sizeof(float)), got.data());
  glDisable(GL_RASTERIZER_DISCARD);
  glDeleteBuffers(1, &probe);
  glDeleteVertexArrays(1, &vao);

  // Positions within 20 um (float rounding of a ~10 m tree, and fast math against GLSL's
  // builtins); normals within 0.2 degrees (a GLSL pow(0, 0) once put 1.3 here).
  double worst_position = 0.0, worst_normal_deg = 0.0;
  for (size_t v = 0; v < size_t(nv); ++v) {
    double dp = 0.0, dot = 0.0;
    for (int a = 0; a < 3; ++a) {
      dp = std::max(dp, std::abs(double(got[v * 6 + a]) - want[v].position[a]));
      dot += double(got[v * 6 + 3 + a]) * want[v].normal[a];
    }
    worst_position = std::max(worst_position, dp);
    const double deg = std::acos(std::min(1.0, dot)) * 180.0 / M_PI;
    worst_normal_deg = std::max(worst_normal_deg, deg);
  }
  std::printf("GLSL vs OpenCL deformer, %s, %d vertices: position %.3g m, normal %.3g deg\n", species, nv,
              worst_position, worst_normal_deg);
  EXPECT_LT(worst_position, 2e-5);
  EXPECT_LT(worst_normal_deg, 0.2);
  EXPECT_TRUE(gl.take_messages().empty());
  boreas_world_destroy(world);
}

TEST(GlslDeformer, MatchesTheOpenClDeformerOnABentTree) {
  int capped = -1;
  expect_glsl_matches_opencl("quaking_aspen", &capped);
  EXPECT_EQ(capped, 0);  // 0Taper 1: no caps
}

// The tupelo's trunk (0Taper 1.1) and its split clones end in a tip cap (boreas_tip_cap),
// read from the record's float 25.
TEST(GlslDeformer, MatchesTheOpenClDeformerOnATreeWithCappedTips) {
  int capped = 0;
  expect_glsl_matches_opencl("black_tupelo", &capped);
  EXPECT_GT(capped, 0);
}

// nTaper 2..3: Arbaro's beads (boreas_beads), on a split trunk (its first piece's beads carry
// a phase, record float 26) and its branches, each closed by a tip cap.
TEST(GlslDeformer, MatchesTheOpenClDeformerOnABeadedTree) {
  test::TempDir dir;
  const std::string path = (dir.path() / "beaded.json").string();
  std::ofstream(path) << R"({"format": "boreas-species-1", "name": "beaded", "params": {
    "Levels": 2, "Scale": 6, "ScaleV": 0, "Ratio": 0.04, "Leaves": 0, "0Taper": 2.6,
    "0SegSplits": 1, "0SplitAngle": 25, "0CurveRes": 6, "1Taper": 2.3, "1Branches": 12}})";
  int capped = 0, beaded = 0, phased = 0;
  expect_glsl_matches_opencl(path.c_str(), &capped, &beaded, &phased);
  EXPECT_GT(capped, 0);
  EXPECT_GT(beaded, 10);
  EXPECT_GT(phased, 0);
}

}  // namespace
}  // namespace boreas::render
