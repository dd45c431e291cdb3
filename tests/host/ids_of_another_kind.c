/* boreas tests: compiled, not run. With BOREAS_WRONG_KIND a tree id goes where a meadow
 * id is expected, and the C compiler must refuse it (ids carry their kind in their type);
 * without it the same file, with the right kind, must compile, so the refusal is the id's
 * and not some other fault of the file. Also checks that boreas.h is strict C99. */
#include <boreas/boreas.h>

int remove_first(boreas_world world) {
  boreas_tree_id tree = BOREAS_NULL_ID;
  boreas_meadow_id meadow = BOREAS_NULL_ID;
  if (!boreas_tree_id_is_null(tree) || !boreas_meadow_id_is_null(meadow)) return -1;
#ifdef BOREAS_WRONG_KIND
  return (int)boreas_world_remove_meadow(world, tree);
#else
  return (int)boreas_world_remove_meadow(world, meadow);
#endif
}
