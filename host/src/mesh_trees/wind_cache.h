// boreas: the preprocessing cache of an imported tree — its mesh and wind data in one binary
// glTF that boreas reads back instead of recomputing, and that engines can read as well.
#pragma once

#include <cstdint>
#include <string>

#include "mesh_trees/model_import.h"
#include "mesh_trees/tree_model.h"
#include "mesh_trees/wind_weights.h"

namespace boreas::impl {

// The file (.glb, glTF 2.0), all floats float32, all data in model space (m, Y up):
//
// mesh and node "trunk", one triangle primitive, material "bark":
//   POSITION (VEC3, with min/max), NORMAL (VEC3), TEXCOORD_0 (VEC2), indices (UNSIGNED_INT)
//   _BOREAS_WEIGHTS  VEC4    w0..w3 of the vertex
//   _BOREAS_BRANCH   SCALAR  the branch that animates the vertex (an index into "branches")
// mesh and node "leaves" (absent when the tree has no leaves), material "leaf" (double-sided):
//   POSITION, NORMAL, TEXCOORD_0, indices as above
//   _BOREAS_WEIGHTS   VEC4    the weights of the vertex's leaf
//   _BOREAS_BRANCH    SCALAR  the leaf's branch
//   _BOREAS_LEAF      SCALAR  the leaf's index (its vertices share every _BOREAS_* value)
//   _BOREAS_PETIOLE   VEC3    the leaf's petiole, m
//   _BOREAS_LEAF_AXIS VEC4    the leaf's unit axis (xyz) and length (w, m)
// Indices stored in SCALAR attributes are FLOAT: glTF allows UNSIGNED_INT only for indices
// (never in vertex attributes) and UNSIGNED_SHORT stops at 65535, while a float holds every
// integer up to 2^24 exactly.
//
// The trunk mesh's extras hold {"boreas_wind": {...}} with
//   "version"  2 (kWindCacheVersion)
//   "key"      16 lower-case hex digits: preprocess_key of the model it was made from
//   "levels", "orphans"  MeshTreeData::levels and ::orphans
//   "longest"  4 numbers, m: the longest branch of levels 0..3
//   "branches" one row of kWindCacheColumns numbers per branch, the stem first:
//      0 parent (-1 for the stem)    1 level
//      2-5 animated_by[0..3]         6-7 phase u, v (tiles)
//      8-10 axis xyz                 11-13 up xyz          14-16 right xyz
//      17-19 center xyz (m)          20-22 base xyz (m)    23-25 tip xyz (m)
//      26 length (m)                 27 radius (m)         28 orphan (0 or 1)
constexpr int kWindCacheVersion = 2;  // bump when the file or compute_mesh_tree's results change
constexpr int kWindCacheColumns = 29;

struct PreprocessedTree {
  MeshModel model;
  MeshTreeData data;
  uint64_t key = 0;  // preprocess_tree: the preprocess_key of the file it came from
};

// FNV-1a 64 over the model file's bytes, the two selectors, the seed and kWindCacheVersion:
// a cache whose key differs was made from something else. Throws Error (IO) naming the path
// when the file cannot be read.
uint64_t preprocess_key(const std::string& model_path, const ModelPartSelection& selection,
                        uint64_t seed);
// The same for a file's bytes already read.
uint64_t preprocess_key_of(const std::string& bytes, const ModelPartSelection& selection,
                           uint64_t seed);

// Writes the tree as above (through a temporary file renamed into place, so that a reader
// never sees half a file). Throws Error: INVALID_ARGUMENT when the data does not fit the
// model (sizes) or holds NaN or infinite values; IO naming the path when it cannot write.
void write_preprocessed_glb(const std::string& path, const PreprocessedTree& tree, uint64_t key);

// Reads a file written by write_preprocessed_glb (binary or text glTF, by its content):
// true, with *out and *key (either may be null) filled, when a mesh carries "boreas_wind"
// extras; false when none does (an ordinary model). Node transforms are ignored: the data
// is in mesh space. Throws Error naming the path: IO when it cannot be read;
// INVALID_ARGUMENT when it is not glTF, or the boreas data is malformed (saying what: a
// missing or mistyped attribute, counts that differ from POSITION's, a wrong column count,
// version not 1, an index out of range, NaN, vertices of one leaf that disagree).
bool read_preprocessed_glb(const std::string& path, PreprocessedTree* out, uint64_t* key);
// The same for the file's bytes, already read; path names it in errors, and a buffer the
// file names is looked for beside it.
bool read_preprocessed_bytes(const std::string& path, const std::string& bytes,
                             PreprocessedTree* out, uint64_t* key);

// The whole preprocessing of a model, with the cache; the model file is read once. A
// preprocessed glb at `path` is read
// as is (*from_cache = true; `selection` and `seed` do not apply). Otherwise, with
// use_cache, `path + ".boreas.glb"` is used when its key matches; else the model is loaded
// (load_tree_model), computed (compute_mesh_tree) and, with use_cache, the cache written.
// Cache trouble is not an error: a corrupt cache is recomputed and rewritten, and a cache
// that cannot be written is skipped; *cache_note then says so in one line (it is empty
// otherwise; a stale cache replaced is routine and not noted). from_cache and cache_note
// may be null. Throws what load_tree_model and compute_mesh_tree throw.
PreprocessedTree preprocess_tree(const std::string& path, const ModelPartSelection& selection,
                                 uint64_t seed, bool use_cache, bool* from_cache,
                                 std::string* cache_note);

}  // namespace boreas::impl
