// boreas for Python: dicts to and from the C structs. Each struct's fields are listed once
// (the *_fields functions) and walked by a Reader (dict -> struct, over the defaults) or a
// Writer (struct -> dict), so both directions use the same names.
#include "convert.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <set>
#include <utility>

namespace py = pybind11;

namespace boreas_py {
namespace {

template <typename E>
struct Name {
  const char* name;
  E value;
};

const Name<boreas_flow_type> kFlowTypes[] = {{"uniform", BOREAS_FLOW_UNIFORM},
                                             {"source", BOREAS_FLOW_SOURCE},
                                             {"sink", BOREAS_FLOW_SINK},
                                             {"vortex", BOREAS_FLOW_VORTEX}};
const Name<boreas_tree_mode> kTreeModes[] = {{"lagged", BOREAS_TREE_LAGGED},
                                             {"exact", BOREAS_TREE_EXACT}};
const Name<boreas_tree_response> kTreeResponses[] = {{"quasi_static", BOREAS_TREE_QUASI_STATIC},
                                                     {"damped", BOREAS_TREE_DAMPED}};
const Name<boreas_tree_load> kTreeLoads[] = {{"drag", BOREAS_TREE_LOAD_DRAG},
                                             {"linear", BOREAS_TREE_LOAD_LINEAR}};
const Name<boreas_leaf_outline> kLeafOutlines[] = {{"species", BOREAS_LEAF_OUTLINE_SPECIES},
                                                   {"broadleaf", BOREAS_LEAF_BROADLEAF},
                                                   {"aspen", BOREAS_LEAF_ASPEN},
                                                   {"oak", BOREAS_LEAF_OAK},
                                                   {"willow", BOREAS_LEAF_WILLOW},
                                                   {"tupelo", BOREAS_LEAF_TUPELO}};
const Name<boreas_blobtree_junction> kJunctions[] = {{"pcm", BOREAS_BLOBTREE_PCM},
                                                     {"blend", BOREAS_BLOBTREE_BLEND}};
const Name<boreas_collider_shape> kColliderShapes[] = {{"sphere", BOREAS_COLLIDER_SPHERE},
                                                      {"capsule", BOREAS_COLLIDER_CAPSULE},
                                                      {"box", BOREAS_COLLIDER_BOX}};
const Name<boreas_mesh_part> kMeshParts[] = {{"trunk", BOREAS_MESH_TRUNK},
                                             {"leaves", BOREAS_MESH_LEAVES}};
const Name<boreas_wind_sampling> kWindSamplings[] = {
    {"exact", BOREAS_WIND_SAMPLING_EXACT}, {"interpolated", BOREAS_WIND_SAMPLING_INTERPOLATED}};

std::string type_name(py::handle obj) { return py::str(py::type::of(obj).attr("__name__")); }

bool is_mapping(py::handle obj) {
  return PyMapping_Check(obj.ptr()) && !PyUnicode_Check(obj.ptr()) && !PySequence_Check(obj.ptr());
}

double to_double(py::handle obj, const std::string& what) {
  if (PyUnicode_Check(obj.ptr()) || PyBytes_Check(obj.ptr()))
    throw py::type_error(what + " must be a number, not " + type_name(obj));
  double x = PyFloat_AsDouble(obj.ptr());
  if (x == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    throw py::type_error(what + " must be a number, not " + type_name(obj));
  }
  return x;
}

// Integers only (no floats: 2.5 seeds or cell counts are mistakes); bools are integers.
long long to_integer(py::handle obj, const std::string& what, long long lo, long long hi) {
  PyObject* index = PyNumber_Index(obj.ptr());
  if (!index) {
    PyErr_Clear();
    throw py::type_error(what + " must be an integer, not " + type_name(obj));
  }
  int overflow = 0;
  long long x = PyLong_AsLongLongAndOverflow(index, &overflow);
  Py_DECREF(index);
  if (overflow || x < lo || x > hi)
    throw py::value_error(what + " is out of range (" + std::to_string(lo) + ".." +
                          std::to_string(hi) + ")");
  return x;
}

uint64_t to_uint64(py::handle obj, const std::string& what) {
  PyObject* index = PyNumber_Index(obj.ptr());
  if (!index) {
    PyErr_Clear();
    throw py::type_error(what + " must be an integer, not " + type_name(obj));
  }
  unsigned long long x = PyLong_AsUnsignedLongLong(index);
  Py_DECREF(index);
  if (x == static_cast<unsigned long long>(-1) && PyErr_Occurred()) {
    PyErr_Clear();
    throw py::value_error(what + " must be an integer in 0..2**64-1");
  }
  return x;
}

// obj as a sequence of exactly n items (any iterable: tuples, lists, NumPy arrays).
std::vector<py::object> items(py::handle obj, size_t n, const std::string& what, const char* of) {
  if (PyUnicode_Check(obj.ptr()) || is_mapping(obj) || !py::isinstance<py::iterable>(obj))
    throw py::type_error(what + " must be " + std::to_string(n) + " " + of + ", not " +
                         type_name(obj));
  std::vector<py::object> out;
  for (py::handle item : obj) out.push_back(py::reinterpret_borrow<py::object>(item));
  if (out.size() != n)
    throw py::value_error(what + " must be " + std::to_string(n) + " " + of + ", not " +
                          std::to_string(out.size()));
  return out;
}

// dict -> struct: the fields named in obj replace the defaults already in the struct.
class Reader {
 public:
  Reader(py::handle obj, std::string what) : what_(std::move(what)) {
    if (obj.is_none()) return;
    if (!is_mapping(obj))
      throw py::type_error(what_ + " must be a mapping of field names to values, not " +
                           type_name(obj));
    dict_ = py::dict(py::reinterpret_borrow<py::object>(obj));
    for (auto item : dict_) {
      if (!PyUnicode_Check(item.first.ptr()))
        throw py::type_error(what_ + ": field names must be strings");
    }
  }

  void operator()(const char* key, float& v) {
    if (py::handle x = take(key)) v = float(to_double(x, field(key)));
  }
  void operator()(const char* key, int& v) {
    if (py::handle x = take(key))
      v = int(to_integer(x, field(key), std::numeric_limits<int>::min(),
                         std::numeric_limits<int>::max()));
  }
  void operator()(const char* key, uint64_t& v) {
    if (py::handle x = take(key)) v = to_uint64(x, field(key));
  }
  template <size_t N>
  void operator()(const char* key, float (&v)[N]) {
    if (py::handle x = take(key)) {
      std::vector<py::object> xs = items(x, N, field(key), "numbers");
      for (size_t i = 0; i < N; ++i)
        v[i] = float(to_double(xs[i], field(key) + "[" + std::to_string(i) + "]"));
    }
  }
  template <size_t N>
  void operator()(const char* key, double (&v)[N]) {  // kept in double (a pose's origin)
    if (py::handle x = take(key)) {
      std::vector<py::object> xs = items(x, N, field(key), "numbers");
      for (size_t i = 0; i < N; ++i) v[i] = to_double(xs[i], field(key) + "[" + std::to_string(i) + "]");
    }
  }
  template <size_t N>
  void operator()(const char* key, int (&v)[N]) {
    if (py::handle x = take(key)) {
      std::vector<py::object> xs = items(x, N, field(key), "integers");
      for (size_t i = 0; i < N; ++i)
        v[i] = int(to_integer(xs[i], field(key) + "[" + std::to_string(i) + "]",
                              std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
    }
  }
  template <typename E, size_t N>
  void choice(const char* key, E& v, const Name<E> (&names)[N]) {
    if (py::handle x = take(key)) v = choose(x, field(key), names);
  }
  // A string field; None gives the null pointer (the library's default).
  void string(const char* key, const char*& v, std::string& storage) {
    py::handle x = take(key);
    if (!x) return;
    if (x.is_none()) {
      v = nullptr;
      return;
    }
    if (!PyUnicode_Check(x.ptr()))
      throw py::type_error(field(key) + " must be a string, not " + type_name(x));
    storage = x.cast<std::string>();
    v = storage.c_str();
  }
  // Up to N sub-structs given as mappings (None or a missing entry keeps the default).
  template <typename S, size_t N, typename Fields>
  void nested(const char* key, S (&v)[N], Fields fields) {
    py::handle x = take(key);
    if (!x || x.is_none()) return;
    if (PyUnicode_Check(x.ptr()) || is_mapping(x) || !py::isinstance<py::iterable>(x))
      throw py::type_error(field(key) + " must be a sequence of at most " + std::to_string(N) +
                           " mappings, not " + type_name(x));
    size_t i = 0;
    for (py::handle item : x) {
      if (i == N)
        throw py::value_error(field(key) + " has more than " + std::to_string(N) + " entries");
      Reader sub(item, field(key) + "[" + std::to_string(i) + "]");
      fields(sub, v[i]);
      sub.finish();
      ++i;
    }
  }
  // The value under key (marked as used), or a null handle.
  py::handle take(const char* key) {
    PyObject* value = PyDict_GetItemString(dict_.ptr(), key);  // borrowed: the dict keeps it
    if (value) used_.insert(key);
    return value;
  }
  std::string field(const char* key) const { return what_ + "." + key; }
  const std::string& what() const { return what_; }

  // A key that no field took is a mistake (a typo would otherwise be ignored).
  void finish() {
    for (auto item : dict_) {
      std::string key = item.first.cast<std::string>();
      if (!used_.count(key)) throw py::type_error(what_ + " has no field '" + key + "'");
    }
  }

  template <typename E, size_t N>
  static E choose(py::handle x, const std::string& what, const Name<E> (&names)[N]) {
    std::string all;
    for (const Name<E>& n : names) all += std::string(all.empty() ? "" : ", ") + "'" + n.name + "'";
    if (!PyUnicode_Check(x.ptr()))
      throw py::type_error(what + " must be one of " + all + ", not " + type_name(x));
    std::string s = x.cast<std::string>();
    for (const Name<E>& n : names)
      if (s == n.name) return n.value;
    throw py::value_error(what + " must be one of " + all + ", not '" + s + "'");
  }

 private:
  py::dict dict_;  // empty when None was given
  std::string what_;
  std::set<std::string> used_;
};

// The shortest decimal that reads back as the same float: 1.8f becomes 1.8, not
// 1.7999999523162842, so defaults print as they are written in the library.
double shortest(float x) {
  char text[32];
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, double(x));
    if (std::strtof(text, nullptr) == x) break;
  }
  return std::strtod(text, nullptr);
}

py::object value(float x) { return py::float_(shortest(x)); }
template <typename T>
py::object value(T x) {
  return py::cast(x);
}

// struct -> dict.
class Writer {
 public:
  template <typename T>
  std::enable_if_t<std::is_arithmetic_v<T>> operator()(const char* key, T& v) {
    out[key] = value(v);
  }
  template <typename T, size_t N>
  void operator()(const char* key, T (&v)[N]) {
    py::tuple t(N);
    for (size_t i = 0; i < N; ++i) t[i] = value(v[i]);
    out[key] = t;
  }
  template <typename E, size_t N>
  void choice(const char* key, E& v, const Name<E> (&names)[N]) {
    for (const Name<E>& n : names)
      if (n.value == v) out[key] = n.name;
  }
  void string(const char* key, const char*& v, std::string&) {
    out[key] = v ? py::object(py::str(v)) : py::object(py::none());
  }
  template <typename S, size_t N, typename Fields>
  void nested(const char* key, S (&v)[N], Fields fields) {
    py::list list;
    for (size_t i = 0; i < N; ++i) {
      Writer sub;
      fields(sub, v[i]);
      list.append(sub.out);
    }
    out[key] = list;
  }
  py::dict out;
};

template <typename V>
void grid_fields(V& v, boreas_grid_def& g) {
  v("origin", g.origin);
  v("cell_size", g.cell_size);
  v("resolution", g.resolution);
  v("diffusion", g.diffusion);
  v("decay_rate", g.decay_rate);
  v("response_time", g.response_time);
  v("edge_fade", g.edge_fade);
  v("follow_focus", g.follow_focus);
  v.choice("wind_sampling", g.wind_sampling, kWindSamplings);
}

template <typename V>
void wave_fields(V& v, boreas_wave& w) {
  v("direction", w.direction);
  v("amplitude", w.amplitude);
  v("wavelength", w.wavelength);
  v("speed", w.speed);
  v("sharpness", w.sharpness);
}

template <typename V>
void gust_fields(V& v, boreas_gust_def& g) {
  v("direction", g.direction);
  v("strength", g.strength);
  v("delay", g.delay);
  v("rise", g.rise);
  v("hold", g.hold);
  v("fall", g.fall);
  v("center", g.center);
  v("radius", g.radius);
}

template <typename V>
void primitive_fields(V& v, boreas_flow_primitive_def& p) {
  v.choice("type", p.type, kFlowTypes);
  v("position", p.position);
  v("direction", p.direction);
  v("strength", p.strength);
  v("radius", p.radius);
  v("lifetime", p.lifetime);
}

template <typename V>
void tree_level_fields(V& v, boreas_tree_level_def& l) {
  v("stiffness", l.stiffness);
  v("damping_ratio", l.damping_ratio);
  v("frequency_scale", l.frequency_scale);
  v("rings", l.rings);
  v("sides", l.sides);
}

template <typename V>
void tree_fields(V& v, boreas_tree_def& t, std::string& species) {
  v.string("species", t.species, species);
  v("position", t.position);
  v("rotation", t.rotation);
  v("scale", t.scale);
  v("seed", t.seed);
  v.choice("mode", t.mode, kTreeModes);
  v.choice("response", t.response, kTreeResponses);
  v.choice("load", t.load, kTreeLoads);
  v.choice("leaf_outline", t.leaf_outline, kLeafOutlines);
  v("bend_exponent", t.bend_exponent);
  v.nested("levels", t.levels,
           [](auto& sub, boreas_tree_level_def& l) { tree_level_fields(sub, l); });
  v("lod_distances", t.lod_distances);
}

// The meadow's fields but its species list and images (read apart).
template <typename V>
void meadow_fields(V& v, boreas_meadow_def& m) {
  v("center", m.center);
  v("size", m.size);
  v("density", m.density);
  v("seed", m.seed);
  v("terrain_relief", m.terrain_relief);
  v("seed_points", m.seed_points);
  v("shape_angles", m.shape_angles);
  v("shape_norms", m.shape_norms);
  v("lod_distances", m.lod_distances);
}

template <typename V>
void collider_fields(V& v, boreas_collider_def& c) {
  v.choice("shape", c.shape, kColliderShapes);
  v("center", c.pose.position);
  v("orientation", c.pose.orientation);
  v("origin", c.pose.origin);
  v("radius", c.radius);
  v("half_height", c.half_height);
  v("half_extents", c.half_extents);
  v("velocity", c.velocity);
  v("angular_velocity", c.angular_velocity);
}

template <typename V>
void emitter_fields(V& v, boreas_emitter_def& e) {
  v("center", e.center);
  v("origin", e.origin);
  v("area_radius", e.area_radius);
  v("event_radius", e.event_radius);
  v("impulse", e.impulse);
  v("rate", e.rate);
  v("lifetime", e.lifetime);
  v("seed", e.seed);
}

template <typename V>
void mesh_level_fields(V& v, boreas_mesh_level_def& l) {
  v("bend", l.bend);
  v("sway", l.sway);
  v("frequency", l.frequency);
  v("response_time", l.response_time);
}

template <typename V>
void mesh_tree_fields(V& v, MeshTreeDef& m) {
  boreas_mesh_tree_def& d = m.def;
  v.string("model", d.model, m.model);
  v.string("trunk_part", d.trunk_part, m.trunk_part);
  v.string("leaves_part", d.leaves_part, m.leaves_part);
  v("position", d.position);
  v("yaw", d.yaw);
  v("scale", d.scale);
  v("seed", d.seed);
  v("noise_beta", d.noise_beta);
  v("bend_exponent", d.bend_exponent);
  v.nested("levels", d.levels,
           [](auto& sub, boreas_mesh_level_def& l) { mesh_level_fields(sub, l); });
  v("leaf_flutter", d.leaf_flutter);
  v("leaf_turn", d.leaf_turn);
  v("flutter_wavelength", d.flutter_wavelength);
  v("cache", d.cache);
}

template <typename V>
void pose_fields(V& v, boreas_pose& p) {
  v("position", p.position);
  v("orientation", p.orientation);
  v("origin", p.origin);
}

// The LiDAR's fields but its vertical angles and pose (read apart).
template <typename V>
void lidar_fields(V& v, boreas_lidar_def& d) {
  v("channels", d.channels);
  v("vertical_fov", d.vertical_fov);
  v("points_per_turn", d.points_per_turn);
  v("rotation_rate", d.rotation_rate);
  v("min_range", d.min_range);
  v("max_range", d.max_range);
  v("range_noise", d.range_noise);
  v("dropout", d.dropout);
  v("reflectivity", d.reflectivity);
  v("seed", d.seed);
}

// The depth camera's fields but its pose.
template <typename V>
void depth_camera_fields(V& v, boreas_depth_camera_def& c) {
  v("width", c.width);
  v("height", c.height);
  v("fx", c.fx);
  v("fy", c.fy);
  v("cx", c.cx);
  v("cy", c.cy);
  v("max_depth", c.max_depth);
}

// The BlobTree's fields but its cuts and scars (read apart).
template <typename V>
void blobtree_fields(V& v, boreas_blobtree_def& b) {
  v("resolution", b.resolution);
  v("cubic", b.cubic);
  v("max_level", b.max_level);
  v("min_radius", b.min_radius);
  v.choice("junctions", b.junctions, kJunctions);
  v("offsets", b.offsets);
  v("ridge", b.ridge);
  v("ridge_width", b.ridge_width);
  v("bend", b.bend);
}

// A record given as a mapping or as a tuple in the fields' order (a cut: (branch, at)).
template <typename S, typename Fields>
S record_from(py::handle obj, S value, const std::string& what,
              std::initializer_list<const char*> order, Fields fields) {
  if (is_mapping(obj)) {
    Reader r(obj, what);
    fields(r, value);
    r.finish();
    return value;
  }
  std::vector<py::object> xs;
  if (!PyUnicode_Check(obj.ptr()) && py::isinstance<py::iterable>(obj))
    for (py::handle item : obj) xs.push_back(py::reinterpret_borrow<py::object>(item));
  if (xs.empty() || xs.size() > order.size())
    throw py::type_error(what + " must be a mapping or a tuple of up to " +
                         std::to_string(order.size()) + " values");
  py::dict d;
  size_t i = 0;
  for (const char* key : order) {
    if (i == xs.size()) break;
    d[key] = xs[i++];
  }
  Reader r(d, what);
  fields(r, value);
  r.finish();
  return value;
}

std::vector<py::object> list_of(py::handle obj, const std::string& what) {
  std::vector<py::object> out;
  if (obj.is_none()) return out;
  if (PyUnicode_Check(obj.ptr()) || is_mapping(obj) || !py::isinstance<py::iterable>(obj))
    throw py::type_error(what + " must be a sequence, not " + type_name(obj));
  for (py::handle item : obj) out.push_back(py::reinterpret_borrow<py::object>(item));
  return out;
}

}  // namespace

boreas_grid_def grid_from(py::handle obj) {
  boreas_grid_def g = boreas_default_grid_def();
  Reader r(obj, "grid");
  grid_fields(r, g);
  r.finish();
  return g;
}

boreas_wave wave_from(py::handle obj, const std::string& what) {
  boreas_wave w = boreas_default_wave();
  Reader r(obj, what);
  wave_fields(r, w);
  r.finish();
  return w;
}

std::vector<boreas_wave> waves_from(py::handle seq) {
  std::vector<boreas_wave> waves;
  std::vector<py::object> list = list_of(seq, "waves");
  for (size_t i = 0; i < list.size(); ++i)
    waves.push_back(wave_from(list[i], "waves[" + std::to_string(i) + "]"));
  return waves;
}

boreas_gust_def gust_from(py::handle obj) {
  boreas_gust_def g = boreas_default_gust_def();
  Reader r(obj, "gust");
  gust_fields(r, g);
  r.finish();
  return g;
}

boreas_flow_primitive_def primitive_from(py::handle obj) {
  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  Reader r(obj, "primitive");
  primitive_fields(r, p);
  r.finish();
  return p;
}

void tree_from(py::handle obj, TreeDef* out, const std::string& what) {
  out->def = boreas_default_tree_def();
  Reader r(obj, what);
  tree_fields(r, out->def, out->species);
  r.finish();
}

namespace {

// A (H, W) or (H, W, C) array of numbers as a boreas_image over `held` (float32, C order;
// converted once when it is not). Row 0 lies on the meadow's -z side, column 0 on its -x
// side. The library checks the values and sizes and names the field.
boreas_image image_from(py::handle obj, const std::string& field,
                        py::array_t<float, py::array::c_style | py::array::forcecast>* held) {
  py::array source = py::array::ensure(obj);
  if (!source) throw py::type_error(field + " must be an array of numbers, (H, W) or (H, W, C)");
  if (source.ndim() != 2 && source.ndim() != 3)
    throw py::value_error(field + " must have shape (H, W) or (H, W, C), not " +
                          std::to_string(source.ndim()) + " dimensions");
  if (source.dtype().kind() != 'f' && source.dtype().kind() != 'i' && source.dtype().kind() != 'u')
    throw py::type_error(field + " must hold numbers (got dtype " +
                         std::string(py::str(source.dtype())) + ")");
  *held = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(source);
  if (!*held) throw py::type_error(field + " cannot be read as float32");
  const auto too_big = [&](py::ssize_t n) {
    if (n > py::ssize_t(INT32_MAX)) throw py::value_error(field + " is too large");
    return int(n);
  };
  boreas_image image{};
  image.height = too_big(held->shape(0));
  image.width = too_big(held->shape(1));
  image.channels = held->ndim() == 3 ? too_big(held->shape(2)) : 1;
  image.pixels = held->data();
  return image;
}

}  // namespace

void meadow_from(py::handle obj, MeadowDef* out, const std::string& what) {
  out->def = boreas_default_meadow_def();
  Reader r(obj, what);
  meadow_fields(r, out->def);
  if (py::handle terrain = r.take("terrain"); terrain && !terrain.is_none())
    out->def.terrain = image_from(terrain, r.field("terrain"), &out->terrain);
  if (py::handle nutrients = r.take("nutrients"); nutrients && !nutrients.is_none())
    out->def.nutrients = image_from(nutrients, r.field("nutrients"), &out->nutrients);
  // species: None (the default mix), names, (name, weight) pairs, or {name: weight}.
  if (py::handle species = r.take("species"); species && !species.is_none()) {
    std::string field = r.field("species");
    std::vector<std::pair<py::object, py::object>> entries;
    if (is_mapping(species)) {
      for (auto item : py::dict(py::reinterpret_borrow<py::object>(species)))
        entries.emplace_back(py::reinterpret_borrow<py::object>(item.first),
                             py::reinterpret_borrow<py::object>(item.second));
    } else {
      for (py::object& item : list_of(species, field)) {
        if (PyUnicode_Check(item.ptr())) {
          entries.emplace_back(item, py::float_(1.0));
        } else {
          std::vector<py::object> pair =
              items(item, 2, field + " entries", "values (name, weight)");
          entries.emplace_back(pair[0], pair[1]);
        }
      }
    }
    for (size_t i = 0; i < entries.size(); ++i) {
      std::string at = field + "[" + std::to_string(i) + "]";
      if (!PyUnicode_Check(entries[i].first.ptr()))
        throw py::type_error(at + ": the species name must be a string");
      out->names.push_back(entries[i].first.cast<std::string>());
      out->species.push_back({nullptr, float(to_double(entries[i].second, at + " weight"))});
    }
    for (size_t i = 0; i < out->species.size(); ++i)
      out->species[i].species = out->names[i].c_str();
    out->def.species = out->species.data();
    out->def.species_count = int(out->species.size());
  }
  r.finish();
}

boreas_collider_def collider_from(py::handle obj) {
  boreas_collider_def c = boreas_default_collider_def();
  Reader r(obj, "collider");
  collider_fields(r, c);
  r.finish();
  return c;
}

boreas_emitter_def emitter_from(py::handle obj) {
  boreas_emitter_def e = boreas_default_emitter_def();
  Reader r(obj, "emitter");
  emitter_fields(r, e);
  r.finish();
  return e;
}

void mesh_tree_from(py::handle obj, MeshTreeDef* out) {
  out->def = boreas_default_mesh_tree_def();
  Reader r(obj, "mesh_tree");
  mesh_tree_fields(r, *out);
  r.finish();
}

void blobtree_from(py::handle obj, BlobTreeDef* out) {
  out->def = boreas_default_blobtree_def();
  Reader r(obj, "blobtree");
  blobtree_fields(r, out->def);
  py::handle cuts = r.take("cuts");
  std::vector<py::object> list = cuts ? list_of(cuts, "blobtree.cuts") : std::vector<py::object>{};
  for (size_t i = 0; i < list.size(); ++i)
    out->cuts.push_back(record_from(list[i], boreas_blobtree_cut{0, 1.0f},
                                    "blobtree.cuts[" + std::to_string(i) + "]", {"branch", "at"},
                                    [](Reader& c, boreas_blobtree_cut& x) {
                                      c("branch", x.branch);
                                      c("at", x.at);
                                    }));
  py::handle scars = r.take("scars");
  list = scars ? list_of(scars, "blobtree.scars") : std::vector<py::object>{};
  for (size_t i = 0; i < list.size(); ++i)
    out->scars.push_back(record_from(
        list[i], boreas_blobtree_scar{0, 0.1f, 0.5f}, "blobtree.scars[" + std::to_string(i) + "]",
        {"branch", "stub", "depth"}, [](Reader& s, boreas_blobtree_scar& x) {
          s("branch", x.branch);
          s("stub", x.stub);
          s("depth", x.depth);
        }));
  out->def.cuts = out->cuts.empty() ? nullptr : out->cuts.data();
  out->def.cut_count = int(out->cuts.size());
  out->def.scars = out->scars.empty() ? nullptr : out->scars.data();
  out->def.scar_count = int(out->scars.size());
  r.finish();
}

boreas_pose pose_from(py::handle obj, const std::string& what) {
  boreas_pose p = boreas_default_pose();
  Reader r(obj, what);
  pose_fields(r, p);
  r.finish();
  return p;
}

// A sub-mapping field of a Reader: its pose.
boreas_pose pose_of(Reader& r, const boreas_pose& base) {
  py::handle x = r.take("pose");
  return x && !x.is_none() ? pose_from(x, r.field("pose")) : base;
}

void lidar_from(py::handle obj, const boreas_lidar_def& base, LidarDef* out) {
  out->def = base;
  Reader r(obj, "lidar");
  lidar_fields(r, out->def);
  out->def.pose = pose_of(r, base.pose);
  if (py::handle angles = r.take("vertical_angles")) {
    out->def.vertical_angles = nullptr;
    if (!angles.is_none()) {
      const std::vector<py::object> list = list_of(angles, "lidar.vertical_angles");
      for (size_t i = 0; i < list.size(); ++i)
        out->vertical_angles.push_back(
            float(to_double(list[i], "lidar.vertical_angles[" + std::to_string(i) + "]")));
      if (!r.take("channels")) out->def.channels = int(list.size());
      if (size_t(out->def.channels) != list.size())
        throw py::value_error("lidar.channels (" + std::to_string(out->def.channels) +
                              ") must equal the length of lidar.vertical_angles (" +
                              std::to_string(list.size()) + ")");
      out->def.vertical_angles = out->vertical_angles.data();
    }
  } else if (base.vertical_angles) {
    // A preset's angles are kept, unless channels or the field of view are given: then
    // the channels spread over it (a preset's vertical_fov is its angles' span).
    const bool respread = PyDict_Check(obj.ptr()) && (PyDict_GetItemString(obj.ptr(), "channels") ||
                                                      PyDict_GetItemString(obj.ptr(), "vertical_fov"));
    if (respread) {
      out->def.vertical_angles = nullptr;
    } else {
      out->vertical_angles.assign(base.vertical_angles, base.vertical_angles + base.channels);
      out->def.vertical_angles = out->vertical_angles.data();
    }
  }
  r.finish();
}

boreas_depth_camera_def depth_camera_from(py::handle obj) {
  boreas_depth_camera_def c = boreas_default_depth_camera_def();
  Reader r(obj, "camera");
  depth_camera_fields(r, c);
  c.pose = pose_of(r, c.pose);
  r.finish();
  return c;
}

boreas_mesh_part mesh_part_from(py::handle obj) { return Reader::choose(obj, "part", kMeshParts); }

void vec3_from(py::handle obj, float out[3], const std::string& what) {
  std::vector<py::object> xs = items(obj, 3, what, "numbers");
  for (int i = 0; i < 3; ++i)
    out[i] = float(to_double(xs[i], what + "[" + std::to_string(i) + "]"));
}

py::dict to_dict(const boreas_grid_def& g) {
  Writer w;
  boreas_grid_def copy = g;
  grid_fields(w, copy);
  return w.out;
}

py::dict to_dict(const boreas_wave& wave) {
  Writer w;
  boreas_wave copy = wave;
  wave_fields(w, copy);
  return w.out;
}

namespace {

// A fixed-size name from the C API as str: the library cuts long names at a byte count,
// which can split a UTF-8 character, so such bytes are replaced.
py::str name_text(const char* name) {
  auto text = py::reinterpret_steal<py::object>(
      PyUnicode_DecodeUTF8(name, py::ssize_t(std::strlen(name)), "replace"));
  if (!text) throw py::error_already_set();
  return py::str(text);
}

}  // namespace

py::dict to_dict(const boreas_device_info& d) {
  py::dict out;
  out["name"] = name_text(d.device_name);
  out["platform"] = name_text(d.platform_name);
  out["version"] = name_text(d.device_version);
  out["driver_version"] = name_text(d.driver_version);
  out["is_gpu"] = d.is_gpu != 0;
  out["compute_units"] = d.compute_units;
  out["global_memory"] = d.global_memory;
  out["has_gl_sharing"] = d.has_gl_sharing != 0;
  out["has_fp64"] = d.has_fp64 != 0;
  out["uses_fast_math"] = d.uses_fast_math != 0;
  out["platform_index"] = d.platform_index;
  out["device_index"] = d.device_index;
  return out;
}

py::dict to_dict(const boreas_step_stats& s) {
  Writer w;
  boreas_step_stats c = s;
  w("wind", c.wind);
  w("trees", c.trees);
  w("underbrush", c.underbrush);
  w("total", c.total);
  w("trees_by_lod", c.trees_by_lod);
  w("branches_stepped", c.branches_stepped);
  w("branches_carried", c.branches_carried);
  w("branches_broken", c.branches_broken);
  w("components_by_rate", c.components_by_rate);
  return w.out;
}

py::dict to_dict(const boreas_memory_info& m) {
  py::dict out;
  out["device_bytes"] = m.device_bytes;
  out["device_limit"] = m.device_limit;
  out["kernel_variants"] = m.kernel_variants;
  return out;
}

py::dict to_dict(const boreas_mesh_tree_info& i) {
  Writer w;
  boreas_mesh_tree_info c = i;
  w("trunk_vertices", c.trunk_vertices);
  w("trunk_triangles", c.trunk_triangles);
  w("leaf_vertices", c.leaf_vertices);
  w("leaf_triangles", c.leaf_triangles);
  w("branches", c.branches);
  w("leaves", c.leaves);
  w("levels", c.levels);
  w("orphans", c.orphans);
  w.out["from_cache"] = c.from_cache != 0;
  return w.out;
}

py::dict to_dict(const boreas_blobtree_info& i) {
  Writer w;
  boreas_blobtree_info c = i;
  w("vertices", c.vertices);
  w("triangles", c.triangles);
  w("primitives", c.primitives);
  w("branches", c.branches);
  w("grid", c.grid);
  w("cell", c.cell);
  w("min_radius", c.min_radius);
  w("bounds_min", c.bounds_min);
  w("bounds_max", c.bounds_max);
  return w.out;
}

py::dict to_dict(const boreas_lidar_info& i) {
  py::dict d;
  d["sweep_start"] = i.sweep_start;
  d["next_sweep_start"] = i.next_sweep_start;
  d["sweeps"] = i.sweeps;
  d["firings"] = i.firings;
  d["last_step_rays"] = i.last_step_rays;
  return d;
}

namespace {
py::dict pose_dict(boreas_pose p) {
  Writer w;
  pose_fields(w, p);
  return w.out;
}
}  // namespace

py::dict to_dict(const boreas_pose& p) { return pose_dict(p); }

py::dict to_dict(const boreas_collider_contact& c) {
  py::dict d;
  d["force"] = py::make_tuple(c.force[0], c.force[1], c.force[2]);
  d["torque"] = py::make_tuple(c.torque[0], c.torque[1], c.torque[2]);
  d["contacts"] = c.contacts;
  return d;
}

py::dict to_dict(const boreas_lidar_def& def) {
  Writer w;
  boreas_lidar_def d = def;
  lidar_fields(w, d);
  if (d.vertical_angles) {
    py::list angles;
    for (int i = 0; i < d.channels; ++i) angles.append(d.vertical_angles[i]);
    w.out["vertical_angles"] = angles;
  } else {
    w.out["vertical_angles"] = py::none();
  }
  w.out["pose"] = pose_dict(d.pose);
  return w.out;
}

py::dict all_defaults() {
  py::dict out;
  out["grid"] = to_dict(boreas_default_grid_def());
  out["wave"] = to_dict(boreas_default_wave());
  {
    Writer w;
    boreas_gust_def g = boreas_default_gust_def();
    gust_fields(w, g);
    out["gust"] = w.out;
  }
  {
    Writer w;
    boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
    primitive_fields(w, p);
    out["primitive"] = w.out;
  }
  {
    Writer w;
    boreas_tree_def t = boreas_default_tree_def();
    std::string unused;
    tree_fields(w, t, unused);
    out["tree"] = w.out;
  }
  {
    Writer w;
    boreas_meadow_def m = boreas_default_meadow_def();
    meadow_fields(w, m);
    w.out["species"] = py::none();
    out["meadow"] = w.out;
  }
  {
    Writer w;
    boreas_collider_def c = boreas_default_collider_def();
    collider_fields(w, c);
    out["collider"] = w.out;
  }
  {
    Writer w;
    boreas_emitter_def e = boreas_default_emitter_def();
    emitter_fields(w, e);
    out["emitter"] = w.out;
  }
  {
    Writer w;
    MeshTreeDef m;
    m.def = boreas_default_mesh_tree_def();
    mesh_tree_fields(w, m);
    out["mesh_tree"] = w.out;
  }
  {
    Writer w;
    boreas_blobtree_def b = boreas_default_blobtree_def();
    blobtree_fields(w, b);
    w.out["cuts"] = py::list();
    w.out["scars"] = py::list();
    out["blobtree"] = w.out;
  }
  out["lidar"] = to_dict(boreas_default_lidar_def());
  {
    Writer w;
    boreas_depth_camera_def c = boreas_default_depth_camera_def();
    depth_camera_fields(w, c);
    w.out["pose"] = pose_dict(c.pose);
    out["depth_camera"] = w.out;
  }
  out["pose"] = pose_dict(boreas_default_pose());
  return out;
}

}  // namespace boreas_py
