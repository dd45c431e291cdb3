// boreas: a tree model written as OBJ (positions and faces; objects "trunk" and "leaves"),
// as obj_reader.cpp reads it back with the default part names: for tests and benchmarks
// that give the importer a mesh built in memory. Floats at 9 significant digits, so every
// position reads back to the same bits.
#pragma once

#include <ostream>

#include "mesh_trees/tree_model.h"

namespace boreas::impl {

void write_obj(std::ostream& out, const MeshModel& model);

}  // namespace boreas::impl
