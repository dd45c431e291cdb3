// boreas tests: public calls made from C with any int where the API takes an enum, as a C
// caller may (C++ cannot even form such a value without undefined behaviour).
#pragma once

#include "boreas/boreas.h"

#ifdef __cplusplus
extern "C" {
#endif

const char* c_status_name(int status);
boreas_status c_add_tree_with(boreas_world world, int mode, int response, int load,
                              boreas_tree_id* out);
boreas_status c_add_primitive_of_type(boreas_world world, int type, boreas_primitive_id* out);
boreas_status c_mesh_tree_indices(boreas_world world, boreas_mesh_tree_id tree, int part,
                                  int* count);

#ifdef __cplusplus
}
#endif
