/* compatmesh: compatible triangulations of planar polygons.
 *
 * One call takes k >= 2 simple polygons of n vertices each, whose vertices
 * correspond by index, and returns one triangle list that is a valid
 * triangulation of every polygon (Surazhsky & Gotsman, "High Quality
 * Compatible Triangulations", Engineering with Computers 2004).
 *
 * Conventions
 * - Every symbol is prefixed cm_ / CM_. No global state: two result handles
 *   never share anything, so separate calls may run in separate threads.
 * - Fallible calls return a cm_status (CM_OK == 0) and leave a one-line
 *   message on the result handle. Nothing here exits, aborts or longjmps.
 * - Inputs are (pointer, count) of doubles and are only read during the call.
 * - Outputs are owned by the result handle and returned as const pointers,
 *   valid until cm_result_free. cm_result_free(NULL) is a no-op.
 *
 * Output order contract
 * - With the index correspondence (the default when the counts match): the
 *   n input vertices come first, in input order, with coordinates
 *   bit-identical to the input; the Steiner vertices follow (indices n..);
 *   the boundary edges of the triangulation are exactly the input
 *   polygon's edges (no Steiner vertex on the boundary).
 * - With arclength or auto, or a largest boundary edge: the boundary
 *   vertices come first in boundary order (every input vertex among them,
 *   bit-identical and in input order; the others exactly on input edges,
 *   named by their edge and parameter in cm_result_boundary_source), then
 *   the interior Steiner vertices.
 * - Every geometry shares the one triangle list; every triangle is strictly
 *   counter-clockwise in every geometry (checked with exact predicates).
 * - When the input polygons are all clockwise they are processed as if
 *   reversed (stats.reversed_input = 1); indices still refer to the input
 *   order, and triangles are still counter-clockwise.
 */
#ifndef COMPATMESH_H
#define COMPATMESH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Marks the functions the shared library exports; everything else in it
 * is hidden. */
#if defined(__GNUC__)
#define CM_API __attribute__((visibility("default")))
#else
#define CM_API
#endif

#define CM_VERSION_MAJOR 0
#define CM_VERSION_MINOR 1
#define CM_VERSION_PATCH 0

typedef enum cm_status {
    CM_OK = 0,
    CM_ERR_ARGUMENT,             /* NULL pointer, k < 2, bad option value */
    CM_ERR_TOO_FEW_VERTICES,     /* n < 3 */
    CM_ERR_COUNT_MISMATCH,       /* polygons with different vertex counts */
    CM_ERR_NOT_FINITE,           /* NaN or infinite coordinate */
    CM_ERR_REPEATED_VERTEX,      /* two vertices of one polygon coincide */
    CM_ERR_SELF_INTERSECTION,    /* edges cross or touch */
    CM_ERR_ZERO_AREA,            /* signed area is exactly zero */
    CM_ERR_ORIENTATION_MISMATCH, /* clockwise and counter-clockwise mixed */
    CM_ERR_NO_MEMORY,
    CM_ERR_CANCELLED,            /* the progress callback asked to stop */
    CM_ERR_INTERNAL,             /* the construction failed its own exact check */
    /* No position in doubles was found for some Steiner vertex: the input's
     * vertices lie so close together, for their magnitude, that the
     * doubles between them are too few (a polygon far from the origin
     * relative to its size). Some such inputs provably have no valid
     * answer in doubles; translated nearer the origin they have room. */
    CM_ERR_PRECISION
} cm_status;

/* A short constant name for a status, e.g. "self-intersection". */
CM_API const char *cm_status_string(cm_status status);

/* How the first compatible triangulation is built. */
typedef enum cm_method {
    /* Aronov-Seidel-Souvaine: triangulate each polygon, map every
     * triangulation onto one convex polygon, overlay, map back. Always
     * succeeds; O(n^2) Steiner vertices in the worst case. */
    CM_METHOD_OVERLAY = 0,
    /* The default. Surazhsky-Gotsman section 2: cut along diagonals common
     * to all polygons and, where none is left, along minimum-link paths
     * between the vertex pair with the smallest largest link distance,
     * recursively. A Steiner-free compatible triangulation is found
     * whenever one exists (exact dynamic program on polygons and
     * sub-polygons up to 300 vertices, larger ones when they have few
     * common diagonals), the one maximising the smallest angle; a part
     * star-shaped in every polygon takes a single Steiner vertex. Few
     * Steiner vertices, poor angles: meant to be remeshed. Where the
     * recursion stalls, that part gets the overlay construction
     * (stats.fallback_count). */
    CM_METHOD_PARTITION = 1
} cm_method;

/* Progress: fraction in [0, 1], never going back within a call; stage a
 * short name, valid during the callback ("validate", "triangulate
 * polygons", "remesh", "check", "done", ...; auto runs its further
 * pairings under one bar as "pairing N: remesh" and the like). Return
 * non-zero to cancel; the call then returns CM_ERR_CANCELLED. */
typedef int (*cm_progress_fn)(void *user, double fraction, const char *stage);

/* Vertex smoothing in the remesher (paper section 3.1). Every variant moves
 * interior Steiner vertices only, each geometry on its own, and never makes
 * a triangle invalid. The remesher applies them in the "smart" manner: a
 * vertex moves only if the smallest angle of its triangles improves. */
typedef enum cm_smoothing {
    CM_SMOOTH_LAPLACIAN = 0, /* to the average of the neighbours */
    CM_SMOOTH_ANGLE,         /* angle-based (Zhou and Shimada) */
    CM_SMOOTH_WEIGHTED,      /* weighted angle-based, weights 1/alpha^2 (eq. 2) */
    CM_SMOOTH_COMBINED       /* weighted angle-based; Laplacian where it fails */
} cm_smoothing;

/* How the remesher improves the first compatible triangulation. */
typedef enum cm_remesher {
    /* Algorithm 1: flips, smoothing and splits, each kept where the
     * smallest angle around it rose, then forced moves out of local
     * optima. The default. */
    CM_REMESHER_GREEDY = 0,
    /* Map-aware: the Steiner vertices of every geometry first move to
     * lower the conformal distortion of the maps between the geometries;
     * vertices are inserted where a triangle is poor in the metric halfway
     * between them (at the same barycentric coordinates in every geometry,
     * so the maps keep), then Algorithm 1 finishes. */
    CM_REMESHER_MAP
} cm_remesher;

/* Which vertices correspond. */
typedef enum cm_correspondence {
    /* Vertex i of every polygon corresponds to vertex i; the counts must
     * be equal and the orientations agree. The default. */
    CM_CORRESPOND_INDEX = 0,
    /* Normalised arc length between pins (or from the first vertex of
     * every polygon): every polygon keeps all of its vertices, bit-
     * identical, and gets the other polygons' vertices as points on its
     * edges, so the counts may differ; clockwise polygons are reversed to
     * agree. The result's boundary is that common refinement, counter-
     * clockwise from the first pin (cm_result_boundary_source says where
     * each boundary vertex comes from). When remeshing, further points may
     * join it on the input edges (the remesher's boundary splits, at the
     * middle of a piece's parameter in every polygon). */
    CM_CORRESPOND_ARCLENGTH,
    /* Chosen where nothing is pinned, with the output of ARCLENGTH (every
     * polygon keeps its vertices and gets the others' on its edges; the
     * boundary starts at a vertex of every polygon where there is one).
     * Polygons without holes: the conformal correspondence, each polygon
     * mapped onto the disk by its harmonic measure, the disks balanced
     * and turned to agree, the crowding of thin parts tempered (stretch
     * to the power 1/4), the others' vertices placed along each edge by
     * that parameter, or the similarity choice below where that allows
     * the higher certified ceiling. Polygons with one hole: both loops at
     * once through the annulus (CM_CHOICE_ANNULUS), the outer loops'
     * pairing too where that ends short of the remesher's aim; with more
     * holes, the outer loops as polygons without holes and each hole from
     * the start the outer loops' similarity chooses. With pins: ARCLENGTH
     * between them. With pin_corners_deg: arc length from the start of
     * every polygon (against polygon 0's first vertex) whose arc-length
     * points are closest to a similar image of polygon 0's (least squares
     * over rotation, scale and translation). */
    CM_CORRESPOND_AUTO,
    /* That similarity choice for every input (AUTO's for all polygons
     * before the conformal one): better where the conformal map crowds
     * beyond what tempering saves, such as a spiral against a disk
     * (bench/CORRESPONDENCE.md). */
    CM_CORRESPOND_SIMILARITY
} cm_correspondence;

typedef struct cm_options {
    cm_method method;
    cm_progress_fn progress; /* may be NULL */
    void *progress_user;

    /* Remeshing (paper section 4, Algorithm 1): edge flips, smoothing,
     * area equalisation and edge splits, applied to every geometry at once
     * so the triangulations stay compatible. It first removes the
     * construction's surplus Steiner vertices (edge collapses valid in
     * every geometry) and at the end those the result does not need
     * (collapses that keep every angle at or above the target). Every step
     * keeps every geometry valid; a split is kept only if the smallest
     * angle around it did not drop. Boundary vertices never move; boundary
     * edges are split only with CM_CORRESPOND_ARCLENGTH and _AUTO, whose
     * boundaries take points on the input edges anyway (the point at the
     * middle of the piece's parameter on its input edge in every polygon,
     * with holes on its own loop's, reported by
     * cm_result_boundary_source). */
    int remesh;             /* 1 (default): remesh; 0: return the construction */
    /* Target smallest angle in degrees, in (0, 60); default 25. A triangle
     * at input corner i aims at min(target, c_i / 2), c_i the corner angle
     * (a corner split in two cannot promise more), and one on a boundary
     * edge at no more than the best isosceles triangle on that edge fitting
     * inside the polygon allows (the edge is never split with
     * CM_CORRESPOND_INDEX).
     * Refinement stops when every triangle of every geometry reaches its
     * aim, the budget is spent, or the smallest angle stops rising. */
    double min_angle_deg;
    /* Most Steiner vertices the refinement may add (edge splits). -1
     * (default): automatic, 2 n + 100, and as many again for each restart
     * (restarts below; the points its split adds counted in them); 0: no
     * refinement, only flips, smoothing and Steiner vertex removal. A
     * number set here is shared with the restarts: a restart's split and
     * refinement add no more than the result's Steiner vertices leave of
     * it. */
    long max_steiner;
    /* Edges split per refinement round (pairwise non-adjacent, best
     * eq. (5) scores first), >= 0; 0 (default): automatic, about 1 % of
     * the triangles, at least 1. */
    int k_split;
    /* Area equalisation (eq. 4) every this many refinement rounds, >= 0;
     * 0: never. Default 0: on the benchmark pairs it did not pay for
     * itself (the sweep is kept only if no angle drops). */
    int area_every;
    cm_smoothing smoothing; /* default CM_SMOOTH_COMBINED */
    /* Cap on refinement rounds, >= 0; 0 (default): no cap beyond the
     * other stopping rules. */
    int max_iterations;
    /* Restarts of the remesher, >= 0, where its result ends below 0.85 of
     * its aim: the tenth of the triangles whose maps between the polygons
     * are most distorted is split and the remesher runs again from there;
     * the result is kept only when its smallest angle is 2 % higher. Default 1
     * (bench/REMESH.md, "Restarts": on the hard bench pairs the smallest
     * angle up by some 7 %, for about twice the time and vertices); 0:
     * off. */
    int restarts;

    cm_correspondence correspondence; /* default CM_CORRESPOND_INDEX */
    /* Pins of CM_CORRESPOND_ARCLENGTH: num_pins k-tuples, pins[j * k + g]
     * the vertex of polygon g (its input numbering) that pin j ties to the
     * others; in the same order along every polygon. NULL and 0 (default):
     * the first vertex of every polygon. */
    const size_t *pins;
    size_t num_pins;
    /* Pins at corners instead (arclength and auto only, no pins given):
     * > 0 pins every vertex whose corner angle deviates from 180 degrees
     * by more than this many degrees, in order. With m the fewest corners
     * any polygon has, each keeps its m most prominent ones (the largest
     * deviations); polygon g's are matched to polygon 0's in order with the
     * cyclic shift that puts them closest in normalised arc length (from
     * vertex 0 with arclength, from the chosen starts with auto). A polygon
     * without such a corner is CM_ERR_ARGUMENT. 0 (default): off. */
    double pin_corners_deg;
    /* Element size along the boundary: > 0 splits the boundary edges
     * compatibly (the same number of points on corresponding edges, evenly
     * by the correspondence's parameter, each on its polygon's input edge)
     * so that no boundary edge is longer than this in any polygon. Every
     * polygon keeps its input vertices; cm_result_boundary_source says
     * where each added point lies. Also with CM_CORRESPOND_INDEX (which
     * otherwise adds interior Steiner vertices only). 0 (default): off. */
    double max_edge;

    /* The ceiling (cm_stats.ceiling_deg): 1 (default): compute the
     * certified caps on the smallest angle any compatible triangulation of
     * the input can have, report them, and let the remesher aim at no more
     * than the ceiling; 0: skip it (a few milliseconds at n = 160). */
    int ceiling;

    cm_remesher remesher; /* default CM_REMESHER_GREEDY */

    /* Time limit: > 0 caps the CPU seconds of the call (of its thread,
     * from the call's start) the remesher may run into. Once they are
     * spent it stops at its next safe point (between refinement rounds,
     * forced-move rounds, polish iterations and moves; before a restart,
     * a map-aware rescue or another of auto's pairings) and the call
     * returns the result reached, valid and checked as always, with
     * cm_stats.time_limit_reached set. Validation, construction, ceiling
     * and check always run whole, and a stage runs on to its next safe
     * point, so a call may take a little longer. The result then depends
     * on the machine's speed. 0 (default): no limit. */
    double time_limit;
} cm_options;

/* Fills *options with the defaults. Always call it first, then change the
 * fields you need: new fields get sensible defaults in later versions. */
CM_API void cm_options_init(cm_options *options);

/* Which correspondence a result was made in (cm_stats.correspondence_choice):
 * what CM_CORRESPOND_AUTO and _SIMILARITY kept, and what the others are. */
typedef enum cm_correspondence_choice {
    /* Vertex i corresponds to vertex i (CM_CORRESPOND_INDEX, also with
     * max_edge; results of cm_result_from_meshes). */
    CM_CHOICE_INDEX = 0,
    /* Normalised arc length from every polygon's first vertex or between
     * pins: CM_CORRESPOND_ARCLENGTH, and AUTO or SIMILARITY with pins (arc
     * length between the pins). */
    CM_CHOICE_ARCLENGTH,
    /* AUTO: the conformal correspondence (the higher ceiling; where the
     * ceilings tie, the higher correspondence bound). */
    CM_CHOICE_CONFORMAL,
    /* AUTO or SIMILARITY: arc length from the starts whose points fit a
     * similar image of polygon 0's best (for AUTO, the higher ceiling, or
     * the conformal map could not be had). */
    CM_CHOICE_SIMILARITY,
    /* AUTO or SIMILARITY: the polygons are affine images of one another up
     * to their first vertex, so every vertex is pinned to its image (no
     * distortion of the correspondence). */
    CM_CHOICE_AFFINE,
    /* Arc length between corner pins: pin_corners_deg, or AUTO's last
     * resort on polygons without holes where every other pairing stays
     * far below the remesher's aim (the corners turning by more than 90
     * degrees pinned, as pin_corners_deg = 90 would). */
    CM_CHOICE_CORNERS,
    /* AUTO on polygons with one hole, its first pairing for them: both
     * loops paired at once through the conformal maps onto round annuli
     * (the angle around the annulus, tempered as the conformal
     * correspondence's; of the turns that fit alike, the least turn of the
     * plane). Where it ends short of the remesher's aim the outer loops'
     * pairing runs too, the better kept. */
    CM_CHOICE_ANNULUS
} cm_correspondence_choice;

/* Its name as the CLI's report.json and the Python module give it:
 * "index", "arclength", "conformal", "similarity", "affine", "corners" or
 * "annulus" ("unknown" for a value outside the enum). */
CM_API const char *cm_correspondence_choice_name(cm_correspondence_choice choice);

typedef struct cm_stats {
    size_t n;                /* input vertices per polygon */
    size_t k;                /* number of polygons (geometries) */
    size_t vertices;         /* n + steiner */
    size_t steiner;          /* interior Steiner vertices */
    size_t triangles;        /* = n + 2 * steiner - 2 */
    int reversed_input;      /* 1 if the input was clockwise */
    size_t fallback_count;   /* sub-problems where the partition stalled and
                                the overlay construction took over */
    double seconds_validate; /* input validation */
    double seconds_build;    /* building the compatible triangulation */
    double seconds_check;    /* exact validation of the result */
    size_t steiner_before_remesh; /* Steiner vertices of the construction */
    double seconds_remesh;   /* remeshing (0 when options.remesh is 0) */
    size_t remesh_iterations; /* refinement rounds of Algorithm 1 */
    /* The smallest angle the remesher aimed at anywhere, in degrees: the
     * target lowered where an input corner (c/2) or a short boundary edge
     * beside a close opposite side allows less; 0 when not remeshed. */
    double remesh_aim_deg;

    /* The ceiling: no compatible triangulation of these polygons (in this
     * correspondence), whatever its Steiner vertices, can have a smallest
     * angle above ceiling_deg = min(corner_fan_cap_deg,
     * correspondence_bound_deg). Certified: rounding and discretisation
     * only ever make it higher than the truth, never lower. 60 when
     * nothing binds; all 0 when options.ceiling is 0. The remesher aims at
     * min(options.min_angle_deg, ceiling_deg). For polygons with holes the
     * corner fan alone (over every loop): the correspondence bound's moduli
     * are those of a simply connected polygon, so it is 60 there. */
    double ceiling_deg;
    /* At boundary vertex i the same m triangles split the corner in every
     * polygon, each angle in [alpha, 180 - 2 alpha]: alpha <= min over i of
     * the largest over m of min(min_g theta_i / m, (180 - max_g theta_i /
     * m) / 2), theta_i the corner angles in degrees. */
    double corner_fan_cap_deg;
    /* A compatible triangulation with all angles >= alpha is a
     * K(alpha)-quasiconformal map between the polygons (K(alpha): the
     * largest dilatation of an affine map between two triangles with all
     * angles >= alpha), so it cannot change the conformal modulus of any
     * four marked boundary vertices by more than K(alpha): the largest
     * alpha allowed by the modulus ratio
     * modulus_distortion, certified by finite elements (lower bound over
     * upper bound) on a quadruple found by a fast search. */
    double correspondence_bound_deg;
    double modulus_distortion;   /* that certified ratio K >= 1 */
    long distortion_quad[4];     /* its four boundary vertices, -1 when K == 1 */
    /* CM_CORRESPOND_AUTO without pins: the correspondence bound of arc
     * length from the first vertex of every polygon, before the
     * correspondence was chosen (what the choice bought); 0 otherwise. */
    double correspondence_bound_before_deg;
    double seconds_ceiling;      /* computing the ceiling (both when auto) */
    size_t holes;            /* hole loops per polygon (cm_triangulate_loops) */
    size_t bridges;          /* paths that cut the holes open: two per hole, or
                                one per hole when the construction that always
                                succeeds took over (fallback_count 1; the
                                overlay method takes it from the start) */
    /* The correspondence the result was made in. For polygons with holes,
     * the outer loop's; every hole then takes the same, except after
     * CM_CHOICE_AFFINE and CM_CHOICE_CONFORMAL, where the holes take
     * CM_CHOICE_SIMILARITY (their starts fitted jointly with the outer
     * loop's). */
    cm_correspondence_choice correspondence_choice;
    /* CM_CORRESPOND_AUTO and _SIMILARITY with two or more holes: how many
     * holes of the polygons after the first pair with polygon 0's hole at
     * another place in their input's list than their own (matched by
     * position, cm_triangulate_loops); 0 where hole j pairs with hole j. */
    size_t holes_moved;
    /* The pairings built (the correspondences auto tries in turn, each
     * counted where it is built again to restart the one kept; 1 in the
     * other modes) and how many of them were remeshed: auto builds a
     * rescue's pairing and sets it aside unremeshed where its corner-fan
     * cap is no higher than the best result so far. */
    size_t pairings_built;
    size_t pairings_remeshed;
    /* 1 where cm_options.time_limit stopped the remesher early. */
    int time_limit_reached;
} cm_stats;

/* Quality of one geometry of the result. */
typedef struct cm_quality {
    double min_angle_deg;
    double max_angle_deg;
    double pct_below_10deg; /* share of triangles, in percent, whose  */
    double pct_below_15deg; /* smallest angle is below 10, 15 and 20 */
    double pct_below_20deg; /* degrees */
} cm_quality;

typedef struct cm_result cm_result;

/* Compatibly triangulates k polygons of n vertices each.
 *   xy:      k * n * 2 doubles, polygon-major: xy[(g * n + i) * 2 + {0,1}]
 *            is vertex i of polygon g. Polygons are closed implicitly.
 *   options: NULL for the defaults.
 *   result:  receives a new handle, also on failure (then it carries only
 *            the status, the message and the error location); NULL only
 *            when even the handle could not be allocated (CM_ERR_NO_MEMORY).
 * Returns CM_OK only if the result passed the exact validity check. */
CM_API cm_status cm_triangulate(const double *xy, size_t k, size_t n,
                         const cm_options *options, cm_result **result);

/* The same with one array per polygon: polygons[g] holds 2 * counts[g]
 * doubles. Different counts are reported as CM_ERR_COUNT_MISMATCH. */
CM_API cm_status cm_triangulate_polygons(const double *const *polygons, const size_t *counts,
                                  size_t k, const cm_options *options,
                                  cm_result **result);

/* One polygon with holes: an outer loop and num_loops - 1 hole loops,
 * stored one after another (no repeated closing vertex). */
typedef struct cm_loops {
    const double *xy;         /* 2 * (sum of loop_sizes) doubles */
    const size_t *loop_sizes; /* num_loops vertex counts, the outer loop first */
    size_t num_loops;         /* 1 + the number of holes, >= 1 */
} cm_loops;

/* Compatibly triangulates k polygons with holes: every polygon has the
 * same number of loops; loop l of every polygon corresponds to loop l.
 * With CM_CORRESPOND_INDEX (loops of the same sizes, each running the same
 * way in every polygon) vertex i of a loop corresponds to vertex i; with
 * CM_CORRESPOND_ARCLENGTH or _AUTO every loop is paired as a polygon
 * without holes would be (loops of any sizes and directions;
 * pin_corners_deg and max_edge per loop; explicit pins are refused; auto
 * pairs the outer loops as polygons without holes, the conformal
 * correspondence of the filled outer loops or the similarity choice (the
 * one that takes the holes onto holes where only one does), pairs
 * the holes by position where that is one-to-one (hole j of a polygon g > 0
 * in the output is then the hole of g nearest to polygon 0's hole j
 * carried through the outer loops' correspondence, stats.holes_moved), and
 * starts every hole at the vertex whose points lie nearest to polygon 0's
 * hole carried radially through the outer loops' correspondence, by
 * their least-squares similarity where that is not defined), and cm_result_boundary_source says where each
 * boundary vertex lies. The holes must lie strictly inside the outer loop,
 * outside each other, and no loop may touch another. Failures of validation name the
 * polygon, the loop and the vertex within the loop; the error location's
 * vertex is the index into the polygon's whole xy array.
 *
 * The holes are cut open by paths between loop vertices, each valid in
 * every polygon (two per hole, disjoint: straight chords, or bent through
 * Steiner vertices), into simple pieces that are triangulated as by
 * cm_triangulate and glued along the paths. Where no such paths are found
 * (or with CM_METHOD_OVERLAY) a construction that succeeds for every valid
 * input takes over: one bridge per hole, routed in each polygon through its
 * own triangulation, cuts the polygon open into one disc, the same in every
 * polygon, which the overlay triangulates compatibly (many more Steiner
 * vertices; stats.fallback_count 1, stats.bridges one per hole). Only
 * rounding can make it fail (CM_ERR_PRECISION).
 *
 * The result: the input vertices first, in input order (outer loop, then
 * each hole), bit-identical (with the arc-length correspondences: the
 * refined loops, outer first), then the Steiner vertices; its boundary edges
 * are exactly the loops' edges; V - E + F = 1 - holes. The half-edge
 * arrays chain each loop's boundary half-edges separately. Remeshing runs
 * as for cm_triangulate (with CM_CORRESPOND_INDEX the loops are never
 * touched; with the arc-length correspondences the remesher may add points
 * on the loops' input edges, each listed within its loop). Such a result is
 * morphed and swept like any other (the morph fills every hole with a
 * compatible triangulation of its own, which the sections leave out);
 * cm_check_geometry_loops and cm_result_from_meshes_loops check and rebuild
 * such a result from its geometries. With one loop per
 * polygon this is cm_triangulate_polygons. */
CM_API cm_status cm_triangulate_loops(const cm_loops *polygons, size_t k,
                                      const cm_options *options, cm_result **result);

/* The correspondence for a caller that was given none (the command line,
 * the Python module and the OpenMesh adapter take it):
 * CM_CORRESPOND_ARCLENGTH where `pinned` (pins or pin_corners_deg given),
 * else CM_CORRESPOND_AUTO where some loop's vertex count differs between
 * the polygons (index needs equal counts), else CM_CORRESPOND_INDEX.
 * Loops beyond the fewest any polygon has are not compared (the run names
 * a hole count that differs). */
CM_API cm_correspondence cm_correspondence_by_counts(const cm_loops *polygons, size_t k, int pinned);

CM_API void cm_result_free(cm_result *result);

CM_API cm_status cm_result_status(const cm_result *result);
/* One line, no trailing newline; "" on success. Never NULL. */
CM_API const char *cm_result_message(const cm_result *result);
/* Where validation failed: polygon and vertex index (0-based), -1 if the
 * failure has no location. For an intersection, vertex is the first
 * vertex of the first offending edge and other_vertex that of the second. */
CM_API void cm_result_error_location(const cm_result *result, long *polygon,
                              long *vertex, long *other_vertex);

/* Geometry. All of these return 0 / NULL on a failed result. */
CM_API size_t cm_result_num_geometries(const cm_result *result);
CM_API size_t cm_result_num_vertices(const cm_result *result); /* per geometry */
/* 2 * num_vertices doubles (x, y) of geometry g. */
CM_API const double *cm_result_vertices(const cm_result *result, size_t g);
CM_API size_t cm_result_num_triangles(const cm_result *result);
/* 3 * num_triangles vertex indices, counter-clockwise. */
CM_API const int32_t *cm_result_triangles(const cm_result *result);

/* Half-edge structure (the layout OpenMesh uses):
 * - half-edges come in pairs: h and h ^ 1 are opposite; edge e owns 2e, 2e+1;
 * - halfedge_to_vertex[h]: the vertex h points to;
 * - halfedge_face[h]: the triangle left of h, -1 on the boundary;
 * - halfedge_next[h]: the next half-edge around the same face (boundary
 *   half-edges chain around the outer boundary, clockwise);
 * - vertex_halfedge[v]: one outgoing half-edge; for boundary vertices the
 *   outgoing boundary half-edge;
 * - face_halfedge[f]: the half-edge from triangles[3f] to triangles[3f+1]. */
CM_API size_t cm_result_num_halfedges(const cm_result *result);
CM_API const int32_t *cm_result_halfedge_next(const cm_result *result);
CM_API const int32_t *cm_result_halfedge_to_vertex(const cm_result *result);
CM_API const int32_t *cm_result_halfedge_face(const cm_result *result);
CM_API const int32_t *cm_result_vertex_halfedge(const cm_result *result);
CM_API const int32_t *cm_result_face_halfedge(const cm_result *result);

CM_API const cm_stats *cm_result_stats(const cm_result *result);
/* Where boundary vertex i (< stats.n) of geometry g comes from: returns
 * the input vertex e of polygon g such that the vertex is the point at
 * parameter *t in [0, 1) of input edge e -> e + 1 (t == 0: input vertex e
 * itself, bit-identical). With CM_CORRESPOND_INDEX it is input vertex i.
 * For polygons with holes, e indexes the polygon's whole xy array and
 * e + 1 is the next vertex of e's loop.
 * -1 for a failed result or an index out of range. t may be NULL. */
CM_API long cm_result_boundary_source(const cm_result *result, size_t g, size_t i, double *t);
/* Returns CM_ERR_ARGUMENT if g is out of range or the result failed. */
CM_API cm_status cm_result_quality(const cm_result *result, size_t g, cm_quality *quality);
/* Quality of geometry g as the construction built it, before remeshing
 * (equal to cm_result_quality when options.remesh was 0). */
CM_API cm_status cm_result_quality_before(const cm_result *result, size_t g, cm_quality *quality);


/* Exact validity of one geometry whose coordinates changed after
 * cm_triangulate (rounded to float by a file format or a host program,
 * interpolated by a morph), keeping the result's triangle list.
 *   xy:         2 * num_vertices doubles; vertices 0..n-1 are the boundary
 *               polygon in order (the output order contract)
 *   triangles:  3 * num_triangles indices
 *   where, other: may be NULL; receive the location of the failure, -1 when
 *               there is none
 * Returns CM_OK when every triangle is strictly counter-clockwise and the
 * boundary is simple (then the triangles tile the polygon); otherwise
 * CM_ERR_ZERO_AREA (triangle *where is flat or clockwise),
 * CM_ERR_REPEATED_VERTEX or CM_ERR_SELF_INTERSECTION (boundary vertices or
 * edges *where and *other), CM_ERR_NOT_FINITE (vertex *where),
 * CM_ERR_ARGUMENT (bad pointers, n < 3, index out of range: triangle *where),
 * CM_ERR_NO_MEMORY. */
CM_API cm_status cm_check_geometry(const double *xy, size_t n, size_t num_vertices,
                            const int32_t *triangles, size_t num_triangles,
                            long *where, long *other);

/* Exact validity of a volume mesh: every tetrahedron (4 node indices, as
 * cm_sweep_tets gives them) has strictly positive volume (orient3d with
 * exact predicates). nodes: 3 * num_nodes doubles. Returns CM_OK, or
 * CM_ERR_ZERO_AREA (tetrahedron *where is flat or inverted),
 * CM_ERR_NOT_FINITE (node *where), CM_ERR_ARGUMENT (bad pointers, an index
 * out of range: tetrahedron *where). where may be NULL. */
CM_API cm_status cm_check_tetrahedra(const double *nodes, size_t num_nodes, const int32_t *tets, size_t num_tets,
                                     long *where);

/* The same for a geometry with holes (a result of cm_triangulate_loops):
 * vertices 0..n-1 are the loops one after another, loop l having
 * loop_sizes[l] >= 3 vertices (the outer loop first); every triangle must
 * be strictly counter-clockwise and the loops simple, none touching
 * another (boundary edge e runs from vertex e to the next of its loop). */
CM_API cm_status cm_check_geometry_loops(const double *xy, const size_t *loop_sizes, size_t num_loops,
                                         size_t num_vertices, const int32_t *triangles,
                                         size_t num_triangles, long *where, long *other);

/* A result from a compatible triangulation built elsewhere (another
 * program, a file), so that it can be morphed and swept. The input is
 * validated exactly, as cm_triangulate validates its own output, and the
 * result has the same half-edge arrays, stats and quality.
 *   xy:            k >= 2 arrays of 2 * num_vertices doubles; in every
 *                  geometry vertices 0..n-1 are the boundary polygon in
 *                  order (the output order contract), the rest interior
 *   triangles:     3 * num_triangles indices, one list for all geometries,
 *                  counter-clockwise in every geometry, or clockwise in
 *                  every geometry (then stored counter-clockwise, the
 *                  vertex numbering unchanged, stats.reversed_input set)
 *   result:        receives a new handle, also on failure (status and a
 *                  message naming the geometry, triangle or vertex).
 * Returns CM_ERR_ARGUMENT (NULL pointers, k < 2, n < 3, n > num_vertices,
 * an index out of range, a mesh that is not a manifold disk bounded by
 * vertices 0..n-1), CM_ERR_NOT_FINITE, CM_ERR_ZERO_AREA (a triangle flat
 * or wrongly oriented in some geometry), CM_ERR_REPEATED_VERTEX,
 * CM_ERR_SELF_INTERSECTION (boundary), CM_ERR_NO_MEMORY. */
CM_API cm_status cm_result_from_meshes(const double *const *xy, size_t k, size_t n,
                                size_t num_vertices, const int32_t *triangles,
                                size_t num_triangles, cm_result **result);

/* The same for polygons with holes: vertices 0..n-1 of every geometry are
 * the loops one after another (loop_sizes[l] vertices each, the outer loop
 * first; each loop in either direction, the same in every geometry), the
 * triangles a manifold disk with num_loops - 1 holes bounded by exactly
 * those loops. The result morphs and sweeps as one of cm_triangulate_loops
 * does (the morph fills the holes). num_loops == 1 is cm_result_from_meshes. */
CM_API cm_status cm_result_from_meshes_loops(const double *const *xy, size_t k, const size_t *loop_sizes,
                                             size_t num_loops, size_t num_vertices,
                                             const int32_t *triangles, size_t num_triangles,
                                             cm_result **result);

/* ---- Morphing and sweeping (paper sections 1 and 5) --------------------
 *
 * A morph carries the polygons of a result through valid intermediate
 * sections: the result's triangulation is surrounded by one convex
 * enclosure (the same corresponding vertices in every geometry) and the
 * annulus between polygon and enclosure is compatibly triangulated, so
 * every geometry is a valid triangulation with a common convex boundary.
 * Each interior vertex is a convex combination of its neighbours with
 * mean value weights; the weights are interpolated linearly in time and
 * the sparse linear system (UMFPACK) gives the vertex positions at time t
 * (Floater and Gotsman, "How to morph tilings injectively"). Every section
 * is checked with exact predicates. For k > 2 geometries the morph is
 * piecewise: geometry g at t = g / (k - 1). */

typedef enum cm_morph_method {
    CM_MORPH_CONVEX = 0, /* convex-combination morph: every section valid */
    CM_MORPH_LINEAR = 1, /* straight-line vertex paths, for comparison:
                            sections may invert (counted, not an error) */
    /* Convex combinations with intrinsic weights (after Surazhsky and
     * Gotsman, "Intrinsic morphing of compatible triangulations"): each
     * interior vertex's star is interpolated by its corner angles
     * (linearly) and edge lengths (geometrically), and the weights at time
     * t are the mean value coordinates of that star. Rotation-aware: a
     * turning star keeps its shape instead of shrinking. Every section
     * valid, as for CM_MORPH_CONVEX; on the test fixtures the smallest
     * angles of the sections are mostly higher. */
    CM_MORPH_INTRINSIC = 2
} cm_morph_method;

/* "convex", "linear" or "intrinsic" (reports' names); "unknown" else. */
CM_API const char *cm_morph_method_name(cm_morph_method method);

typedef struct cm_morph_options {
    cm_morph_method method;  /* default CM_MORPH_CONVEX */
    cm_progress_fn progress; /* may be NULL */
    void *progress_user;
} cm_morph_options;

CM_API void cm_morph_options_init(cm_morph_options *options);

typedef struct cm_morph cm_morph;

/* Builds the morph through the k geometries of a successful result. The
 * enclosure and its annulus triangulation are internal; sections expose
 * the result's own vertices and triangles only.
 *   result:  a successful result; must outlive the morph.
 *   options: NULL for the defaults.
 *   morph:   receives a new handle, also on failure (then it carries the
 *            message, cm_morph_message); NULL only when even the handle
 *            could not be allocated. Always cm_morph_free it.
 * Returns CM_ERR_ARGUMENT (NULL or failed result, unknown method),
 * CM_ERR_CANCELLED, CM_ERR_NO_MEMORY, or CM_ERR_INTERNAL when no enclosure
 * could be built (no bridge from the polygon to the enclosure valid in
 * every geometry) or a mean value weight is not positive in doubles. The
 * linear method builds nothing and always succeeds on a valid result. */
CM_API cm_status cm_morph_create(const cm_result *result, const cm_morph_options *options,
                          cm_morph **morph);
CM_API void cm_morph_free(cm_morph *morph);
/* One line, no trailing newline; "" when nothing failed. Never NULL. */
CM_API const char *cm_morph_message(const cm_morph *morph);

/* The section at time t in [0, 1].
 *   xy:            receives cm_result_num_vertices(result) * 2 doubles, in
 *                  the result's vertex order (its triangles are
 *                  cm_result_triangles). At t = g / (k - 1) (to within
 *                  a few units of rounding) every vertex is bit-identical
 *                  to geometry g.
 *   inverted:      may be NULL; receives the number of triangles that are
 *                  not strictly counter-clockwise (exact predicates). For
 *                  the convex methods, valid at every t in exact
 *                  arithmetic, a non-zero count is rounding in doubles
 *                  (CM_ERR_PRECISION); for CM_MORPH_LINEAR it is reported
 *                  and the call returns CM_OK.
 *   min_angle_deg: may be NULL; receives the section's smallest angle. */
CM_API cm_status cm_morph_section(cm_morph *morph, double t, double *xy, size_t *inverted,
                           double *min_angle_deg);

/* The most sections per segment cm_sweep_options.sections gives. */
#define CM_SWEEP_MAX_SECTIONS 10000

typedef struct cm_sweep_options {
    /* Sections per segment between consecutive geometries, both ends
     * included: 2 to CM_SWEEP_MAX_SECTIONS, default 11; or 0: layers about
     * as tall as the median edge of the triangulation (over every input
     * geometry) in the tallest segment, so that the prisms are about as
     * tall as they are wide. */
    size_t sections;
    /* Total height, inputs evenly spaced; > 0, or 0 (the default): the
     * largest diagonal of the geometries' bounding boxes, so that prisms
     * are about as tall as the sections are wide whatever their units. */
    double height;
    /* Optional: one z per input geometry, strictly increasing; overrides
     * height. Only read during cm_sweep_create. */
    const double *heights;
    int tets;               /* 1: also split every prism into 3 tetrahedra */
    /* Most sections the validity refinement may insert; default 1000. */
    size_t max_refine;
    /* The walls of the boundary groups (cm_sweep_boundary_faces): 0 (the
     * default) gives one wall per loop; a positive angle in degrees splits
     * each loop's wall at its corners, the boundary vertices where some
     * polygon's boundary turns by more than it, as the faces of a swept
     * profile (a rectangle's four sides); < 180. */
    double wall_corner_deg;
    /* 1: a ruled sweep, as a CAD loft: the sections on straight lines
     * between consecutive inputs (every vertex moving straight, the walls
     * ruled surfaces), used when every prism stays valid along them
     * (checked exactly), else the morph's sections (cm_sweep_morph_method
     * says which: CM_MORPH_LINEAR for the ruled sweep). 0 (the default):
     * the morph's sections. */
    int ruled;
    /* Optional, a loft between sections in any planes: 9 doubles per input
     * geometry, the origin of its plane and two unit vectors u, v at right
     * angles in it (its point (x, y) is origin + x u + y v). The sweep is
     * built as above with heights the distances between consecutive
     * sections' centres (the mean of each geometry's boundary vertices,
     * placed in its plane), cumulated (cm_sweep_section_z then gives that
     * parameter;
     * heights and height must not be given), and every node is then placed
     * between the planes of the geometries around it: at fraction s of its
     * segment, (1 - s) times its point in the lower plane plus s times its
     * point in the upper one. Every cell is checked positive in space,
     * exactly (a tetrahedron, or a prism at each of its six corners); where
     * one is not (planes too close for their turn, planes crossing inside
     * the polygons, or a geometry given the other way round), the sweep
     * fails and says which. Nodes, volume and quality are those in space;
     * the flatness fields stay those of the parameter. Only read during
     * cm_sweep_create. */
    const double *frames;
    cm_progress_fn progress; /* may be NULL */
    void *progress_user;
} cm_sweep_options;

CM_API void cm_sweep_options_init(cm_sweep_options *options);

typedef struct cm_sweep cm_sweep;

/* Stacks sections of the morph at increasing heights into 6-node prisms.
 * A prism is valid everywhere, not only at its corners, when its triangle
 * stays counter-clockwise along the straight blend between its bottom and
 * top sections; this is checked exactly, and where it fails an
 * intermediate section is inserted (bisecting morph time) up to
 * max_refine times; with options.tets, also where a tetrahedron of the
 * split is not positive. When a convex-combination morph needs more than
 * max_refine sections, the sweep is built again from an intrinsic morph of
 * the same result (cm_sweep_morph_method says which was used). Every
 * section must be valid (a linear morph that inverts fails). Same handle
 * and message conventions as the morph; a failed sweep holds no mesh. */
CM_API cm_status cm_sweep_create(cm_morph *morph, const cm_sweep_options *options, cm_sweep **sweep);
CM_API void cm_sweep_free(cm_sweep *sweep);
CM_API const char *cm_sweep_message(const cm_sweep *sweep);
CM_API size_t cm_sweep_num_sections(const cm_sweep *sweep);
CM_API const double *cm_sweep_section_z(const cm_sweep *sweep);  /* one z per section */
/* Nodes: sections * nv, nv = cm_result_num_vertices; node s * nv + v is
 * vertex v of section s; 3 doubles (x, y, z) each. */
CM_API size_t cm_sweep_num_nodes(const cm_sweep *sweep);
CM_API const double *cm_sweep_nodes(const cm_sweep *sweep);
/* 6 node indices per prism: bottom a b c (counter-clockwise seen from +z),
 * then top a' b' c' (Gmsh's wedge order). */
CM_API size_t cm_sweep_num_prisms(const cm_sweep *sweep);
CM_API const int32_t *cm_sweep_prisms(const cm_sweep *sweep);
/* 4 node indices per tetrahedron, positive volume (checked exactly); 0 /
 * NULL unless options.tets. Prism p gives tetrahedra 3p .. 3p + 2. In each
 * layer the diagonals of the quad faces follow an order of the triangle
 * corners chosen per prism, acyclic around every triangle, so faces
 * conform; among such orders the worst prisms (by the smallest dihedral
 * angle they admit) choose first, looking one step ahead at the
 * neighbours whose diagonals they force, then a local search (one diagonal,
 * one prism's three, or all diagonals at one vertex) raises the worst. A
 * layer is halved in morph time where a prism's split has a dihedral angle
 * under half the smallest angle of its two triangles while the prism is at
 * least half as tall as its longest triangle edge (a long morph step tilts
 * or twists it; halving a flatter one would only flatten it), as long as no
 * prism of the halved layer is flatter than 1:5, within max_refine. */
CM_API size_t cm_sweep_num_tets(const cm_sweep *sweep);
CM_API const int32_t *cm_sweep_tets(const cm_sweep *sweep);
/* Sum of the prism volumes (equal to the integral of section areas; for a
 * loft, options.frames, the wedges' volume in space, the integral of their
 * Jacobian); HUGE_VAL when it is beyond the double range. */
CM_API double cm_sweep_volume(const cm_sweep *sweep);
/* The height from the first to the last section, and 1 if it was the
 * default (options.height 0 without heights: the largest bounding-box
 * diagonal of the geometries), else 0. */
CM_API double cm_sweep_height(const cm_sweep *sweep);
CM_API int cm_sweep_height_is_default(const cm_sweep *sweep);
/* The volume's boundary as faces in groups, for boundary conditions:
 * group 0 is the first section (the bottom), group 1 the last (the top),
 * then the walls over the loops, the outer loop's first, then hole 1's,
 * ...: one wall per loop, named "side" and "hole_1", "hole_2", ..., or
 * with options.wall_corner_deg one per stretch of a loop between its
 * corners, "side_1", "side_2", ..., "hole_1_1", ..., numbered from the
 * first corner in the loop's order (a loop without such a corner keeps
 * one wall, "side" or "hole_j"). Faces come sorted by group, 4 node
 * indices each, ordered so that the normal (right-hand rule) points out
 * of the volume: the caps' triangles (the 4th index -1) and the walls'
 * quads a b b' a' (a -> b a boundary edge with the material on its left,
 * primes one section up: the prisms' side faces), or with tets = 1 the
 * two triangles of each quad that the tetrahedra have (a sweep built
 * without tets has no such faces: 0 / NULL). */
CM_API size_t cm_sweep_num_boundary_groups(const cm_sweep *sweep);
CM_API size_t cm_sweep_num_boundary_faces(const cm_sweep *sweep, int tets);
CM_API const int32_t *cm_sweep_boundary_faces(const cm_sweep *sweep, int tets);
CM_API const int32_t *cm_sweep_boundary_groups(const cm_sweep *sweep, int tets);
/* Where each group's faces lie, so that a group is taken without a scan:
 * num_boundary_groups + 1 offsets, group g's faces [offsets[g],
 * offsets[g + 1]), the first offset 0, the last the face count; NULL where
 * the faces are NULL. */
CM_API const size_t *cm_sweep_boundary_group_offsets(const cm_sweep *sweep, int tets);
/* Which cell face each boundary face is, for solvers that load element
 * faces (an Abaqus or CalculiX *SURFACE, TYPE=ELEMENT): 2 per face, the
 * cell's index (into cm_sweep_prisms, or cm_sweep_tets with tets = 1) and
 * its face, numbered as Abaqus numbers them from S1, here from 0. Prisms
 * (C3D6, corners a b c over a' b' c'): 0 the bottom a b c, 1 the top,
 * 2 + j the quad over the triangle's edge j (a b, b c, c a); tetrahedra
 * (C3D4, corners 1 to 4): 0 1-2-3, 1 1-4-2, 2 2-4-3, 3 3-4-1. NULL where
 * the faces are NULL. */
CM_API const int64_t *cm_sweep_boundary_cells(const cm_sweep *sweep, int tets);
/* Group g's name, as every writer gives it (at most 31 characters, words a
 * solver's input deck takes as set names); NULL out of range. Owned by
 * the sweep. */
CM_API const char *cm_sweep_boundary_group_name(const cm_sweep *sweep, size_t group);
/* The method of the morph whose sections the sweep holds. */
CM_API cm_morph_method cm_sweep_morph_method(const cm_sweep *sweep);

/* A prism is flat when its longest triangle edge (bottom or top) exceeds
 * this many times its height: its tetrahedra have dihedral angles of a few
 * degrees at best (about atan(height / edge)). */
#define CM_SWEEP_FLAT_RATIO 10.0

/* Shape of the volume's cells: the tetrahedra with options.tets, else the
 * prisms (their corner planes: exact where the faces are planar). The
 * measures are those of Verdict and Gmsh: scaled Jacobian 1 for the
 * regular tetrahedron and the right prism on an equilateral triangle;
 * aspect ratio longest edge / (2 sqrt 6 inradius) for a tetrahedron
 * (1 when regular), longest / shortest edge for a prism. */
typedef struct cm_sweep_quality {
    double min_dihedral_deg, max_dihedral_deg;
    double min_scaled_jacobian;
    double max_aspect_ratio;
    /* Over the prisms: the largest longest-triangle-edge / height, and how
     * many exceed CM_SWEEP_FLAT_RATIO. */
    double max_flatness;
    size_t flat_prisms;
} cm_sweep_quality;

/* Fills quality (all zero for a failed sweep). */
CM_API void cm_sweep_get_quality(const cm_sweep *sweep, cm_sweep_quality *quality);

/* The cells' part of cm_sweep_quality (the flatness fields 0) for any
 * nodes (3 per node) and cells (4 corners per tetrahedron with tets = 1,
 * else 6 per prism, as cm_sweep_tets and cm_sweep_prisms give them): for
 * a sweep's cells placed elsewhere in space, as between two sections in
 * planes that are not parallel. */
CM_API void cm_cells_quality(const double *nodes, const int32_t *cells, size_t num_cells, int tets,
                             cm_sweep_quality *quality);

/* A morph section xy (num_vertices points, cm_morph_section) at time t
 * placed in space between the planes of k geometries (frames as in
 * cm_sweep_options.frames, the morph passing through geometry g at
 * t = g / (k - 1)): each point (1 - s) times its point in the plane of the
 * geometry before t plus s times its point in the plane of the one after,
 * s the fraction of that segment, as a loft places its nodes. xyz receives
 * 3 doubles per point. */
CM_API void cm_loft_section(const double *frames, size_t k, double t, const double *xy, size_t num_vertices,
                            double *xyz);

#ifdef __cplusplus
}
#endif
#endif
