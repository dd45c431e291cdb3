/* boreas tests: public calls made from C with any int where the API takes an enum
 * (enums_from_c.h). */
#include "enums_from_c.h"

const char* c_status_name(int status) { return boreas_status_name((boreas_status)status); }

boreas_status c_add_tree_with(boreas_world world, int mode, int response, int load,
                              boreas_tree_id* out) {
  boreas_tree_def def = boreas_default_tree_def();
  def.mode = (boreas_tree_mode)mode;
  def.response = (boreas_tree_response)response;
  def.load = (boreas_tree_load)load;
  return boreas_world_add_tree(world, &def, out);
}

boreas_status c_add_primitive_of_type(boreas_world world, int type, boreas_primitive_id* out) {
  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  p.type = (boreas_flow_type)type;
  return boreas_wind_add_primitive(world, &p, out);
}

boreas_status c_mesh_tree_indices(boreas_world world, boreas_mesh_tree_id tree, int part,
                                  int* count) {
  return boreas_mesh_tree_get_indices(world, tree, (boreas_mesh_part)part, 0, 0, count);
}
