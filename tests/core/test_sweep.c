/* The sweep: prisms valid along their blends (re-checked here with the
 * exact blend predicate on the node coordinates), tetrahedra positive and
 * conforming, the ends equal to the inputs, the volume equal to the
 * integral of the section areas (Simpson's rule per slab is exact: the
 * area of a blended polygon is quadratic), and clear failures: the linear
 * morph, a refinement budget too small, bad options. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "morph_fixtures.h"
#include "geom/angle.h"
#include "geom/predicates.h"
#include "sweep_boundary_check.h"

#define N 60

/* Area of the polygon (vertices 0..n-1) blended at s between two sections. */
static double blended_area(const double *nodes, size_t lo, size_t hi, size_t n, double s)
{
    double a = 0;
    for (size_t i = 0; i < n; i++) {
        size_t j = (i + 1) % n;
        double xi = (1 - s) * nodes[3 * (lo + i)] + s * nodes[3 * (hi + i)];
        double yi = (1 - s) * nodes[3 * (lo + i) + 1] + s * nodes[3 * (hi + i) + 1];
        double xj = (1 - s) * nodes[3 * (lo + j)] + s * nodes[3 * (hi + j)];
        double yj = (1 - s) * nodes[3 * (lo + j) + 1] + s * nodes[3 * (hi + j) + 1];
        a += xi * yj - xj * yi;
    }
    return 0.5 * fabs(a);
}

/* Tet faces: each shared by at most two tets, and the unshared ones are
 * exactly the sweep's boundary (bottom, top, two per side quad). */
static void check_conforming(const cm_sweep *w, size_t nt, size_t n)
{
    size_t nf = 4 * cm_sweep_num_tets(w);
    int32_t *faces = malloc(3 * nf * sizeof *faces);
    const int32_t *tet = cm_sweep_tets(w);
    for (size_t t = 0; t < cm_sweep_num_tets(w); t++)
        for (int f = 0; f < 4; f++) {
            int32_t *face = faces + 3 * (4 * t + (size_t)f);
            for (int c = 0, j = 0; c < 4; c++)
                if (c != f) face[j++] = tet[4 * t + (size_t)c];
            qsort(face, 3, sizeof *face, sb_int_less);
        }
    qsort(faces, nf, 3 * sizeof *faces, sb_key_less);
    size_t open = 0, over = 0;
    for (size_t i = 0; i < nf;) {
        size_t j = i + 1;
        while (j < nf && sb_key_less(faces + 3 * i, faces + 3 * j) == 0) j++;
        open += j - i == 1, over += j - i > 2;
        i = j;
    }
    size_t ns = cm_sweep_num_sections(w);
    CHECK_MSG(over == 0 && open == 2 * nt + 2 * n * (ns - 1), "%zu faces over-shared, %zu open (expected %zu)", over,
              open, 2 * nt + 2 * n * (ns - 1));
    free(faces);
}

static void test_sweep(fixture_kind kind, const double *heights, int tets, cm_morph_method method)
{
    const char *name = fixture_name(kind);
    cm_result *r = fixture_result(kind, N);
    if (!r) {
        CHECK(0);
        return;
    }
    size_t k = cm_result_num_geometries(r), nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r);
    cm_morph *m = NULL;
    cm_morph_options mo;
    cm_morph_options_init(&mo);
    mo.method = method;
    CHECK(cm_morph_create(r, &mo, &m) == CM_OK);
    cm_sweep_options o;
    cm_sweep_options_init(&o);
    o.tets = tets;
    o.height = 2.0;
    o.heights = heights;
    cm_sweep *w = NULL;
    cm_status s = cm_sweep_create(m, &o, &w);
    CHECK_MSG(s == CM_OK, "%s: %s", name, cm_sweep_message(w));
    if (s != CM_OK) goto done;
    size_t ns = cm_sweep_num_sections(w), np = cm_sweep_num_prisms(w);
    const double *z = cm_sweep_section_z(w), *nodes = cm_sweep_nodes(w);
    CHECK(ns >= (k - 1) * (o.sections - 1) + 1);
    CHECK(cm_sweep_num_nodes(w) == ns * nv && np == (ns - 1) * nt && cm_sweep_num_tets(w) == (tets ? 3 * np : 0));
    CHECK(z[0] == (heights ? heights[0] : 0.0) && z[ns - 1] == (heights ? heights[k - 1] : 2.0));
    for (size_t i = 0; i + 1 < ns; i++) CHECK(z[i + 1] > z[i]);
    /* Ends: the input geometries, bit for bit. */
    for (size_t v = 0; v < nv; v++) {
        CHECK(nodes[3 * v] == cm_result_vertices(r, 0)[2 * v]);
        CHECK(nodes[3 * ((ns - 1) * nv + v) + 1] == cm_result_vertices(r, k - 1)[2 * v + 1]);
    }
    /* Every prism valid along its blend; every tet positive. */
    size_t bad_prisms = 0, bad_tets = 0;
    const int32_t *pr = cm_sweep_prisms(w), *tet = cm_sweep_tets(w);
    for (size_t p = 0; p < np; p++) {
        const int32_t *q = pr + 6 * p;
        int ok = 1;
        for (int c = 0; c < 3; c++)
            ok &= q[3 + c] - q[c] == (int32_t)nv && nodes[3 * (size_t)q[3 + c] + 2] > nodes[3 * (size_t)q[c] + 2];
        double p2[6][2];
        for (int c = 0; c < 6; c++) p2[c][0] = nodes[3 * (size_t)q[c]], p2[c][1] = nodes[3 * (size_t)q[c] + 1];
        bad_prisms += !ok || !cm_blend_positive(p2[0], p2[1], p2[2], p2[3], p2[4], p2[5]);
    }
    for (size_t t = 0; t < cm_sweep_num_tets(w); t++)
        bad_tets += cm_orient3d(nodes + 3 * (size_t)tet[4 * t], nodes + 3 * (size_t)tet[4 * t + 1],
                                nodes + 3 * (size_t)tet[4 * t + 2], nodes + 3 * (size_t)tet[4 * t + 3]) <= 0;
    CHECK_MSG(bad_prisms == 0 && bad_tets == 0, "%s: %zu prisms, %zu tets invalid", name, bad_prisms, bad_tets);
    if (tets) check_conforming(w, nt, (size_t)N);
    check_sweep_boundary(name, w, r, 0);
    if (tets) check_sweep_boundary(name, w, r, 1);
    /* Volume = integral of the polygon's section area. */
    double integral = 0;
    for (size_t i = 0; i + 1 < ns; i++) {
        size_t lo = i * nv, hi = (i + 1) * nv;
        integral += (z[i + 1] - z[i]) / 6 *
                    (blended_area(nodes, lo, hi, N, 0) + 4 * blended_area(nodes, lo, hi, N, 0.5) +
                     blended_area(nodes, lo, hi, N, 1));
    }
    double rel = fabs(cm_sweep_volume(w) - integral) / integral;
    CHECK_MSG(rel < 1e-9, "%s: volume %.15g, integral of areas %.15g", name, cm_sweep_volume(w), integral);
    printf("%s%s%s: %zu sections (%zu inserted), %zu prisms, %zu tets, volume %.12g (relative difference %.1e)\n", name,
           method == CM_MORPH_INTRINSIC ? ", intrinsic" : "", tets ? " with tets" : "", ns,
           ns - ((k - 1) * (o.sections - 1) + 1), np, cm_sweep_num_tets(w), cm_sweep_volume(w), rel);
done:
    cm_sweep_free(w);
    cm_morph_free(m);
    cm_result_free(r);
}

/* Without height or heights the sweep is as tall as the largest bounding-box
 * diagonal of the geometries and says so; the quality figures describe the
 * tetrahedra (recomputed here from the nodes). */
static void test_default_height_and_quality(void)
{
    cm_result *r = fixture_result(FIX_GLYPH, N);
    cm_morph *m = NULL;
    CHECK(r && cm_morph_create(r, NULL, &m) == CM_OK);
    if (!m) goto done;
    double diagonal = 0;
    for (size_t g = 0; g < cm_result_num_geometries(r); g++) {
        const double *xy = cm_result_vertices(r, g);
        double lo[2] = {xy[0], xy[1]}, hi[2] = {xy[0], xy[1]};
        for (size_t v = 0; v < cm_result_num_vertices(r); v++)
            for (int c = 0; c < 2; c++) lo[c] = fmin(lo[c], xy[2 * v + c]), hi[c] = fmax(hi[c], xy[2 * v + c]);
        diagonal = fmax(diagonal, hypot(hi[0] - lo[0], hi[1] - lo[1]));
    }
    cm_sweep_options o;
    cm_sweep_options_init(&o);
    CHECK(o.height == 0);
    o.tets = 1;
    cm_sweep *w = NULL;
    CHECK_MSG(cm_sweep_create(m, &o, &w) == CM_OK, "%s", cm_sweep_message(w));
    CHECK(cm_sweep_height_is_default(w) && cm_sweep_height(w) == diagonal);
    cm_sweep_quality q;
    cm_sweep_get_quality(w, &q);
    /* Where validity needed many inserted sections some layers are thin, so
     * only the figures' consistency is asserted here; the sliver bound is
     * tested on the command line's default sweep. */
    double least = 180;
    const double *nodes = cm_sweep_nodes(w);
    for (size_t t = 0; t < cm_sweep_num_tets(w); t++) {
        const int32_t *c = cm_sweep_tets(w) + 4 * t;
        for (int i = 0; i < 4; i++)
            for (int j = i + 1; j < 4; j++) {
                int k = 0, l;
                while (k == i || k == j) k++;
                l = 6 - i - j - k;
                double e[3], u[3], v[3], n1[3], n2[3], n[3];
                for (int x = 0; x < 3; x++)
                    e[x] = nodes[3 * c[j] + x] - nodes[3 * c[i] + x], u[x] = nodes[3 * c[k] + x] - nodes[3 * c[i] + x],
                    v[x] = nodes[3 * c[l] + x] - nodes[3 * c[i] + x];
                for (int x = 0; x < 3; x++) {
                    int y = (x + 1) % 3, z = (x + 2) % 3;
                    n1[x] = e[y] * u[z] - e[z] * u[y], n2[x] = e[y] * v[z] - e[z] * v[y];
                }
                for (int x = 0; x < 3; x++) n[x] = n1[(x + 1) % 3] * n2[(x + 2) % 3] - n1[(x + 2) % 3] * n2[(x + 1) % 3];
                double angle = atan2(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2]);
                least = fmin(least, angle * 180 / 3.14159265358979323846);
            }
    }
    CHECK_MSG(fabs(q.min_dihedral_deg - least) < 1e-9, "reported %.12g, recomputed %.12g", q.min_dihedral_deg, least);
    CHECK_MSG(q.min_dihedral_deg > 0 && q.max_dihedral_deg < 180 && q.min_scaled_jacobian > 0 &&
              q.max_aspect_ratio >= 1 && q.max_flatness > 0,
              "dihedral %g..%g, scaled Jacobian %g, aspect %g, flatness %g (%zu flat)", q.min_dihedral_deg,
              q.max_dihedral_deg, q.min_scaled_jacobian, q.max_aspect_ratio, q.max_flatness, q.flat_prisms);
    printf("glyph, default height %g: dihedral %.2f..%.2f deg, scaled Jacobian %.3f, aspect %.2f, flatness %.2f\n",
           cm_sweep_height(w), q.min_dihedral_deg, q.max_dihedral_deg, q.min_scaled_jacobian, q.max_aspect_ratio,
           q.max_flatness);
    cm_sweep_free(w);
    /* A given height is used as given; a very flat one is counted as flat. */
    size_t flat_before = q.flat_prisms;
    o.height = 1e-3 * diagonal;
    CHECK(cm_sweep_create(m, &o, &w) == CM_OK && !cm_sweep_height_is_default(w) && cm_sweep_height(w) == o.height);
    cm_sweep_get_quality(w, &q);
    CHECK_MSG(q.flat_prisms > flat_before && q.max_flatness > CM_SWEEP_FLAT_RATIO, "%zu flat prisms, flatness %g", q.flat_prisms,
              q.max_flatness);
    cm_sweep_free(w);
done:
    cm_morph_free(m);
    cm_result_free(r);
}

static int cancel_now(void *user, double fraction, const char *stage)
{
    (void)user, (void)fraction, (void)stage;
    return 1;
}

/* A square plate with a square hole against a wider plate whose hole
 * moved, swept with walls split at corners: four sides and four hole
 * sides, each over one side of its square (5 vertices, collinear in the
 * bottom section), numbered from the first corner in the loop's order
 * (the outer loops start mid-side, so their last wall wraps past vertex
 * 0); without the corner angle, one wall per loop; an angle of 180
 * refused. The 16 vertices of a square loop, 4 a side, from `shift`
 * vertices before a corner. */
static void square_loop(double *xy, double cx, double cy, double h, double sx, int clockwise, int shift)
{
    static const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int j = 0; j < 16; j++) {
        int i = (j + 16 - shift) % 16;
        int c = clockwise ? (4 - i / 4) % 4 : i / 4, d = clockwise ? (c + 3) % 4 : (c + 1) % 4;
        double t = (i % 4) / 4.0;
        xy[2 * j] = cx + sx * h * ((1 - t) * corner[c][0] + t * corner[d][0]);
        xy[2 * j + 1] = cy + h * ((1 - t) * corner[c][1] + t * corner[d][1]);
    }
}

/* The square plate with a square hole and the wider plate whose hole
 * moved, the outer loops listed from `shift` vertices before a corner,
 * triangulated and morphed; NULL on failure (checked). */
static cm_morph *square_plates(int shift, cm_result **r)
{
    double a[64], b[64];
    square_loop(a, 0, 0, 1, 1, 0, shift), square_loop(a + 32, 0, 0, 0.4, 1, 1, 0);
    square_loop(b, 0, 0, 1, 1.5, 0, shift), square_loop(b + 32, 0.3, 0.1, 0.3, 1, 1, 0);
    const size_t sizes[2] = {16, 16};
    const cm_loops in[2] = {{a, sizes, 2}, {b, sizes, 2}};
    cm_morph *m = NULL;
    *r = NULL;
    CHECK(cm_triangulate_loops(in, 2, NULL, r) == CM_OK && cm_morph_create(*r, NULL, &m) == CM_OK);
    return m;
}

static void test_walls_at_corners(void)
{
    cm_result *r = NULL;
    cm_morph *m = square_plates(2, &r);
    for (int tets = 0; tets < 2 && m; tets++) {
        cm_sweep_options so;
        cm_sweep_options_init(&so);
        so.tets = tets, so.sections = 4, so.wall_corner_deg = 45;
        cm_sweep *w = NULL;
        CHECK_MSG(cm_sweep_create(m, &so, &w) == CM_OK, "walls at corners: %s", cm_sweep_message(w));
        static const char *const names[10] = {"bottom", "top", "side_1", "side_2", "side_3", "side_4",
                                              "hole_1_1", "hole_1_2", "hole_1_3", "hole_1_4"};
        CHECK(cm_sweep_num_boundary_groups(w) == 10);
        for (size_t k = 0; k < 10 && cm_sweep_num_boundary_groups(w) == 10; k++)
            CHECK_MSG(strcmp(cm_sweep_boundary_group_name(w, k), names[k]) == 0, "group %zu is %s", k,
                      cm_sweep_boundary_group_name(w, k));
        check_sweep_boundary(tets ? "walls at corners, tets" : "walls at corners", w, r, tets);
        /* Each wall over one side: 5 boundary vertices, at the bottom on
         * one line; side_1 from vertex 2 (the first corner) to 6, side_4
         * from 14 past vertex 0 to 2, hole_1_1 from vertex 16. */
        size_t nv = cm_result_num_vertices(r), nf = cm_sweep_num_boundary_faces(w, tets);
        const int32_t *f = cm_sweep_boundary_faces(w, tets), *g = cm_sweep_boundary_groups(w, tets);
        const double *nodes = cm_sweep_nodes(w);
        for (int32_t k = 2; k < 10; k++) {
            int seen[32] = {0}, count = 0, first = 32, on_x = 1, on_y = 1;
            double x = NAN, y = NAN;
            for (size_t i = 0; i < nf; i++)
                for (int c = 0; c < 4 && g[i] == k && f[4 * i + c] >= 0; c++) {
                    size_t v = (size_t)f[4 * i + c] % nv;
                    if (v >= 32) continue;
                    count += !seen[v], seen[v] = 1, first = (int)v < first ? (int)v : first;
                    if ((size_t)f[4 * i + c] >= nv) continue; /* the bottom section's nodes only */
                    const double *p = nodes + 3 * (size_t)f[4 * i + c];
                    if (isnan(x)) x = p[0], y = p[1];
                    on_x &= p[0] == x, on_y &= p[1] == y;
                }
            CHECK_MSG(count == 5 && (on_x || on_y), "wall %s: %d vertices, on one line %d", names[k], count,
                      on_x || on_y);
            if (k == 2 || k == 6) CHECK_MSG(first == (k == 2 ? 2 : 16), "wall %s starts at %d", names[k], first);
            if (k == 5) CHECK_MSG(seen[14] && seen[15] && seen[0] && seen[2], "wall side_4 does not wrap");
        }
        cm_sweep_free(w);
    }
    cm_sweep_options so;
    cm_sweep_options_init(&so);
    cm_sweep *w = NULL;
    CHECK(m && cm_sweep_create(m, &so, &w) == CM_OK && cm_sweep_num_boundary_groups(w) == 4 &&
          strcmp(cm_sweep_boundary_group_name(w, 2), "side") == 0 &&
          strcmp(cm_sweep_boundary_group_name(w, 3), "hole_1") == 0);
    cm_sweep_free(w);
    so.wall_corner_deg = 180;
    CHECK(m && cm_sweep_create(m, &so, &w) == CM_ERR_ARGUMENT && strstr(cm_sweep_message(w), "wall_corner_deg") &&
          cm_sweep_num_boundary_groups(w) == 0 && !cm_sweep_boundary_group_name(w, 0) &&
          !cm_sweep_boundary_group_offsets(w, 0));
    cm_sweep_free(w);
    cm_morph_free(m);
    cm_result_free(r);
}

/* The ruled sweep: where the straight blends stay valid (a square plate
 * against a wider one) every node lies on the straight line between its
 * inputs and the plates' bottom side stays in the plane y = -1; where they
 * invert (the twisted pair) the convex morph's sections are swept. */
static void test_ruled(void)
{
    cm_result *r = NULL, *twisted = fixture_result(FIX_TWISTED, N);
    cm_morph *m = square_plates(0, &r), *mt = NULL;
    CHECK(twisted && cm_morph_create(twisted, NULL, &mt) == CM_OK);
    cm_sweep_options so;
    cm_sweep_options_init(&so);
    so.ruled = 1, so.tets = 1, so.height = 2.0;
    cm_sweep *w = NULL;
    CHECK_MSG(m && cm_sweep_create(m, &so, &w) == CM_OK, "ruled: %s", cm_sweep_message(w));
    if (w && cm_sweep_num_sections(w)) {
        CHECK(cm_sweep_morph_method(w) == CM_MORPH_LINEAR);
        size_t nv = cm_result_num_vertices(r), ns = cm_sweep_num_sections(w), off = 0;
        const double *nodes = cm_sweep_nodes(w), *p0 = cm_result_vertices(r, 0), *p1 = cm_result_vertices(r, 1);
        for (size_t i = 0; i < ns; i++)
            for (size_t v = 0; v < nv; v++) {
                double t = nodes[3 * (i * nv + v) + 2] / 2.0;
                for (int c = 0; c < 2; c++)
                    off += fabs(nodes[3 * (i * nv + v) + c] - ((1 - t) * p0[2 * v + c] + t * p1[2 * v + c])) > 1e-12;
                if (v <= 4) off += fabs(nodes[3 * (i * nv + v) + 1] + 1) > 1e-12; /* the bottom side, y = -1 */
            }
        CHECK_MSG(off == 0, "ruled: %zu coordinates off the straight blends", off);
        check_sweep_boundary("ruled", w, r, 1);
    }
    cm_sweep_free(w);
    w = NULL;
    CHECK_MSG(mt && cm_sweep_create(mt, &so, &w) == CM_OK, "ruled, twisted: %s", cm_sweep_message(w));
    CHECK(w && cm_sweep_morph_method(w) == CM_MORPH_CONVEX && cm_sweep_volume(w) > 0);
    cm_sweep_free(w);
    cm_morph_free(m), cm_morph_free(mt);
    cm_result_free(r), cm_result_free(twisted);
}

/* sections = 0: layers about as tall as the triangulation's median edge
 * h in the tallest segment, so the sections per segment are ceil(tallest
 * / h) + 1 (more where the validity refinement inserts some); the same
 * triangulation swept 3 and 9 times as tall gets about 3 and 9 times the
 * layers, at most CM_SWEEP_MAX_SECTIONS. */
static void test_sections_for_edges(void)
{
    cm_result *r = NULL;
    cm_morph *m = square_plates(0, &r);
    size_t nt = m ? cm_result_num_triangles(r) : 0, n = 6 * nt, layers[3] = {0, 0, 0};
    double *length = malloc((n + 1) * sizeof *length);
    const int32_t *tri = r ? cm_result_triangles(r) : NULL;
    for (size_t g = 0, i = 0; m && length && g < 2; g++) {
        const double *xy = cm_result_vertices(r, g);
        for (size_t t = 0; t < nt; t++)
            for (int c = 0; c < 3; c++) {
                const double *p = xy + 2 * tri[3 * t + c], *q = xy + 2 * tri[3 * t + (c + 1) % 3];
                length[i++] = hypot(q[0] - p[0], q[1] - p[1]);
            }
    }
    for (size_t i = 1; m && length && i < n; i++) /* insertion sort: a few hundred edges */
        for (size_t j = i; j > 0 && length[j - 1] > length[j]; j--) {
            double swap = length[j];
            length[j] = length[j - 1], length[j - 1] = swap;
        }
    double median = m && length ? length[n / 2] : 1;
    const double heights[3] = {1.0, 3.0, 9.0};
    for (int i = 0; m && i < 3; i++) {
        cm_sweep_options so;
        cm_sweep_options_init(&so);
        so.sections = 0, so.height = heights[i];
        cm_sweep *w = NULL;
        CHECK_MSG(cm_sweep_create(m, &so, &w) == CM_OK, "sections for edges: %s", cm_sweep_message(w));
        layers[i] = cm_sweep_num_sections(w) - 1;
        CHECK_MSG(layers[i] >= (size_t)ceil(heights[i] / median) && layers[i] <= 2 * (size_t)ceil(heights[i] / median),
                  "height %g, median edge %g: %zu layers", heights[i], median, layers[i]);
        check_sweep_boundary("sections for edges", w, r, 0);
        cm_sweep_free(w);
    }
    CHECK_MSG(layers[2] > layers[1] && layers[1] > layers[0], "layers %zu, %zu, %zu", layers[0], layers[1], layers[2]);
    cm_sweep_options so;
    cm_sweep_options_init(&so);
    so.sections = 0, so.height = 1e9 * median;
    cm_sweep *w = NULL;
    CHECK(m && cm_sweep_create(m, &so, &w) == CM_OK && cm_sweep_num_sections(w) == CM_SWEEP_MAX_SECTIONS);
    cm_sweep_free(w);
    so.sections = 1;
    CHECK(m && cm_sweep_create(m, &so, &w) == CM_ERR_ARGUMENT && strstr(cm_sweep_message(w), "2 to 10000, got 1"));
    cm_sweep_free(w);
    free(length);
    cm_morph_free(m);
    cm_result_free(r);
}

/* cm_cells_quality: the sweep's own cell quality from its own nodes, and
 * another where the same cells are placed elsewhere (the z stretched ten
 * times: the regular-ish tetrahedra flatten the other way). */
static void test_cells_quality(void)
{
    cm_result *r = NULL;
    cm_morph *m = square_plates(0, &r);
    cm_sweep_options so;
    cm_sweep_options_init(&so);
    so.tets = 1, so.sections = 4;
    cm_sweep *w = NULL;
    CHECK(m && cm_sweep_create(m, &so, &w) == CM_OK);
    if (w) {
        cm_sweep_quality own, again, stretched;
        cm_sweep_get_quality(w, &own);
        size_t nn = cm_sweep_num_nodes(w), nt = cm_sweep_num_tets(w);
        cm_cells_quality(cm_sweep_nodes(w), cm_sweep_tets(w), nt, 1, &again);
        CHECK(again.min_dihedral_deg == own.min_dihedral_deg && again.max_dihedral_deg == own.max_dihedral_deg &&
              again.min_scaled_jacobian == own.min_scaled_jacobian && again.max_aspect_ratio == own.max_aspect_ratio &&
              again.max_flatness == 0 && again.flat_prisms == 0);
        double *moved = malloc(3 * nn * sizeof *moved);
        for (size_t i = 0; moved && i < 3 * nn; i++) moved[i] = cm_sweep_nodes(w)[i] * (i % 3 == 2 ? 10.0 : 1.0);
        if (moved) cm_cells_quality(moved, cm_sweep_tets(w), nt, 1, &stretched);
        CHECK_MSG(moved && stretched.min_dihedral_deg < own.min_dihedral_deg && stretched.max_aspect_ratio > own.max_aspect_ratio,
                  "stretched: %g degrees, aspect %g (own %g, %g)", moved ? stretched.min_dihedral_deg : 0,
                  moved ? stretched.max_aspect_ratio : 0, own.min_dihedral_deg, own.max_aspect_ratio);
        free(moved);
    }
    cm_sweep_free(w);
    cm_morph_free(m);
    cm_result_free(r);
}

/* The loft (options.frames): frames of two parallel planes give the
 * ordinary sweep's nodes and volume (the loft at least as long as the
 * planes are apart); a square swept from z = 0 to a plane
 * turned by 30 degrees about x through (0, 0, 2) has its ends in the two
 * planes, every cell positive (the core's check, and cm_check_tetrahedra
 * again), and the volume of the blend, 4 (1 + cos 30 degrees), to within
 * rounding (the square does not change along the loft, so the wedges
 * are the blend itself); planes crossing inside the square fold (a clear
 * failure, prisms and tetrahedra); bad frames are refused; a morph
 * section placed by cm_loft_section lies as the loft's nodes do. */
static void set_frame(double *f, double oz, double turn_deg)
{
    double c = cos(turn_deg * CM_PI / 180), s = sin(turn_deg * CM_PI / 180);
    const double frame[9] = {0, 0, oz, 1, 0, 0, 0, c, s};
    memcpy(f, frame, sizeof frame);
}

static void test_loft(void)
{
    cm_result *r = NULL;
    cm_morph *plates = square_plates(0, &r);
    cm_sweep_options so;
    double frames[18], heights[2] = {0, 3};
    cm_sweep *plain = NULL, *w = NULL;
    for (int tets = 0; tets < 2 && plates; tets++) {
        cm_sweep_options_init(&so);
        so.tets = tets, so.sections = 5, so.heights = heights;
        CHECK(cm_sweep_create(plates, &so, &plain) == CM_OK);
        set_frame(frames, 0, 0), set_frame(frames + 9, 3, 0);
        so.heights = NULL, so.frames = frames;
        CHECK_MSG(cm_sweep_create(plates, &so, &w) == CM_OK, "parallel loft: %s", cm_sweep_message(w));
        size_t nn = cm_sweep_num_nodes(w);
        double worst = nn == cm_sweep_num_nodes(plain) ? 0 : 1;
        for (size_t i = 0; i < 3 * nn && !worst; i++) worst = fmax(worst, fabs(cm_sweep_nodes(w)[i] - cm_sweep_nodes(plain)[i]));
        CHECK_MSG(worst < 1e-12 && fabs(cm_sweep_volume(w) - cm_sweep_volume(plain)) < 1e-9 * cm_sweep_volume(plain) &&
                      cm_sweep_height(w) >= 3 && cm_sweep_height(w) < 3.1,
                  "parallel loft: nodes %g apart, volume %.15g against %.15g", worst, cm_sweep_volume(w), cm_sweep_volume(plain));
        cm_sweep_free(plain), cm_sweep_free(w);
        plain = w = NULL;
    }
    cm_morph_free(plates);
    cm_result_free(r);

    double sq[32];
    square_loop(sq, 0, 0, 1, 1, 0, 0);
    const double *both[2] = {sq, sq};
    const size_t counts[2] = {16, 16};
    cm_morph *m = NULL;
    r = NULL;
    CHECK(cm_triangulate_polygons(both, counts, 2, NULL, &r) == CM_OK && cm_morph_create(r, NULL, &m) == CM_OK);
    for (int tets = 0; tets < 2 && m; tets++) {
        cm_sweep_options_init(&so);
        so.tets = tets, so.sections = 0, so.frames = frames;
        set_frame(frames, 0, 0), set_frame(frames + 9, 2, 30);
        CHECK_MSG(cm_sweep_create(m, &so, &w) == CM_OK, "turned loft: %s", cm_sweep_message(w));
        size_t nv = cm_result_num_vertices(r), nn = cm_sweep_num_nodes(w);
        const double *nodes = cm_sweep_nodes(w), *top = nodes + 3 * (nn - nv);
        double off = 0, normal[3] = {0, -sin(CM_PI / 6), cos(CM_PI / 6)};
        for (size_t v = 0; v < nv; v++) {
            off = fmax(off, fabs(nodes[3 * v + 2]));
            off = fmax(off, fabs(top[3 * v] * normal[0] + top[3 * v + 1] * normal[1] + (top[3 * v + 2] - 2) * normal[2]));
        }
        long where = -1;
        if (tets) CHECK(cm_check_tetrahedra(nodes, nn, cm_sweep_tets(w), cm_sweep_num_tets(w), &where) == CM_OK);
        cm_sweep_quality q;
        cm_sweep_get_quality(w, &q);
        double exact = 4 * (1 + cos(CM_PI / 6));
        CHECK_MSG(off < 1e-12 && fabs(cm_sweep_volume(w) - exact) < 1e-9 * exact && q.min_dihedral_deg > 0 &&
                      cm_sweep_num_sections(w) > 2,
                  "turned loft: ends %g off their planes, volume %g against %g, dihedral %g, %zu sections", off,
                  cm_sweep_volume(w), exact, q.min_dihedral_deg, cm_sweep_num_sections(w));
        cm_sweep_free(w), w = NULL;

        set_frame(frames + 9, 0.3, 80); /* its plane dips under z = 0 at y < -0.3 */
        CHECK_MSG(cm_sweep_create(m, &so, &w) == CM_ERR_ARGUMENT && strstr(cm_sweep_message(w), "not positive in space") &&
                      cm_sweep_num_nodes(w) == 0,
                  "crossing planes: %s", cm_sweep_message(w));
        cm_sweep_free(w), w = NULL;
    }
    set_frame(frames, 0, 0), set_frame(frames + 9, 0, 30);
    CHECK(m && cm_sweep_create(m, &so, &w) == CM_ERR_ARGUMENT && strstr(cm_sweep_message(w), "centred at the same point"));
    cm_sweep_free(w), w = NULL;
    set_frame(frames + 9, 1, 0), frames[12] = 2;
    CHECK(m && cm_sweep_create(m, &so, &w) == CM_ERR_ARGUMENT && strstr(cm_sweep_message(w), "unit vectors"));
    cm_sweep_free(w), w = NULL;
    set_frame(frames + 9, 1, 0), so.height = 2;
    CHECK(m && cm_sweep_create(m, &so, &w) == CM_ERR_ARGUMENT && strstr(cm_sweep_message(w), "no heights"));
    cm_sweep_free(w);
    cm_morph_free(m);
    cm_result_free(r);

    /* cm_loft_section: a morph section placed as the loft places nodes:
     * in the first plane at t = 0, the last at t = 1, and with three
     * frames halfway along the second segment at t = 0.75. */
    double three[27], xy[4] = {0.5, -1, 2, 3}, out[6];
    set_frame(three, 0, 0), set_frame(three + 9, 2, 30), set_frame(three + 18, 4, 60);
    cm_loft_section(three, 3, 0.0, xy, 2, out);
    CHECK(out[0] == 0.5 && out[1] == -1 && out[2] == 0 && out[3] == 2 && out[4] == 3 && out[5] == 0);
    cm_loft_section(three, 3, 1.0, xy, 2, out);
    CHECK(fabs(out[4] - 3 * cos(CM_PI / 3)) < 1e-15 && fabs(out[5] - (4 + 3 * sin(CM_PI / 3))) < 1e-15);
    cm_loft_section(three, 3, 0.75, xy, 2, out);
    double mid_y = 0.5 * 3 * (cos(CM_PI / 6) + cos(CM_PI / 3)), mid_z = 0.5 * (2 + 3 * sin(CM_PI / 6) + 4 + 3 * sin(CM_PI / 3));
    CHECK_MSG(out[3] == 2 && fabs(out[4] - mid_y) < 1e-14 && fabs(out[5] - mid_z) < 1e-14, "halfway: %g %g %g",
              out[3], out[4], out[5]);
}

static void test_failures(void)
{
    cm_result *r = fixture_result(FIX_TWISTED, N);
    if (!r) {
        CHECK(0);
        return;
    }
    cm_morph *m = NULL, *lin = NULL;
    cm_morph_options mo;
    cm_morph_options_init(&mo);
    mo.method = CM_MORPH_LINEAR;
    CHECK(cm_morph_create(r, NULL, &m) == CM_OK && cm_morph_create(r, &mo, &lin) == CM_OK);
    cm_sweep_options o;
    cm_sweep *w = NULL;

    cm_sweep_options_init(&o);
    CHECK(cm_sweep_create(lin, &o, &w) == CM_ERR_INTERNAL && strstr(cm_sweep_message(w), "inverted"));
    CHECK(cm_sweep_num_prisms(w) == 0 && cm_sweep_prisms(w) == NULL);
    cm_sweep_free(w);

    /* The convex morph's tetrahedra of the three-geometry fixture need 9
     * inserted sections, the intrinsic morph's 8: with 8 allowed, the sweep
     * is built from the intrinsic morph; with none, both fail. */
    cm_result *three = fixture_result(FIX_THREE, N);
    cm_morph *mc = NULL, *mi = NULL;
    cm_morph_options_init(&mo);
    mo.method = CM_MORPH_INTRINSIC;
    CHECK(three && cm_morph_create(three, NULL, &mc) == CM_OK && cm_morph_create(three, &mo, &mi) == CM_OK);
    o.tets = 1;
    o.max_refine = 8;
    cm_status s = cm_sweep_create(mc, &o, &w);
    CHECK_MSG(s == CM_OK && cm_sweep_morph_method(w) == CM_MORPH_INTRINSIC, "%s", cm_sweep_message(w));
    CHECK(cm_sweep_num_sections(w) > 2 * o.sections - 1 && cm_sweep_volume(w) > 0);
    cm_sweep_free(w);
    o.max_refine = 0;
    s = cm_sweep_create(mc, &o, &w);
    CHECK_MSG(s == CM_ERR_INTERNAL && strstr(cm_sweep_message(w), "max_refine") && cm_sweep_num_tets(w) == 0,
              "%s", cm_sweep_message(w));
    cm_sweep_free(w);
    s = cm_sweep_create(mi, &o, &w);
    CHECK_MSG(s == CM_ERR_INTERNAL && strstr(cm_sweep_message(w), "max_refine"), "%s", cm_sweep_message(w));
    cm_sweep_free(w);
    cm_morph_free(mc), cm_morph_free(mi);
    cm_result_free(three);

    cm_sweep_options_init(&o);
    o.sections = 1;
    CHECK(cm_sweep_create(m, &o, &w) == CM_ERR_ARGUMENT && strstr(cm_sweep_message(w), "sections"));
    cm_sweep_free(w);
    cm_sweep_options_init(&o);
    o.height = -1;
    CHECK(cm_sweep_create(m, &o, &w) == CM_ERR_ARGUMENT && strstr(cm_sweep_message(w), "height"));
    cm_sweep_free(w);
    double flat[2] = {1.0, 1.0};
    cm_sweep_options_init(&o);
    o.heights = flat;
    CHECK(cm_sweep_create(m, &o, &w) == CM_ERR_ARGUMENT && strstr(cm_sweep_message(w), "increase"));
    cm_sweep_free(w);
    cm_sweep_options_init(&o);
    o.progress = cancel_now;
    CHECK(cm_sweep_create(m, &o, &w) == CM_ERR_CANCELLED);
    cm_sweep_free(w);
    CHECK(cm_sweep_create(NULL, NULL, &w) == CM_ERR_ARGUMENT && strstr(cm_sweep_message(w), "morph"));
    cm_sweep_free(w);
    CHECK(cm_sweep_create(m, NULL, NULL) == CM_ERR_ARGUMENT);
    cm_sweep_free(NULL);
    CHECK(cm_sweep_message(NULL) != NULL && cm_sweep_num_nodes(NULL) == 0);
    cm_morph_free(lin);
    cm_morph_free(m);
    cm_result_free(r);
}

int main(void)
{
    static const double three_heights[3] = {0.0, 0.25, 2.0};
    test_sweep(FIX_TWISTED, NULL, 1, CM_MORPH_CONVEX);
    test_sweep(FIX_SPIRAL, NULL, 0, CM_MORPH_CONVEX); /* the blends alone need one more section */
    test_sweep(FIX_SPIRAL, NULL, 1, CM_MORPH_CONVEX);
    test_sweep(FIX_GLYPH, NULL, 1, CM_MORPH_CONVEX);
    test_sweep(FIX_THREE, three_heights, 1, CM_MORPH_CONVEX);
    test_default_height_and_quality();
    test_sweep(FIX_SPIRAL, NULL, 1, CM_MORPH_INTRINSIC);
    test_sweep(FIX_THREE, three_heights, 1, CM_MORPH_INTRINSIC);
    test_walls_at_corners();
    test_ruled();
    test_sections_for_edges();
    test_cells_quality();
    test_loft();
    test_failures();
    return check_summary("test_sweep");
}
