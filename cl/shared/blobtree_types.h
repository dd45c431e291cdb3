/* boreas: the buffer layout of BlobTree trees (Galbraith, MacMurchy and Wyvill 2004), shared
 * by the polygonizer's kernels and the host. Every table is planar (one plane of `stride`
 * values per quantity), as the other kernels' tables are, so PoCL vectorizes across
 * work-items (see wind_types.h).
 *
 * The field (cl/shared/blobtree_field.h) is a sum over junction groups of skeletal cone
 * primitives; see host/src/blobtree/blobtree_model.h for how a tree becomes primitives. */
#ifndef BOREAS_CL_SHARED_BLOBTREE_TYPES_H
#define BOREAS_CL_SHARED_BLOBTREE_TYPES_H

/* The surface is F = 1/2. Every primitive's fall-off is Wyvill's g(d) = (1 - d^2/R^2)^3
 * of the distance d to its skeleton, so a lone primitive's surface lies where
 * d = R sqrt(1 - (1/2)^(1/3)) = 0.4542 R; R is chosen so that this is the primitive's iso
 * distance. The slope |g'| there is 1.7168 / R. */
#define BOREAS_BT_ISO 0.5f
#define BOREAS_BT_ISO_FRACTION 0.45420201894740647f
#define BOREAS_BT_ISO_SLOPE 1.7167760537297625f

/* Float planes per primitive (stride = primitive count). A cone's skeleton runs from BASE
 * along AXIS for LENGTH: a solid cone of radius CONE at the base and 0 at the top (sec.
 * 3.1: r_cb = r_b - r_t), whose surface lies ISO = r_t further out. A bent primitive's
 * skeleton follows a circular arc of radius BEND_RHO in the plane of AXIS and BEND_DIR,
 * leaving the base turned towards BEND_DIR by the half angle (BEND_SIN, BEND_COS) and
 * landing on BASE + chord * AXIS; LENGTH is then the arc's length. */
#define BOREAS_BT_BASE 0        /* 3: m */
#define BOREAS_BT_AXIS 3        /* 3: unit, base -> top (the chord when bent) */
#define BOREAS_BT_LENGTH 6      /* m, > 0: the skeleton's length */
#define BOREAS_BT_CONE 7        /* m, >= 0: the skeleton cone's radius at the base */
#define BOREAS_BT_ISO_DIST 8    /* m, > 0: the surface's distance from the skeleton */
#define BOREAS_BT_INV_R2 9      /* 1/m^2: 1 / R^2, R the radius of influence */
#define BOREAS_BT_WEIGHT 10     /* +1, or -1 for a scar's negative field */
#define BOREAS_BT_PCM_WIDTH 11  /* m: w, the propagation region's width */
#define BOREAS_BT_PCM_PEAK 12   /* M, the largest expansion (at w/2) */
#define BOREAS_BT_SLOPE 13      /* 1/m: |grad g| on its own surface, BOREAS_BT_ISO_SLOPE / R */
#define BOREAS_BT_BEND_DIR 14   /* 3: unit, perpendicular to AXIS */
#define BOREAS_BT_BEND_RHO 17   /* m: the arc's radius, 0 for a straight primitive */
#define BOREAS_BT_BEND_SIN 18   /* sin and cos of half the arc's angle */
#define BOREAS_BT_BEND_COS 19
#define BOREAS_BT_U_DIR 20      /* 3: unit, perpendicular to AXIS: where u = 0 */
#define BOREAS_BT_V0 23         /* v at the base */
#define BOREAS_BT_V_SCALE 24    /* v per metre along the skeleton */
#define BOREAS_BT_FLOATS 25

/* Int planes per primitive. Members of one group are contiguous in the primitive order. */
#define BOREAS_BT_GROUP 0 /* the junction group */
#define BOREAS_BT_PCM 1   /* 1: the group's members combine by Precise Contact Modeling;
                             0: the primitive is summed on its own */
#define BOREAS_BT_INTS 2

/* Float planes per cut (stride = cut count): the cutter is the half-space on NORMAL's side
 * of POINT's plane, within RADIUS of POINT; its field ramps linearly from 0 to 1 over
 * RAMP across each of its faces, so the field min(F, 1 - cutter) is linear across the
 * cut and the face it leaves is flat. */
#define BOREAS_BT_CUT_POINT 0  /* 3: m */
#define BOREAS_BT_CUT_NORMAL 3 /* 3: unit, towards what is removed */
#define BOREAS_BT_CUT_RADIUS 6 /* m */
#define BOREAS_BT_CUT_RAMP 7   /* m, > 0 */
#define BOREAS_BT_CUT_FLOATS 8

/* The grid is split into bins of BOREAS_BT_BIN^3 points; each bin lists the primitives
 * whose reach touches it, ascending. The field kernel runs one bin per work-group. */
#define BOREAS_BT_BIN 8

/* Marching cubes: a cube's corner c sits at (c & 1, (c >> 1) & 1, (c >> 2) & 1); its
 * edges 0-3 run along x from corners 0, 2, 4, 6; 4-7 along y from 0, 1, 4, 5; 8-11 along
 * z from 0, 1, 2, 3. A case (bit c set: corner c inside, F > 1/2) has at most
 * BOREAS_BT_CASE_TRIANGLES triangles, three edges each, counter-clockwise seen from
 * outside; the table row holds 3 * that many entries, -1 after the last. */
#define BOREAS_BT_CASE_TRIANGLES 5
#define BOREAS_BT_CASE_ENTRIES (3 * BOREAS_BT_CASE_TRIANGLES)

/* Float planes of the attributes per output vertex (stride = vertex count); the positions
 * are emit's, which the host already holds. */
#define BOREAS_BT_VERTEX_NORMAL 0 /* 3: unit, outward: -grad F */
#define BOREAS_BT_VERTEX_UV 3     /* 2 */
#define BOREAS_BT_VERTEX_FLOATS 5

#endif
