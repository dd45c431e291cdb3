/* boreas: the layouts of the one-call tree records (boreas_world_enqueue_tree_records,
 * boreas_cl.h), shared by its kernels (tree_record_offsets.cl with shared/tree_cull.h,
 * export_records.cl, tree_leaves.cl) and the host (trees/tree_batch_view.cpp).
 *
 * A call, per tree batch: tree_record_offsets.cl decides each tree's fate from the view
 * (culled, drawn with how many of its leaves, or an impostor: shared/tree_cull.h) into its
 * row of the batch's out table, turns the rows' counts into record offsets (one
 * work-group, prefix sums in slot order) and writes the impostor and range records and the
 * indirect commands; then the record kernels (one launch each over the batch's record tiles) write
 * the records of the rows that have an offset.
 * Compiles as OpenCL C and C++ (only 4-byte fields: one layout in both). */
#ifndef BOREAS_CL_SHARED_TREE_RECORDS_H
#define BOREAS_CL_SHARED_TREE_RECORDS_H

/* What the device knows of one tree slot for a view (host: TreeBatch's view table, kept
 * up to date as trees come and go; a free slot has live 0). */
typedef struct BoreasTreeView {
  float base[3];      /* m: the tree's base, the centre of its bounding sphere */
  float radius;       /* m: nothing of the tree (branch surface or leaf) reaches farther
                       * from its base, however it bends */
  float rest_tip[3];  /* m: its trunk's first piece's tip at rest, relative to its base (as
                       * the state is: shared/tree_origin.h) */
  float scale;
  float rotation;     /* rad about +y */
  float leaf_area;    /* m^2: its leaves' mean blade area, length x width at its scale */
  int live;           /* 1: a tree holds the slot */
  int template_index; /* boreas_tree_get_template */
  int root;           /* its root entry in the batch's state planes */
  int branches;       /* branch records (its branches, the root excluded) */
  int leaves;         /* its leaves at full detail */
  int leaf_stride;    /* the permutation that thins its leaves (tree_leaves.cl) */
  int leaf_inverse;   /* leaf_stride's inverse modulo leaves */
  int id_index;       /* its boreas_tree_id */
  int id_generation;
  int pad;
} BoreasTreeView;

/* The view of one call, as the kernels read it (the host's checked copy of
 * boreas_tree_view_def, planes normalized). */
typedef struct BoreasRecordView {
  float planes[24];          /* 6 x (nx, ny, nz, d), |n| = 1 or n = 0 (no plane) */
  float eye[3];              /* m */
  float footprint_per_m;     /* rad: a pixel's size per metre of distance; 0: no thinning */
  float resolved_area;       /* pixels: a leaf smaller than this is thinned */
  float min_keep;            /* the least share of a tree's leaves kept */
  float impostor_distance;   /* m: trees at least this far are impostors; 0: none */
  int branch_capacity;       /* records the caller's buffers hold */
  int leaf_capacity;
  int impostor_capacity;
  int range_capacity;
  int first_batch;           /* 1: counts start at 0; 0: after the batches before */
  int vertices[3];           /* the indirect commands' counts: branch, leaf, impostor */
  int pad;
} BoreasRecordView;

/* A slot's row of the out table (ints): what shared/tree_cull.h decided, then where its records
 * go (tree_record_offsets.cl). */
#define BOREAS_TREE_OUT_KIND 0         /* 0 culled (or free), 1 drawn, 2 impostor */
#define BOREAS_TREE_OUT_BRANCHES 1     /* branch records it writes */
#define BOREAS_TREE_OUT_KEPT 2         /* leaf records it writes (its kept leaves) */
#define BOREAS_TREE_OUT_FACTOR 3       /* float bits: each kept leaf's size factor */
#define BOREAS_TREE_OUT_BRANCH_FIRST 4 /* its first branch record; -1: none written */
#define BOREAS_TREE_OUT_LEAF_FIRST 5   /* its first leaf record; -1: none written */
#define BOREAS_TREE_OUT_LEAVES 6       /* its leaves at full detail */
#define BOREAS_TREE_OUT_INVERSE 7      /* BoreasTreeView.leaf_inverse */
#define BOREAS_TREE_OUT_INTS 8

#define BOREAS_TREE_KIND_CULLED 0
#define BOREAS_TREE_KIND_DRAWN 1
#define BOREAS_TREE_KIND_IMPOSTOR 2

/* The public layouts (boreas_cl.h names them for callers; the host checks they agree): */
/* Range record (int32): one per drawn tree. */
#define BOREAS_TREE_RANGE_ID_INDEX 0
#define BOREAS_TREE_RANGE_ID_GENERATION 1
#define BOREAS_TREE_RANGE_BRANCH_FIRST 2
#define BOREAS_TREE_RANGE_BRANCH_COUNT 3
#define BOREAS_TREE_RANGE_LEAF_FIRST 4
#define BOREAS_TREE_RANGE_LEAF_COUNT 5
#define BOREAS_TREE_RANGE_LEAVES 6
#define BOREAS_TREE_RANGE_LEAF_STRIDE 7
#define BOREAS_TREE_RANGE_WORDS 8
/* Impostor record (floats). */
#define BOREAS_TREE_IMPOSTOR_WORDS 12
/* Indirect buffer (uint32): commands for branches, leaves, impostors (count, instanceCount,
 * first, baseInstance), then the ranges written and three zeros, then the records each
 * kind needed (branches, leaves, impostors, ranges). */
#define BOREAS_TREE_INDIRECT_BRANCHES 0
#define BOREAS_TREE_INDIRECT_LEAVES 4
#define BOREAS_TREE_INDIRECT_IMPOSTORS 8
#define BOREAS_TREE_INDIRECT_RANGES 12
#define BOREAS_TREE_INDIRECT_NEEDED 16
#define BOREAS_TREE_INDIRECT_WORDS 20

/* Threads of tree_record_offsets.cl's one group, at most. */
#define BOREAS_TREE_OFFSETS_GROUP 256

#endif
