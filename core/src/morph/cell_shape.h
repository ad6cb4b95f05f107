/* Shape measures of the sweep's cells: linear tetrahedra and 6-node
 * prisms, as finite-element codes and mesh checkers (Verdict, Gmsh) define
 * them, so the figures in a report can be compared with theirs. */
#ifndef CM_CELL_SHAPE_H
#define CM_CELL_SHAPE_H

typedef struct cm_cell_shape {
    double min_dihedral_deg, max_dihedral_deg;
    /* Smallest over the corners of det[e1 e2 e3] / (|e1| |e2| |e3|) for the
     * corner's three edges, scaled to 1 for the regular tetrahedron (by
     * sqrt 2) and the right prism with an equilateral triangle (by
     * 2 / sqrt 3); <= 0 when the cell is degenerate or inverted. */
    double scaled_jacobian;
    /* Tetrahedron: longest edge / (2 sqrt(6) inradius), 1 when regular.
     * Prism: longest edge / shortest edge. */
    double aspect_ratio;
} cm_cell_shape;

/* Corners p[0..3], positive when p[3] lies above p[0] p[1] p[2]
 * (counter-clockwise seen from p[3]). The dihedral angle at an edge is the
 * angle between the other two corners seen along the edge. */
void cm_tet_shape(const double p[4][3], cm_cell_shape *shape);

/* Corners in Gmsh's wedge order: bottom a b c counter-clockwise seen from
 * above, top a' b' c'. Dihedral angles are those of the three planes
 * through each corner and two of its edges (exact for planar faces). */
void cm_prism_shape(const double p[6][3], cm_cell_shape *shape);

/* Smallest dihedral angle of a tetrahedron in degrees, -1 when its signed
 * volume is not positive in floating point (the cheap part of
 * cm_tet_shape, for choosing among splits). */
double cm_tet_min_dihedral(const double p[4][3]);

#endif
