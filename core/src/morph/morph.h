/* The morph handle, shared by morph.c and sweep.c. Not installed. */
#ifndef CM_MORPH_H
#define CM_MORPH_H

#include "api/result.h"
#include "base/error.h"

struct cm_morph {
    cm_error error;
    cm_morph_method method;
    const cm_result *result;
    size_t k, nv, nt; /* the result's geometries, vertices, triangles */

    /* CM_MORPH_CONVEX: the enclosed mesh and the convex-combination
     * system, one unknown per interior vertex. */
    cm_mesh full;
    unsigned char *boundary; /* full.nv flags */
    int32_t *unknown;        /* full.nv: row of an interior vertex, or -1 */
    int32_t nu;              /* unknowns */
    /* Neighbours of interior vertex row i: nbr[start[i] .. start[i+1]),
     * normalized mean value weights lambda[g][same range] per geometry;
     * entry[j] is the triplet slot of an interior neighbour, or -1. */
    size_t *start;
    int32_t *nbr, *entry;
    double **lambda;
    /* CM_MORPH_INTRINSIC: every triangle corner at an interior vertex
     * (slots of its two neighbours), its angle and the logarithms of its
     * two edge lengths per geometry; scratch weights per frame. */
    size_t ncorner;
    size_t *corner_slot;     /* 2 per corner */
    double **corner_shape;   /* k arrays of 3 per corner: angle, log|a|, log|b| */
    double *weights;         /* start[nu] */
    /* UMFPACK: the pattern of I - Lambda (fixed), its symbolic analysis. */
    int nz;                  /* triplets: diagonal first, then entries */
    int *ti, *tj, *map, *ap, *ai;
    double *tx, *ax;
    void *symbolic;
    double *rhs, *sol, *pos; /* 2 * nu, 2 * nu, 2 * full.nv */
    /* Geometry g is morphed about centre[2g .. 2g+1] (k entries of 2):
     * its bounding-box centre, or the origin where centring would fold a
     * triangle by rounding. */
    double *centre;
};

/* The section at local time s in [0, 1] between geometries g and g + 1
 * (s == 0, s == 1: the geometry itself, bit-identical); otherwise as
 * cm_morph_section. */
cm_status cm_morph_section_at(cm_morph *m, size_t g, double s, double *xy, size_t *inverted,
                              double *min_angle_deg);

#endif
