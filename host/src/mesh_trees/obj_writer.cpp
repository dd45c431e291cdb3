// boreas: a tree model as OBJ (obj_writer.h).
#include "mesh_trees/obj_writer.h"

#include <iomanip>

namespace boreas::impl {

void write_obj(std::ostream& out, const MeshModel& model) {
  const auto precision = out.precision(9);
  size_t first = 1;  // OBJ counts vertices from 1, across objects
  for (const MeshPart* part : {&model.trunk, &model.leaves}) {
    out << "o " << (part == &model.trunk ? "trunk" : "leaves") << "\n";
    for (size_t v = 0; v < part->vertex_count(); ++v)
      out << "v " << part->positions[3 * v] << " " << part->positions[3 * v + 1] << " "
          << part->positions[3 * v + 2] << "\n";
    for (size_t t = 0; t < part->triangle_count(); ++t)
      out << "f " << first + part->indices[3 * t] << " " << first + part->indices[3 * t + 1]
          << " " << first + part->indices[3 * t + 2] << "\n";
    first += part->vertex_count();
  }
  out.precision(precision);
}

}  // namespace boreas::impl
