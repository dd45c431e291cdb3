// boreas for Python: the C structs to and from Python dicts. A def is read from a dict over
// the library's defaults (boreas_default_*), key by key under the C field's own name; an
// unknown key is a TypeError and a value of the wrong kind a TypeError or ValueError naming
// the field. Enum fields are lowercase strings ("exact", "damped", ...).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas_py {

// A def together with the strings and lists its pointers refer to. Not copyable: the
// pointers point into the object itself.
struct TreeDef {
  boreas_tree_def def;
  std::string species;
  TreeDef() = default;
  TreeDef(const TreeDef&) = delete;
  TreeDef& operator=(const TreeDef&) = delete;
};

struct MeadowDef {
  boreas_meadow_def def;
  std::vector<std::string> names;
  std::vector<boreas_meadow_species> species;
  // The terrain and nutrient maps as C-contiguous float32 arrays, held while def points
  // into them.
  pybind11::array_t<float, pybind11::array::c_style | pybind11::array::forcecast> terrain,
      nutrients;
  MeadowDef() = default;
  MeadowDef(const MeadowDef&) = delete;
  MeadowDef& operator=(const MeadowDef&) = delete;
};

struct MeshTreeDef {
  boreas_mesh_tree_def def;
  std::string model, trunk_part, leaves_part;
  MeshTreeDef() = default;
  MeshTreeDef(const MeshTreeDef&) = delete;
  MeshTreeDef& operator=(const MeshTreeDef&) = delete;
};

struct BlobTreeDef {
  boreas_blobtree_def def;
  std::vector<boreas_blobtree_cut> cuts;
  std::vector<boreas_blobtree_scar> scars;
  BlobTreeDef() = default;
  BlobTreeDef(const BlobTreeDef&) = delete;
  BlobTreeDef& operator=(const BlobTreeDef&) = delete;
};

struct LidarDef {
  boreas_lidar_def def;
  std::vector<float> vertical_angles;  // def.vertical_angles points here when given
  LidarDef() = default;
  LidarDef(const LidarDef&) = delete;
  LidarDef& operator=(const LidarDef&) = delete;
};

// From dicts (None: the defaults). `what` names the argument in messages.
boreas_grid_def grid_from(pybind11::handle obj);
boreas_wave wave_from(pybind11::handle obj, const std::string& what);
std::vector<boreas_wave> waves_from(pybind11::handle seq);  // None: no waves
boreas_gust_def gust_from(pybind11::handle obj);
boreas_flow_primitive_def primitive_from(pybind11::handle obj);
void tree_from(pybind11::handle obj, TreeDef* out, const std::string& what);
void meadow_from(pybind11::handle obj, MeadowDef* out, const std::string& what);
boreas_collider_def collider_from(pybind11::handle obj);
boreas_emitter_def emitter_from(pybind11::handle obj);
void mesh_tree_from(pybind11::handle obj, MeshTreeDef* out);
void blobtree_from(pybind11::handle obj, BlobTreeDef* out);
boreas_mesh_part mesh_part_from(pybind11::handle obj);
void vec3_from(pybind11::handle obj, float out[3], const std::string& what);
// A LiDAR def over `base` (the defaults or a preset's): vertical_angles a sequence of
// floats (channels defaults to its length) or None; pose a mapping.
void lidar_from(pybind11::handle obj, const boreas_lidar_def& base, LidarDef* out);
boreas_pose pose_from(pybind11::handle obj, const std::string& what);
boreas_depth_camera_def depth_camera_from(pybind11::handle obj);

// To dicts (tuples for fixed-size arrays, strings for enums).
pybind11::dict to_dict(const boreas_grid_def& g);
pybind11::dict to_dict(const boreas_wave& w);
pybind11::dict to_dict(const boreas_device_info& d);
pybind11::dict to_dict(const boreas_step_stats& s);
pybind11::dict to_dict(const boreas_memory_info& m);
pybind11::dict to_dict(const boreas_mesh_tree_info& i);
pybind11::dict to_dict(const boreas_blobtree_info& i);
pybind11::dict to_dict(const boreas_lidar_info& i);
pybind11::dict to_dict(const boreas_pose& p);  // position, orientation
pybind11::dict to_dict(const boreas_collider_contact& c);  // force, torque, contacts
// A LiDAR def as lidar_from reads it (vertical_angles a list, or None).
pybind11::dict to_dict(const boreas_lidar_def& d);

// The library's defaults of every def, as dicts (module function `defaults`).
pybind11::dict all_defaults();

}  // namespace boreas_py
