// Library tests: bad input through every public function, as tables. Each row is one call
// a careless or hostile caller makes (a NULL pointer, a negative or huge count, NaN or
// infinity in a float field, an enum out of range, an id that is null, stale, of another
// world or of another kind). Each must return its documented status, name what was wrong
// in boreas_last_error(), and leave the world as it was: its state hash unchanged after
// the call, and, once every row has run, the same hashes step by step as a twin world
// that was never abused (which catches an object added or removed by a refused call).
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "host/mesh_trees/tube_trees.h"
#include "support/small_world.h"
#include "support/temp_dir.h"

namespace {

const float kBadFloats[] = {NAN, INFINITY, -INFINITY};
const int kBadInts[] = {-1, INT_MIN, INT_MAX};

std::string text(float v) { return std::isnan(v) ? "NaN" : v > 0 ? "+inf" : "-inf"; }

// A float field of a struct, by the name the library's messages use for it.
struct Field {
  std::string name;
  float* at;
};
struct IntField {
  std::string name;
  int* at;
};

#define F(path) \
  Field { #path, &d.path }
#define F3(path) F(path[0]), F(path[1]), F(path[2])
#define I(path) \
  IntField { #path, &d.path }

std::vector<Field> fields_of(boreas_grid_def& d) {
  return {F3(origin), F(cell_size), F(diffusion), F(decay_rate), F(response_time), F(edge_fade)};
}
std::vector<IntField> ints_of(boreas_grid_def& d) {
  return {I(resolution[0]), I(resolution[1]), I(resolution[2]), I(follow_focus)};
}
std::vector<Field> fields_of(boreas_wave& d) {
  return {F(direction[0]), F(direction[1]), F(amplitude), F(wavelength), F(speed), F(sharpness)};
}
std::vector<Field> fields_of(boreas_flow_primitive_def& d) {
  return {F3(position), F3(direction), F(strength), F(radius), F(lifetime)};
}
std::vector<Field> fields_of(boreas_gust_def& d) {
  return {F3(direction), F(strength), F(delay), F(rise), F(hold), F(fall), F3(center), F(radius)};
}
std::vector<Field> fields_of(boreas_tree_def& d) {
  std::vector<Field> f = {F3(position), F(rotation), F(scale), F(bend_exponent), F3(lod_distances)};
  for (int i = 0; i < 4; ++i) {
    const std::string level = "levels[" + std::to_string(i) + "].";
    f.push_back({level + "stiffness", &d.levels[i].stiffness});
    f.push_back({level + "damping_ratio", &d.levels[i].damping_ratio});
    f.push_back({level + "frequency_scale", &d.levels[i].frequency_scale});
  }
  return f;
}
std::vector<IntField> ints_of(boreas_tree_def& d) {
  std::vector<IntField> f;
  for (int i = 0; i < 4; ++i) {
    const std::string level = "levels[" + std::to_string(i) + "].";
    f.push_back({level + "rings", &d.levels[i].rings});
    f.push_back({level + "sides", &d.levels[i].sides});
  }
  return f;
}
std::vector<Field> fields_of(boreas_meadow_def& d) {
  return {F3(center), F(size[0]), F(size[1]), F(density), F(terrain_relief), F3(lod_distances)};
}
std::vector<IntField> ints_of(boreas_meadow_def& d) {
  return {I(species_count), I(seed_points), I(shape_angles), I(shape_norms)};
}
std::vector<Field> fields_of(boreas_collider_def& d) {
  return {F3(pose.position),        F(pose.orientation[0]), F(pose.orientation[1]),
          F(pose.orientation[2]),   F(pose.orientation[3]), F(radius),
          F3(velocity),             F3(angular_velocity)};
}
std::vector<Field> fields_of(boreas_lidar_def& d) {
  return {F(vertical_fov[0]), F(vertical_fov[1]), F(rotation_rate),    F(min_range),
          F(max_range),       F(range_noise),     F(dropout),          F(reflectivity[0]),
          F(reflectivity[1]), F(reflectivity[2]), F(reflectivity[3]),  F(reflectivity[4]),
          F3(pose.position),  F(pose.orientation[0]), F(pose.orientation[1]),
          F(pose.orientation[2]), F(pose.orientation[3])};
}
std::vector<Field> fields_of(boreas_depth_camera_def& d) {
  return {F(fx), F(fy), F(cx), F(cy), F(max_depth), F3(pose.position), F(pose.orientation[0]),
          F(pose.orientation[1]), F(pose.orientation[2]), F(pose.orientation[3])};
}
std::vector<Field> fields_of(boreas_emitter_def& d) {
  return {F3(center), F(area_radius), F(event_radius), F3(impulse), F(rate), F(lifetime)};
}
std::vector<Field> fields_of(boreas_mesh_tree_def& d) {
  std::vector<Field> f = {F3(position),     F(yaw),          F(scale),     F(noise_beta),
                          F(bend_exponent), F(leaf_flutter), F(leaf_turn), F(flutter_wavelength)};
  for (int i = 0; i < 4; ++i) {
    const std::string level = "levels[" + std::to_string(i) + "].";
    f.push_back({level + "bend", &d.levels[i].bend});
    f.push_back({level + "sway", &d.levels[i].sway});
    f.push_back({level + "frequency", &d.levels[i].frequency});
    f.push_back({level + "response_time", &d.levels[i].response_time});
  }
  return f;
}
std::vector<IntField> ints_of(boreas_mesh_tree_def& d) { return {I(cache)}; }
std::vector<Field> fields_of(boreas_blobtree_def& d) {
  return {F(min_radius), F(ridge), F(ridge_width), F(bend)};
}
std::vector<IntField> ints_of(boreas_blobtree_def& d) {
  return {I(resolution), I(cubic), I(max_level), I(offsets), I(cut_count), I(scar_count)};
}
#undef F
#undef F3
#undef I

// Writes an int where the API has an enum, as a C caller may (the bytes C leaves there).
template <typename Enum>
void poke_enum(Enum* field, int value) {
  static_assert(sizeof(Enum) == sizeof(int), "C enums are ints here");
  std::memcpy(field, &value, sizeof value);
}

// Reinterprets an id's bytes as another kind's, as a C cast through a pointer would.
template <typename To, typename From>
To cast_id(From id) {
  To out;
  std::memcpy(&out, &id, sizeof out);
  return out;
}

struct Row {
  std::string call;  // for the failure message
  std::function<boreas_status(boreas_world)> run;
  boreas_status expect;
  std::string names;  // what boreas_last_error() must mention
};

// One of every kind of object, and the device buffers the enqueue calls write to.
struct Objects {
  boreas_tree_id tree = BOREAS_NULL_ID;
  boreas_mesh_tree_id mesh_tree = BOREAS_NULL_ID;
  boreas_blobtree_id blobtree = BOREAS_NULL_ID;
  boreas_meadow_id meadow = BOREAS_NULL_ID;
  boreas_collider_id collider = BOREAS_NULL_ID;
  boreas_emitter_id emitter = BOREAS_NULL_ID;
  boreas_primitive_id primitive = BOREAS_NULL_ID;
  boreas_gust_id gust = BOREAS_NULL_ID;
};

uint64_t hash_of(boreas_world world) {
  uint64_t hash = 0;
  EXPECT_EQ(boreas_world_get_state_hash(world, &hash), BOREAS_OK) << boreas_last_error();
  return hash;
}

class BadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    populate(&world_, &mine_);
    populate(&twin_, &theirs_);
    ASSERT_EQ(boreas_world_get_cl(world_, &cl_), BOREAS_OK) << boreas_last_error();
    cl_int err = CL_SUCCESS;
    buffer_ = clCreateBuffer(cl_.context, CL_MEM_READ_WRITE, 1 << 22, nullptr, &err);
    ASSERT_EQ(err, CL_SUCCESS);
  }
  void TearDown() override {
    if (buffer_) clReleaseMemObject(buffer_);
    boreas_world_destroy(world_);
    boreas_world_destroy(twin_);
  }

  void populate(boreas_world* world, Objects* o) {
    ASSERT_EQ(boreas::test::create_small_windy_world(world), BOREAS_OK) << boreas_last_error();
    boreas_world w = *world;
    boreas_tree_def tree = boreas_default_tree_def();
    ASSERT_EQ(boreas_world_add_tree(w, &tree, &o->tree), BOREAS_OK) << boreas_last_error();
    boreas_mesh_tree_def mesh = boreas_default_mesh_tree_def();
    mesh.model = tube_tree_.c_str();
    mesh.cache = 0;
    mesh.position[0] = 2.0f;
    ASSERT_EQ(boreas_world_add_mesh_tree(w, &mesh, &o->mesh_tree), BOREAS_OK)
        << boreas_last_error();
    boreas_blobtree_def blob = boreas_default_blobtree_def();
    blob.resolution = 16;
    blob.min_radius = 0.05f;  // the trunk and limbs, on a coarse grid
    ASSERT_EQ(boreas_world_add_blobtree(w, o->tree, &blob, nullptr, nullptr, &o->blobtree),
              BOREAS_OK)
        << boreas_last_error();
    boreas_meadow_def meadow = boreas_default_meadow_def();
    meadow.size[0] = meadow.size[1] = 2.0f;
    meadow.density = 100.0f;
    ASSERT_EQ(boreas_world_add_meadow(w, &meadow, &o->meadow), BOREAS_OK) << boreas_last_error();
    boreas_collider_def ball = boreas_default_collider_def();
    ball.pose.position[1] = 0.11f;
    ASSERT_EQ(boreas_world_add_collider(w, &ball, &o->collider), BOREAS_OK) << boreas_last_error();
    boreas_emitter_def rain = boreas_default_emitter_def();
    ASSERT_EQ(boreas_world_add_emitter(w, &rain, &o->emitter), BOREAS_OK) << boreas_last_error();
    boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
    p.type = BOREAS_FLOW_VORTEX;
    p.radius = 3.0f;
    ASSERT_EQ(boreas_wind_add_primitive(w, &p, &o->primitive), BOREAS_OK) << boreas_last_error();
    boreas_gust_def g = boreas_default_gust_def();
    g.hold = 100.0f;
    ASSERT_EQ(boreas_wind_add_gust(w, &g, &o->gust), BOREAS_OK) << boreas_last_error();
    for (int s = 0; s < 3; ++s) ASSERT_EQ(boreas_world_step(w, 1.0f / 30.0f), BOREAS_OK);
  }

  // Runs every row on the abused world: each refused as documented, naming what was wrong,
  // and the state hash unchanged by it.
  void run(const std::vector<Row>& rows) {
    ASSERT_FALSE(rows.empty());
    for (const Row& row : rows) {
      const uint64_t before = hash_of(world_);
      const double time = boreas_world_get_time(world_);
      const boreas_status got = row.run(world_);
      const std::string message = boreas_last_error();
      EXPECT_EQ(got, row.expect) << row.call << ": " << boreas_status_name(got) << " " << message;
      EXPECT_NE(message.find(row.names), std::string::npos)
          << row.call << ": the message does not name '" << row.names << "': " << message;
      EXPECT_EQ(hash_of(world_), before) << row.call << " changed the world";
      EXPECT_EQ(boreas_world_get_time(world_), time) << row.call;
    }
  }

  // After the rows: the abused world and its twin step to the same states.
  void expect_twin_agrees() {
    for (int s = 0; s < 5; ++s) {
      ASSERT_EQ(boreas_world_step(world_, 1.0f / 30.0f), BOREAS_OK) << boreas_last_error();
      ASSERT_EQ(boreas_world_step(twin_, 1.0f / 30.0f), BOREAS_OK) << boreas_last_error();
      ASSERT_EQ(hash_of(world_), hash_of(twin_)) << "step " << s << ": a refused call left a trace";
    }
  }

  // Rows putting NaN and infinities in every float field of a def.
  template <typename Def, typename Call>
  void add_float_rows(std::vector<Row>& rows, const std::string& what, Def (*make)(), Call call) {
    Def probe = make();
    const size_t n = fields_of(probe).size();
    for (size_t i = 0; i < n; ++i) {
      for (float bad : kBadFloats) {
        const std::string name = fields_of(probe)[i].name;
        rows.push_back({what + "." + name + " = " + text(bad),
                        [=](boreas_world w) {
                          Def d = make();
                          *fields_of(d)[i].at = bad;
                          return call(w, d);
                        },
                        BOREAS_ERROR_INVALID_ARGUMENT, name});
      }
    }
  }
  // Rows putting negative and huge values in every int field of a def that has a range.
  template <typename Def, typename Call>
  void add_int_rows(std::vector<Row>& rows, const std::string& what, Def (*make)(), Call call) {
    Def probe = make();
    const size_t n = ints_of(probe).size();
    for (size_t i = 0; i < n; ++i) {
      for (int bad : kBadInts) {
        const std::string name = ints_of(probe)[i].name;
        rows.push_back({what + "." + name + " = " + std::to_string(bad),
                        [=](boreas_world w) {
                          Def d = make();
                          *ints_of(d)[i].at = bad;
                          return call(w, d);
                        },
                        BOREAS_ERROR_INVALID_ARGUMENT, name});
      }
    }
  }
  // Rows handing a function an id that is null, never issued, of the twin world, or of
  // another kind.
  template <typename Id, typename OtherId, typename Call>
  void add_id_rows(std::vector<Row>& rows, const std::string& what, const char* kind, Id live,
                   Id foreign, OtherId other_kind, Call call) {
    Id never = live;
    never.generation += 7;
    const Id cast = cast_id<Id>(other_kind);
    rows.push_back({what + "(null id)", [=](boreas_world w) { return call(w, Id{}); },
                    BOREAS_ERROR_NOT_FOUND, std::string("null ") + kind + " id"});
    rows.push_back({what + "(never issued)", [=](boreas_world w) { return call(w, never); },
                    BOREAS_ERROR_NOT_FOUND, std::string("no ") + kind + " with id"});
    rows.push_back({what + "(the twin's id)", [=](boreas_world w) { return call(w, foreign); },
                    BOREAS_ERROR_NOT_FOUND, "another world"});
    rows.push_back({what + "(another kind's id)", [=](boreas_world w) { return call(w, cast); },
                    BOREAS_ERROR_NOT_FOUND, std::string("is not a ") + kind + " id"});
  }

  boreas::test::TempDir dir_;
  std::string tube_tree_ = boreas::test::write_tube_tree_obj(dir_.path());
  boreas_world world_ = nullptr, twin_ = nullptr;
  Objects mine_, theirs_;
  boreas_cl_objects cl_{};
  cl_mem buffer_ = nullptr;
};

boreas_world_def small_world_def() {
  boreas_world_def def = boreas_default_world_def();
  def.grid.resolution[0] = def.grid.resolution[2] = 8;
  def.grid.resolution[1] = 4;
  return def;
}
boreas_grid_def small_grid_def() { return small_world_def().grid; }

TEST_F(BadInput, EveryFloatFieldRefusesNaNAndInfinity) {
  std::vector<Row> rows;
  add_float_rows(rows, "world_def.grid", small_grid_def, [](boreas_world, boreas_grid_def g) {
    boreas_world_def def = small_world_def();
    def.grid = g;
    boreas_world made = nullptr;
    boreas_status s = boreas_world_create(&def, &made);
    if (made) boreas_world_destroy(made);
    return made == nullptr ? s : BOREAS_ERROR_INTERNAL;
  });
  add_float_rows(rows, "waves", boreas_default_wave, [](boreas_world w, boreas_wave wave) {
    return boreas_wind_set_waves(w, &wave, 1, 0.0f);
  });
  add_float_rows(rows, "primitive", boreas_default_flow_primitive_def,
                 [](boreas_world w, boreas_flow_primitive_def p) {
                   boreas_primitive_id id;
                   return boreas_wind_add_primitive(w, &p, &id);
                 });
  add_float_rows(rows, "gust", boreas_default_gust_def, [](boreas_world w, boreas_gust_def g) {
    boreas_gust_id id;
    return boreas_wind_add_gust(w, &g, &id);
  });
  add_float_rows(rows, "lidar_def", boreas_default_lidar_def,
                 [](boreas_world w, boreas_lidar_def d) {
                   boreas_lidar_id id;
                   return boreas_world_add_lidar(w, &d, &id);
                 });
  add_float_rows(rows, "depth_camera_def", boreas_default_depth_camera_def,
                 [](boreas_world w, boreas_depth_camera_def d) {
                   return boreas_world_capture_depth(w, &d, nullptr, nullptr);
                 });
  add_float_rows(rows, "tree_def", boreas_default_tree_def, [](boreas_world w, boreas_tree_def d) {
    boreas_tree_id id;
    return boreas_world_add_tree(w, &d, &id);
  });
  add_float_rows(rows, "defs[0]", boreas_default_tree_def, [](boreas_world w, boreas_tree_def d) {
    boreas_tree_def two[2] = {d, boreas_default_tree_def()};
    return boreas_world_add_trees(w, two, 2, nullptr);
  });
  add_float_rows(rows, "meadow_def", boreas_default_meadow_def,
                 [](boreas_world w, boreas_meadow_def d) {
                   boreas_meadow_id id;
                   return boreas_world_add_meadow(w, &d, &id);
                 });
  add_float_rows(rows, "collider_def", boreas_default_collider_def,
                 [](boreas_world w, boreas_collider_def d) {
                   boreas_collider_id id;
                   return boreas_world_add_collider(w, &d, &id);
                 });
  add_float_rows(rows, "emitter_def", boreas_default_emitter_def,
                 [](boreas_world w, boreas_emitter_def d) {
                   boreas_emitter_id id;
                   return boreas_world_add_emitter(w, &d, &id);
                 });
  const std::string model = tube_tree_;
  add_float_rows(rows, "mesh_tree_def", boreas_default_mesh_tree_def,
                 [model](boreas_world w, boreas_mesh_tree_def d) {
                   d.model = model.c_str();
                   d.cache = 0;
                   boreas_mesh_tree_id id;
                   return boreas_world_add_mesh_tree(w, &d, &id);
                 });
  const boreas_tree_id tree = mine_.tree;
  add_float_rows(rows, "blobtree_def", boreas_default_blobtree_def,
                 [tree](boreas_world w, boreas_blobtree_def d) {
                   d.resolution = 16;
                   boreas_blobtree_id id;
                   return boreas_world_add_blobtree(w, tree, &d, nullptr, nullptr, &id);
                 });
  // Floats passed as arguments.
  const boreas_collider_id collider = mine_.collider;
  const boreas_emitter_id emitter = mine_.emitter;
  const boreas_meadow_id meadow = mine_.meadow;
  const cl_mem buffer = buffer_;
  for (float bad : kBadFloats) {
    const std::string v = " = " + text(bad);
    rows.push_back({"dt" + v, [=](boreas_world w) { return boreas_world_step(w, bad); },
                    BOREAS_ERROR_INVALID_ARGUMENT, "dt"});
    rows.push_back({"blend_seconds" + v,
                    [=](boreas_world w) {
                      boreas_wave wave = boreas_default_wave();
                      return boreas_wind_set_waves(w, &wave, 1, bad);
                    },
                    BOREAS_ERROR_INVALID_ARGUMENT, "blend_seconds"});
    for (int axis = 0; axis < 3; ++axis) {
      const std::string at = "[" + std::to_string(axis) + "]";
      rows.push_back({"focus points" + at + v,
                      [=](boreas_world w) {
                        float p[3] = {0.0f, 1.8f, 0.0f};
                        p[axis] = bad;
                        return boreas_world_set_focus(w, p, 1);
                      },
                      BOREAS_ERROR_INVALID_ARGUMENT, "points" + at});
      rows.push_back({"collider center" + at + v,
                      [=](boreas_world w) {
                        float c[3] = {0.0f, 0.1f, 0.0f};
                        c[axis] = bad;
                        return boreas_collider_set_position(w, collider, c);
                      },
                      BOREAS_ERROR_INVALID_ARGUMENT, "center" + at});
      rows.push_back({"emitter center" + at + v,
                      [=](boreas_world w) {
                        float c[3] = {0.0f, 1.0f, 0.0f};
                        c[axis] = bad;
                        return boreas_emitter_set_position(w, emitter, c);
                      },
                      BOREAS_ERROR_INVALID_ARGUMENT, "center" + at});
      rows.push_back({"solid box min" + at + v,
                      [=](boreas_world w) {
                        float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {1.0f, 1.0f, 1.0f};
                        lo[axis] = bad;
                        return boreas_wind_add_solid_box(w, lo, hi);
                      },
                      BOREAS_ERROR_INVALID_ARGUMENT, "min" + at});
      rows.push_back({"sample xyz" + at + v,
                      [=](boreas_world w) {
                        float p[6] = {0, 1, 0, 1, 1, 1}, out[6];
                        p[3 + axis] = bad;
                        return boreas_wind_sample(w, p, 2, out);
                      },
                      BOREAS_ERROR_INVALID_ARGUMENT, "xyz[" + std::to_string(3 + axis) + "]"});
      rows.push_back({"meadow vertices camera" + at + v,
                      [=](boreas_world w) {
                        float c[3] = {0.0f, 1.7f, 0.0f};
                        c[axis] = bad;
                        int n = 0;
                        return boreas_meadow_get_vertices(w, meadow, c, nullptr, 0, &n, nullptr);
                      },
                      BOREAS_ERROR_INVALID_ARGUMENT, "camera" + at});
      rows.push_back({"meadow enqueue camera" + at + v,
                      [=](boreas_world w) {
                        float c[3] = {0.0f, 1.7f, 0.0f};
                        c[axis] = bad;
                        return boreas_meadow_enqueue_vertices(w, meadow, c, buffer, buffer, 0);
                      },
                      BOREAS_ERROR_INVALID_ARGUMENT, "camera" + at});
    }
    rows.push_back({"meadow species weight" + v,
                    [=](boreas_world w) {
                      boreas_meadow_species s = {"meadow_grass", bad};
                      boreas_meadow_def d = boreas_default_meadow_def();
                      d.species = &s;
                      d.species_count = 1;
                      boreas_meadow_id id;
                      return boreas_world_add_meadow(w, &d, &id);
                    },
                    BOREAS_ERROR_INVALID_ARGUMENT, "weight"});
    rows.push_back({"blobtree cut at" + v,
                    [=](boreas_world w) {
                      boreas_blobtree_def d = boreas_default_blobtree_def();
                      d.resolution = 16;
                      boreas_blobtree_cut cut = {1, bad};
                      d.cuts = &cut;
                      d.cut_count = 1;
                      boreas_blobtree_id id;
                      return boreas_world_add_blobtree(w, tree, &d, nullptr, nullptr, &id);
                    },
                    BOREAS_ERROR_INVALID_ARGUMENT, "cuts[0].at"});
    rows.push_back({"blobtree scar depth" + v,
                    [=](boreas_world w) {
                      boreas_blobtree_def d = boreas_default_blobtree_def();
                      d.resolution = 16;
                      boreas_blobtree_scar scar = {1, 0.2f, bad};
                      d.scars = &scar;
                      d.scar_count = 1;
                      boreas_blobtree_id id;
                      return boreas_world_add_blobtree(w, tree, &d, nullptr, nullptr, &id);
                    },
                    BOREAS_ERROR_INVALID_ARGUMENT, "scars[0].depth"});
  }
  run(rows);
  expect_twin_agrees();
}

TEST_F(BadInput, IntFieldsOutOfRangeAndEnumsFromCAreRefused) {
  std::vector<Row> rows;
  add_int_rows(rows, "world_def.grid", small_grid_def, [](boreas_world, boreas_grid_def g) {
    boreas_world_def def = small_world_def();
    def.grid = g;
    boreas_world made = nullptr;
    boreas_status s = boreas_world_create(&def, &made);
    if (made) boreas_world_destroy(made);
    return made == nullptr ? s : BOREAS_ERROR_INTERNAL;
  });
  add_int_rows(rows, "tree_def", boreas_default_tree_def, [](boreas_world w, boreas_tree_def d) {
    boreas_tree_id id;
    return boreas_world_add_tree(w, &d, &id);
  });
  add_int_rows(rows, "meadow_def", boreas_default_meadow_def,
               [](boreas_world w, boreas_meadow_def d) {
                 boreas_meadow_id id;
                 return boreas_world_add_meadow(w, &d, &id);
               });
  const std::string model = tube_tree_;
  add_int_rows(rows, "mesh_tree_def", boreas_default_mesh_tree_def,
               [model](boreas_world w, boreas_mesh_tree_def d) {
                 d.model = model.c_str();
                 boreas_mesh_tree_id id;
                 return boreas_world_add_mesh_tree(w, &d, &id);
               });
  const boreas_tree_id tree = mine_.tree;
  add_int_rows(rows, "blobtree_def", boreas_default_blobtree_def,
               [tree](boreas_world w, boreas_blobtree_def d) {
                 if (d.resolution == 256) d.resolution = 16;
                 boreas_blobtree_id id;
                 return boreas_world_add_blobtree(w, tree, &d, nullptr, nullptr, &id);
               });
  // Enum fields of structs, poked as a C caller leaves them. An enum passed by value (the
  // mesh part) cannot be given a bad value from C++ without undefined behaviour in the test
  // itself: tests/host/enums_from_c.c does that from C.
  for (int bad : {-1, 7, INT_MIN, INT_MAX}) {
    const std::string v = " = " + std::to_string(bad);
    rows.push_back({"tree_def.mode" + v,
                    [=](boreas_world w) {
                      boreas_tree_def d = boreas_default_tree_def();
                      poke_enum(&d.mode, bad);
                      return boreas_world_add_tree(w, &d, nullptr);
                    },
                    BOREAS_ERROR_INVALID_ARGUMENT, "mode"});
    rows.push_back({"tree_def.response" + v,
                    [=](boreas_world w) {
                      boreas_tree_def d = boreas_default_tree_def();
                      poke_enum(&d.response, bad);
                      return boreas_world_add_tree(w, &d, nullptr);
                    },
                    BOREAS_ERROR_INVALID_ARGUMENT, "response"});
    rows.push_back({"tree_def.load" + v,
                    [=](boreas_world w) {
                      boreas_tree_def d = boreas_default_tree_def();
                      poke_enum(&d.load, bad);
                      return boreas_world_add_tree(w, &d, nullptr);
                    },
                    BOREAS_ERROR_INVALID_ARGUMENT, "load"});
    rows.push_back({"primitive.type" + v,
                    [=](boreas_world w) {
                      boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
                      poke_enum(&p.type, bad);
                      boreas_primitive_id id;
                      return boreas_wind_add_primitive(w, &p, &id);
                    },
                    BOREAS_ERROR_INVALID_ARGUMENT, "type"});
    rows.push_back({"blobtree_def.junctions" + v,
                    [=](boreas_world w) {
                      boreas_blobtree_def d = boreas_default_blobtree_def();
                      d.resolution = 16;
                      poke_enum(&d.junctions, bad);
                      boreas_blobtree_id id;
                      return boreas_world_add_blobtree(w, tree, &d, nullptr, nullptr, &id);
                    },
                    BOREAS_ERROR_INVALID_ARGUMENT, "junctions"});
  }
  run(rows);
  expect_twin_agrees();
}

TEST_F(BadInput, NullPointersAndBadCountsAreRefused) {
  const Objects o = mine_;
  const cl_mem buffer = buffer_;
  auto invalid = [](std::string call, std::function<boreas_status(boreas_world)> f,
                    std::string names) {
    return Row{std::move(call), std::move(f), BOREAS_ERROR_INVALID_ARGUMENT, std::move(names)};
  };
  boreas_world_def def = small_world_def();
  std::vector<Row> rows = {
      invalid(
          "world_create(NULL def)",
          [](boreas_world) {
            boreas_world w = nullptr;
            return boreas_world_create(nullptr, &w);
          },
          "NULL"),
      invalid(
          "world_create(NULL out)",
          [=](boreas_world) { return boreas_world_create(&def, nullptr); }, "NULL"),
      invalid(
          "world_create(wave_count -1)",
          [=](boreas_world) {
            boreas_world_def d = def;
            d.wave_count = -1;
            boreas_world w = nullptr;
            return boreas_world_create(&d, &w);
          },
          "wave_count"),
      invalid(
          "world_create(waves NULL, wave_count 2)",
          [=](boreas_world) {
            boreas_world_def d = def;
            d.wave_count = 2;
            boreas_world w = nullptr;
            return boreas_world_create(&d, &w);
          },
          "waves"),
      invalid(
          "world_step(NULL world)", [](boreas_world) { return boreas_world_step(nullptr, 0.1f); },
          "world is NULL"),
      invalid(
          "world_step(dt 0)", [](boreas_world w) { return boreas_world_step(w, 0.0f); }, "dt"),
      invalid(
          "world_step(dt -1)", [](boreas_world w) { return boreas_world_step(w, -1.0f); }, "dt"),
      invalid(
          "world_step(dt 1e9)", [](boreas_world w) { return boreas_world_step(w, 1e9f); }, "dt"),
      invalid(
          "world_device(NULL)", [](boreas_world w) { return boreas_world_get_device(w, nullptr); },
          "NULL"),
      invalid(
          "get_step_stats(NULL)",
          [](boreas_world w) { return boreas_world_get_step_stats(w, nullptr); }, "NULL"),
      invalid(
          "get_memory(NULL)", [](boreas_world w) { return boreas_world_get_memory(w, nullptr); },
          "NULL"),
      invalid(
          "state_hash(NULL)",
          [](boreas_world w) { return boreas_world_get_state_hash(w, nullptr); }, "NULL"),
      invalid(
          "list_devices(capacity -1)",
          [](boreas_world) {
            int n = 0;
            boreas_device_info info;
            return boreas_list_devices(&info, -1, &n);
          },
          "capacity"),
      invalid(
          "list_devices(NULL count)",
          [](boreas_world) { return boreas_list_devices(nullptr, 0, nullptr); }, "count"),
      invalid(
          "choose_device(NULL index)",
          [](boreas_world) { return boreas_choose_device("cpu", nullptr); }, "NULL"),
      invalid(
          "set_waves(NULL, 1)",
          [](boreas_world w) { return boreas_wind_set_waves(w, nullptr, 1, 0.0f); }, "waves"),
      invalid(
          "set_waves(count -1)",
          [](boreas_world w) {
            boreas_wave wave = boreas_default_wave();
            return boreas_wind_set_waves(w, &wave, -1, 0.0f);
          },
          "count"),
      invalid(
          "set_waves(count INT_MAX)",
          [](boreas_world w) {
            boreas_wave wave = boreas_default_wave();
            return boreas_wind_set_waves(w, &wave, INT_MAX, 0.0f);
          },
          "count"),
      invalid(
          "set_waves(blend -1)",
          [](boreas_world w) {
            boreas_wave wave = boreas_default_wave();
            return boreas_wind_set_waves(w, &wave, 1, -1.0f);
          },
          "blend_seconds"),
      invalid(
          "add_primitive(NULL)",
          [](boreas_world w) {
            boreas_primitive_id id;
            return boreas_wind_add_primitive(w, nullptr, &id);
          },
          "NULL"),
      invalid(
          "add_gust(NULL gust)",
          [](boreas_world w) {
            boreas_gust_id id;
            return boreas_wind_add_gust(w, nullptr, &id);
          },
          "NULL"),
      invalid(
          "add_solid_box(NULL)",
          [](boreas_world w) {
            float hi[3] = {1, 1, 1};
            return boreas_wind_add_solid_box(w, nullptr, hi);
          },
          "NULL"),
      invalid(
          "add_solid_box(min > max)",
          [](boreas_world w) {
            float lo[3] = {0, 2, 0}, hi[3] = {1, 1, 1};
            return boreas_wind_add_solid_box(w, lo, hi);
          },
          "min"),
      invalid(
          "set_solid_mask(NULL, 5)",
          [](boreas_world w) { return boreas_wind_set_solid_mask(w, nullptr, 5); }, "mask"),
      invalid(
          "set_solid_mask(count of another grid)",
          [](boreas_world w) {
            std::vector<uint8_t> mask(7, 0);
            return boreas_wind_set_solid_mask(w, mask.data(), 7);
          },
          "count"),
      invalid(
          "sample(NULL xyz)",
          [](boreas_world w) {
            float out[3];
            return boreas_wind_sample(w, nullptr, 1, out);
          },
          "NULL"),
      invalid(
          "sample(NULL out)",
          [](boreas_world w) {
            float p[3] = {0, 1, 0};
            return boreas_wind_sample(w, p, 1, nullptr);
          },
          "NULL"),
      invalid(
          "sample(count -1)",
          [](boreas_world w) {
            float p[3] = {0, 1, 0}, out[3];
            return boreas_wind_sample(w, p, -1, out);
          },
          "count"),
      invalid(
          "sample(count INT_MAX)",
          [](boreas_world w) {
            float p[3] = {0, 1, 0}, out[3];
            return boreas_wind_sample(w, p, INT_MAX, out);
          },
          "count"),
      invalid(
          "wind_grid(NULL)", [](boreas_world w) { return boreas_wind_get_grid(w, nullptr); },
          "NULL"),
      invalid(
          "read_grid(NULL, 8)",
          [](boreas_world w) { return boreas_wind_get_grid_values(w, nullptr, 8); }, "NULL"),
      invalid(
          "read_grid(capacity too small)",
          [](boreas_world w) {
            float few[8];
            return boreas_wind_get_grid_values(w, few, 8);
          },
          "capacity"),
      invalid(
          "read_grid(capacity -1)",
          [](boreas_world w) {
            float few[8];
            return boreas_wind_get_grid_values(w, few, -1);
          },
          "capacity"),
      invalid(
          "add_tree(NULL def)",
          [](boreas_world w) { return boreas_world_add_tree(w, nullptr, nullptr); }, "NULL"),
      invalid(
          "add_tree(species NULL)",
          [](boreas_world w) {
            boreas_tree_def d = boreas_default_tree_def();
            d.species = nullptr;
            return boreas_world_add_tree(w, &d, nullptr);
          },
          "species"),
      invalid(
          "add_trees(NULL, 2)",
          [](boreas_world w) { return boreas_world_add_trees(w, nullptr, 2, nullptr); }, "defs"),
      invalid(
          "add_trees(count -1)",
          [](boreas_world w) {
            boreas_tree_def d = boreas_default_tree_def();
            return boreas_world_add_trees(w, &d, -1, nullptr);
          },
          "count"),
      invalid(
          "add_trees(defs[2] bad: none added)",
          [](boreas_world w) {
            boreas_tree_def d[3] = {boreas_default_tree_def(), boreas_default_tree_def(),
                                    boreas_default_tree_def()};
            d[2].scale = -1.0f;
            return boreas_world_add_trees(w, d, 3, nullptr);
          },
          "defs[2]"),
      invalid(
          "set_focus(NULL, 1)",
          [](boreas_world w) { return boreas_world_set_focus(w, nullptr, 1); }, "points"),
      invalid(
          "set_focus(count -1)",
          [](boreas_world w) {
            float p[3] = {0, 0, 0};
            return boreas_world_set_focus(w, p, -1);
          },
          "count"),
      invalid(
          "get_branches(NULL count)",
          [=](boreas_world w) { return boreas_tree_get_branches(w, o.tree, nullptr, 0, nullptr); },
          "count"),
      invalid(
          "get_branches(capacity -1)",
          [=](boreas_world w) {
            boreas_branch b;
            int n = 0;
            return boreas_tree_get_branches(w, o.tree, &b, -1, &n);
          },
          "capacity"),
      invalid(
          "get_leaves(NULL count)",
          [=](boreas_world w) { return boreas_tree_get_leaves(w, o.tree, nullptr, 0, nullptr); },
          "count"),
      invalid(
          "get_mesh(vertex capacity too small)",
          [=](boreas_world w) {
            boreas_vertex v[4];
            uint32_t idx[4];
            int nv = 0, ni = 0;
            return boreas_tree_get_mesh(w, o.tree, v, 4, &nv, idx, 4, &ni);
          },
          "capacities"),
      invalid(
          "add_meadow(NULL def)",
          [](boreas_world w) {
            boreas_meadow_id id;
            return boreas_world_add_meadow(w, nullptr, &id);
          },
          "NULL"),
      invalid(
          "add_meadows(count -1)",
          [](boreas_world w) {
            boreas_meadow_def d = boreas_default_meadow_def();
            return boreas_world_add_meadows(w, &d, -1, nullptr);
          },
          "count"),
      invalid(
          "add_meadow(species NULL, count 2)",
          [](boreas_world w) {
            boreas_meadow_def d = boreas_default_meadow_def();
            d.species_count = 2;
            boreas_meadow_id id;
            return boreas_world_add_meadow(w, &d, &id);
          },
          "species"),
      invalid(
          "meadow_get_components(NULL count)",
          [=](boreas_world w) {
            return boreas_meadow_get_components(w, o.meadow, nullptr, 0, nullptr);
          },
          "count"),
      invalid(
          "meadow_get_parts(NULL count)",
          [=](boreas_world w) { return boreas_meadow_get_parts(w, o.meadow, nullptr, 0, nullptr); },
          "count"),
      invalid(
          "meadow_get_vertices(capacity too small)",
          [=](boreas_world w) {
            boreas_meadow_vertex v[4];
            int n = 0;
            return boreas_meadow_get_vertices(w, o.meadow, nullptr, v, 4, &n, nullptr);
          },
          "capacity"),
      invalid(
          "add_collider(NULL def)",
          [](boreas_world w) {
            boreas_collider_id id;
            return boreas_world_add_collider(w, nullptr, &id);
          },
          "NULL"),
      invalid(
          "collider_set_position(NULL)",
          [=](boreas_world w) { return boreas_collider_set_position(w, o.collider, nullptr); },
          "NULL"),
      invalid(
          "add_emitter(NULL def)",
          [](boreas_world w) {
            boreas_emitter_id id;
            return boreas_world_add_emitter(w, nullptr, &id);
          },
          "NULL"),
      invalid(
          "emitter_set_position(NULL)",
          [=](boreas_world w) { return boreas_emitter_set_position(w, o.emitter, nullptr); },
          "NULL"),
      invalid(
          "add_mesh_tree(model NULL)",
          [](boreas_world w) {
            boreas_mesh_tree_def d = boreas_default_mesh_tree_def();
            boreas_mesh_tree_id id;
            return boreas_world_add_mesh_tree(w, &d, &id);
          },
          "model"),
      invalid(
          "mesh_tree_get_info(NULL)",
          [=](boreas_world w) { return boreas_mesh_tree_get_info(w, o.mesh_tree, nullptr); },
          "NULL"),
      invalid(
          "mesh_tree_get_vertices(capacity -1)",
          [=](boreas_world w) {
            boreas_vertex v;
            int n = 0;
            return boreas_mesh_tree_get_vertices(w, o.mesh_tree, BOREAS_MESH_TRUNK, &v, -1, &n);
          },
          "capacity"),
      invalid(
          "mesh_tree_get_indices(NULL count)",
          [=](boreas_world w) {
            return boreas_mesh_tree_get_indices(w, o.mesh_tree, BOREAS_MESH_TRUNK, nullptr, 0,
                                                nullptr);
          },
          "count"),
      invalid(
          "preprocess_mesh_tree(NULL def)",
          [](boreas_world) { return boreas_preprocess_mesh_tree(nullptr, "/tmp/x.glb", nullptr); },
          "NULL"),
      invalid(
          "add_blobtree(NULL def)",
          [=](boreas_world w) {
            boreas_blobtree_id id;
            return boreas_world_add_blobtree(w, o.tree, nullptr, nullptr, nullptr, &id);
          },
          "NULL"),
      invalid(
          "add_blobtree(cuts NULL, cut_count 1)",
          [=](boreas_world w) {
            boreas_blobtree_def d = boreas_default_blobtree_def();
            d.resolution = 16;
            d.cut_count = 1;
            boreas_blobtree_id id;
            return boreas_world_add_blobtree(w, o.tree, &d, nullptr, nullptr, &id);
          },
          "cuts"),
      invalid(
          "blobtree_get_info(NULL)",
          [=](boreas_world w) { return boreas_blobtree_get_info(w, o.blobtree, nullptr); }, "NULL"),
      invalid(
          "blobtree_get_mesh(capacity too small)",
          [=](boreas_world w) {
            boreas_vertex v[4];
            uint32_t idx[4];
            int nv = 0, ni = 0;
            return boreas_blobtree_get_mesh(w, o.blobtree, v, 4, &nv, idx, 4, &ni);
          },
          "capacities"),
      invalid(
          "world_get_cl(NULL)", [](boreas_world w) { return boreas_world_get_cl(w, nullptr); },
          "NULL"),
      invalid(
          "enqueue_branch_records(NULL buffer)",
          [=](boreas_world w) { return boreas_tree_enqueue_branch_records(w, o.tree, nullptr, 0); },
          "NULL"),
      invalid(
          "enqueue_branch_records(past the buffer's end)",
          [=](boreas_world w) {
            return boreas_tree_enqueue_branch_records(w, o.tree, buffer, size_t(1) << 40);
          },
          "buffer"),
      invalid(
          "enqueue_leaf_records(NULL buffer)",
          [=](boreas_world w) { return boreas_tree_enqueue_leaf_records(w, o.tree, nullptr, 0); },
          "NULL"),
      invalid(
          "meadow_enqueue_vertices(NULL counts)",
          [=](boreas_world w) {
            return boreas_meadow_enqueue_vertices(w, o.meadow, nullptr, buffer, nullptr, 0);
          },
          "NULL"),
      invalid(
          "mesh_tree_enqueue_vertices(NULL buffer)",
          [=](boreas_world w) {
            return boreas_mesh_tree_enqueue_vertices(w, o.mesh_tree, BOREAS_MESH_LEAVES, nullptr,
                                                     0);
          },
          "NULL"),
  };
  // No world: every call that takes one says so.
  rows.push_back(invalid(
      "add_tree(NULL world)",
      [](boreas_world) {
        boreas_tree_def d = boreas_default_tree_def();
        return boreas_world_add_tree(nullptr, &d, nullptr);
      },
      "world is NULL"));
  rows.push_back(invalid(
      "remove_meadow(NULL world)",
      [=](boreas_world) { return boreas_world_remove_meadow(nullptr, o.meadow); },
      "world is NULL"));
  run(rows);
  EXPECT_EQ(boreas_world_get_time(nullptr), 0.0);
  boreas_world_destroy(nullptr);  // a no-op, as free(NULL)
  EXPECT_EQ(boreas_builtin_species(-1), nullptr);
  EXPECT_EQ(boreas_builtin_species(INT_MAX), nullptr);
  EXPECT_EQ(boreas_builtin_underbrush_species(-1), nullptr);
  EXPECT_STRNE(boreas_status_name(static_cast<boreas_status>(99)), "");
  expect_twin_agrees();
}

// One output-array rule for every getter (boreas.h, "Output arrays"): out NULL gives the
// count; a capacity below it is refused naming the size needed, and nothing is written,
// count included; a capacity that holds them all writes them all.
// A progress callback that calls into the world it reports on (steps it, adds to it, reads
// it, destroys it) is refused while the call runs, and the world is left as it was.
TEST_F(BadInput, CallsIntoTheWorldFromItsOwnProgressCallbackAreRefused) {
  struct Inside {
    boreas_world world;
    boreas_tree_id tree;
    int calls = 0;
    std::vector<boreas_status> got;
    std::vector<std::string> messages;
  } inside{world_, mine_.tree};
  auto progress = [](void* user, float, const char*) {
    auto* in = static_cast<Inside*>(user);
    if (in->calls++ > 0) return;  // once is enough
    auto record = [&](boreas_status s) {
      in->got.push_back(s);
      in->messages.push_back(boreas_last_error());
    };
    record(boreas_world_step(in->world, 1.0f / 30.0f));
    boreas_tree_def tree = boreas_default_tree_def();
    boreas_tree_id id;
    record(boreas_world_add_tree(in->world, &tree, &id));
    uint64_t hash = 0;
    record(boreas_world_get_state_hash(in->world, &hash));
    boreas_world_destroy(in->world);  // left alone: the call below must still finish
    in->got.push_back(BOREAS_ERROR_INVALID_ARGUMENT);
    in->messages.push_back(boreas_last_error());
  };
  const uint64_t before = hash_of(world_);
  const double time = boreas_world_get_time(world_);
  boreas_blobtree_def blob = boreas_default_blobtree_def();
  blob.resolution = 16;
  blob.min_radius = 0.05f;
  boreas_blobtree_id id;
  ASSERT_EQ(boreas_world_add_blobtree(world_, mine_.tree, &blob, progress, &inside, &id), BOREAS_OK)
      << boreas_last_error();
  ASSERT_EQ(inside.got.size(), 4u) << "the callback ran";
  const char* calls[4] = {"boreas_world_step", "boreas_world_add_tree",
                          "boreas_world_get_state_hash", "boreas_world_destroy"};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(inside.got[i], BOREAS_ERROR_INVALID_ARGUMENT) << calls[i];
    EXPECT_NE(inside.messages[i].find(std::string(calls[i]) + ": the world is locked: "
                                                              "boreas_world_add_blobtree"),
              std::string::npos)
        << inside.messages[i];
  }
  EXPECT_EQ(hash_of(world_), before) << "a refused call changed the world";
  EXPECT_EQ(boreas_world_get_time(world_), time);
  boreas_blobtree_info info;
  EXPECT_EQ(boreas_blobtree_get_info(world_, id, &info), BOREAS_OK) << boreas_last_error();
  expect_twin_agrees();
}

TEST_F(BadInput, OutputArraysTooSmallAreRefusedAndNothingIsWritten) {
  const Objects o = mine_;
  struct Getter {
    std::string name;
    size_t item_size;
    std::function<boreas_status(void* out, int capacity, int* count)> call;
  };
  const boreas_world w = world_;
  const std::vector<Getter> getters = {
      {"list_devices", sizeof(boreas_device_info),
       [](void* out, int capacity, int* count) {
         return boreas_list_devices(static_cast<boreas_device_info*>(out), capacity, count);
       }},
      {"tree_get_branches", sizeof(boreas_branch),
       [=](void* out, int capacity, int* count) {
         return boreas_tree_get_branches(w, o.tree, static_cast<boreas_branch*>(out), capacity,
                                         count);
       }},
      {"tree_get_leaves", sizeof(boreas_leaf),
       [=](void* out, int capacity, int* count) {
         return boreas_tree_get_leaves(w, o.tree, static_cast<boreas_leaf*>(out), capacity, count);
       }},
      {"meadow_get_components", sizeof(boreas_component),
       [=](void* out, int capacity, int* count) {
         return boreas_meadow_get_components(w, o.meadow, static_cast<boreas_component*>(out),
                                             capacity, count);
       }},
      {"meadow_get_parts", sizeof(boreas_meadow_part),
       [=](void* out, int capacity, int* count) {
         return boreas_meadow_get_parts(w, o.meadow, static_cast<boreas_meadow_part*>(out),
                                        capacity, count);
       }},
      {"mesh_tree_get_vertices", sizeof(boreas_vertex),
       [=](void* out, int capacity, int* count) {
         return boreas_mesh_tree_get_vertices(w, o.mesh_tree, BOREAS_MESH_TRUNK,
                                              static_cast<boreas_vertex*>(out), capacity, count);
       }},
      {"mesh_tree_get_indices", sizeof(uint32_t),
       [=](void* out, int capacity, int* count) {
         return boreas_mesh_tree_get_indices(w, o.mesh_tree, BOREAS_MESH_LEAVES,
                                             static_cast<uint32_t*>(out), capacity, count);
       }},
  };
  const uint64_t before = hash_of(world_);
  for (const Getter& g : getters) {
    int total = -1;
    ASSERT_EQ(g.call(nullptr, 0, &total), BOREAS_OK) << g.name << ": " << boreas_last_error();
    ASSERT_GE(total, 1) << g.name;
    // One item short (or none at all): refused, nothing written.
    for (int capacity : {total - 1, 0}) {
      std::vector<unsigned char> out(g.item_size * size_t(total), 0xAB);
      int count = -7;
      EXPECT_EQ(g.call(out.data(), capacity, &count), BOREAS_ERROR_INVALID_ARGUMENT) << g.name;
      const std::string message = boreas_last_error();
      EXPECT_NE(message.find("capacity " + std::to_string(capacity) + " is below the " +
                             std::to_string(total)),
                std::string::npos)
          << g.name << ": " << message;
      EXPECT_EQ(count, -7) << g.name << ": count was written";
      EXPECT_TRUE(std::all_of(out.begin(), out.end(), [](unsigned char b) { return b == 0xAB; }))
          << g.name << ": items were written";
    }
    // Room for all, and more: all are written, the rest is untouched.
    std::vector<unsigned char> out(g.item_size * size_t(total + 1), 0xAB);
    int count = -7;
    ASSERT_EQ(g.call(out.data(), total + 1, &count), BOREAS_OK)
        << g.name << ": " << boreas_last_error();
    EXPECT_EQ(count, total) << g.name;
    EXPECT_TRUE(std::all_of(out.end() - std::ptrdiff_t(g.item_size), out.end(),
                            [](unsigned char b) { return b == 0xAB; }))
        << g.name;
  }
  EXPECT_EQ(hash_of(world_), before);
}

TEST_F(BadInput, EveryFunctionTakingAnIdRefusesNullStaleForeignAndWrongKindIds) {
  const Objects m = mine_, t = theirs_;
  const cl_mem buffer = buffer_;
  std::vector<Row> rows;
  const float at[3] = {0.0f, 0.5f, 0.0f};
  int n = 0;
  int* count = &n;
  add_id_rows(rows, "remove_tree", "tree", m.tree, t.tree, m.meadow,
              [](boreas_world w, boreas_tree_id id) { return boreas_world_remove_tree(w, id); });
  add_id_rows(rows, "get_branches", "tree", m.tree, t.tree, m.collider,
              [=](boreas_world w, boreas_tree_id id) {
                return boreas_tree_get_branches(w, id, nullptr, 0, count);
              });
  add_id_rows(rows, "get_leaves", "tree", m.tree, t.tree, m.mesh_tree,
              [=](boreas_world w, boreas_tree_id id) {
                return boreas_tree_get_leaves(w, id, nullptr, 0, count);
              });
  add_id_rows(rows, "get_mesh", "tree", m.tree, t.tree, m.blobtree,
              [=](boreas_world w, boreas_tree_id id) {
                int ni = 0;
                return boreas_tree_get_mesh(w, id, nullptr, 0, count, nullptr, 0, &ni);
              });
  add_id_rows(rows, "enqueue_branch_records", "tree", m.tree, t.tree, m.meadow,
              [=](boreas_world w, boreas_tree_id id) {
                return boreas_tree_enqueue_branch_records(w, id, buffer, 0);
              });
  add_id_rows(rows, "enqueue_leaf_records", "tree", m.tree, t.tree, m.meadow,
              [=](boreas_world w, boreas_tree_id id) {
                return boreas_tree_enqueue_leaf_records(w, id, buffer, 0);
              });
  add_id_rows(rows, "add_blobtree", "tree", m.tree, t.tree, m.mesh_tree,
              [](boreas_world w, boreas_tree_id id) {
                boreas_blobtree_def d = boreas_default_blobtree_def();
                d.resolution = 16;
                boreas_blobtree_id out;
                return boreas_world_add_blobtree(w, id, &d, nullptr, nullptr, &out);
              });
  add_id_rows(
      rows, "remove_meadow", "meadow", m.meadow, t.meadow, m.tree,
      [](boreas_world w, boreas_meadow_id id) { return boreas_world_remove_meadow(w, id); });
  add_id_rows(rows, "meadow_get_components", "meadow", m.meadow, t.meadow, m.tree,
              [=](boreas_world w, boreas_meadow_id id) {
                return boreas_meadow_get_components(w, id, nullptr, 0, count);
              });
  add_id_rows(rows, "meadow_get_parts", "meadow", m.meadow, t.meadow, m.tree,
              [=](boreas_world w, boreas_meadow_id id) {
                return boreas_meadow_get_parts(w, id, nullptr, 0, count);
              });
  add_id_rows(rows, "meadow_get_vertices", "meadow", m.meadow, t.meadow, m.emitter,
              [=](boreas_world w, boreas_meadow_id id) {
                return boreas_meadow_get_vertices(w, id, nullptr, nullptr, 0, count, nullptr);
              });
  add_id_rows(rows, "meadow_enqueue_vertices", "meadow", m.meadow, t.meadow, m.tree,
              [=](boreas_world w, boreas_meadow_id id) {
                return boreas_meadow_enqueue_vertices(w, id, nullptr, buffer, buffer, 0);
              });
  add_id_rows(
      rows, "remove_collider", "collider", m.collider, t.collider, m.emitter,
      [](boreas_world w, boreas_collider_id id) { return boreas_world_remove_collider(w, id); });
  add_id_rows(rows, "collider_set_position", "collider", m.collider, t.collider, m.meadow,
              [=](boreas_world w, boreas_collider_id id) {
                return boreas_collider_set_position(w, id, at);
              });
  add_id_rows(
      rows, "remove_emitter", "emitter", m.emitter, t.emitter, m.collider,
      [](boreas_world w, boreas_emitter_id id) { return boreas_world_remove_emitter(w, id); });
  add_id_rows(
      rows, "emitter_set_position", "emitter", m.emitter, t.emitter, m.gust,
      [=](boreas_world w, boreas_emitter_id id) { return boreas_emitter_set_position(w, id, at); });
  add_id_rows(
      rows, "remove_mesh_tree", "mesh tree", m.mesh_tree, t.mesh_tree, m.tree,
      [](boreas_world w, boreas_mesh_tree_id id) { return boreas_world_remove_mesh_tree(w, id); });
  add_id_rows(rows, "mesh_tree_get_info", "mesh tree", m.mesh_tree, t.mesh_tree, m.tree,
              [](boreas_world w, boreas_mesh_tree_id id) {
                boreas_mesh_tree_info info;
                return boreas_mesh_tree_get_info(w, id, &info);
              });
  add_id_rows(rows, "mesh_tree_get_vertices", "mesh tree", m.mesh_tree, t.mesh_tree, m.blobtree,
              [=](boreas_world w, boreas_mesh_tree_id id) {
                return boreas_mesh_tree_get_vertices(w, id, BOREAS_MESH_LEAVES, nullptr, 0, count);
              });
  add_id_rows(rows, "mesh_tree_get_indices", "mesh tree", m.mesh_tree, t.mesh_tree, m.tree,
              [=](boreas_world w, boreas_mesh_tree_id id) {
                return boreas_mesh_tree_get_indices(w, id, BOREAS_MESH_TRUNK, nullptr, 0, count);
              });
  add_id_rows(rows, "mesh_tree_enqueue_vertices", "mesh tree", m.mesh_tree, t.mesh_tree, m.tree,
              [=](boreas_world w, boreas_mesh_tree_id id) {
                return boreas_mesh_tree_enqueue_vertices(w, id, BOREAS_MESH_TRUNK, buffer, 0);
              });
  add_id_rows(
      rows, "remove_blobtree", "blobtree", m.blobtree, t.blobtree, m.tree,
      [](boreas_world w, boreas_blobtree_id id) { return boreas_world_remove_blobtree(w, id); });
  add_id_rows(rows, "blobtree_get_info", "blobtree", m.blobtree, t.blobtree, m.mesh_tree,
              [](boreas_world w, boreas_blobtree_id id) {
                boreas_blobtree_info info;
                return boreas_blobtree_get_info(w, id, &info);
              });
  add_id_rows(rows, "blobtree_get_mesh", "blobtree", m.blobtree, t.blobtree, m.tree,
              [=](boreas_world w, boreas_blobtree_id id) {
                int ni = 0;
                return boreas_blobtree_get_mesh(w, id, nullptr, 0, count, nullptr, 0, &ni);
              });
  add_id_rows(
      rows, "remove_primitive", "flow primitive", m.primitive, t.primitive, m.gust,
      [](boreas_world w, boreas_primitive_id id) { return boreas_wind_remove_primitive(w, id); });
  add_id_rows(rows, "remove_gust", "gust", m.gust, t.gust, m.primitive,
              [](boreas_world w, boreas_gust_id id) { return boreas_wind_remove_gust(w, id); });
  run(rows);
  expect_twin_agrees();
}

}  // namespace
