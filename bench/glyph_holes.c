/* cm_glyph_holes: compatible triangulations of glyph pairs with holes from
 * DejaVu Sans (O/D, P/R, A/R, 6/9, B/8, a/e, b/d, ...), every result checked
 * by the independent exact checker (tests/core/result_check.h: loops
 * bit-identical, boundary edges exactly the loops, Euler characteristic
 * 1 - h, areas adding up in rationals).
 *
 *   cm_glyph_holes [--font PATH] [--outer N] [--hole M] [--no-remesh] [--min-good G]
 *                  [--method partition|overlay] [--auto] [--fixtures] [--markdown]
 *                  [--dump DIR] [--hole-starts|--starts|--joint-starts]
 *
 * Each glyph's outer contour is resampled by arc length to N points (default
 * 64), each hole to M (default 24), corners kept (glyph_outline.h); the
 * holes pair up top to bottom. Prints one line per pair (Steiner vertices,
 * smallest angles, the smallest input corner c, the remesher's aim) and a
 * summary; exit status 1 when a pair fails or its result is not exactly
 * valid, or when fewer than G pairs (default: 90 % of them) reach a
 * smallest angle of min(15, c / 3) degrees in both polygons. --fixtures
 * runs the pairs with holes of tests/core (hole_fixtures.h) in place of the
 * glyphs, each by the command line's default correspondence (index, auto
 * where the loops' sizes differ). --markdown prints the rows of
 * bench/holes_table.py; --dump writes every pair's loops as DIR/<pair>_a.xy
 * and _b.xy for the command line's pictures. --method overlay measures the
 * construction that always succeeds (one bridge per hole and the overlay)
 * in place of the bridges' pieces. --auto pairs every loop by the library's
 * auto correspondence (arc length from the outer loop's best aligned start
 * and every hole's start chosen under the outer loops' similarity) in place
 * of vertex by vertex from each contour's resampling start. --hole-starts
 * turns every hole of the second glyph to the start that a similarity fits
 * best (--starts: every loop; --joint-starts: the outer loop's, then every
 * hole to the start its points are nearest to under the outer loop's
 * similarity), then pairs vertex by vertex. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compatmesh/compatmesh.h"
#include "glyph_outline.h"
#include "hole_fixtures.h"
#include "result_check.h"

#define MAX_LOOPS 8

static const char *const pairs[][2] = {
    {"O", "D"}, {"P", "R"}, {"A", "R"}, {"6", "9"}, {"B", "8"}, {"a", "e"},
    {"b", "d"}, {"O", "Q"}, {"D", "P"}, {"o", "e"}, {"p", "q"}, {"4", "A"},
};

/* One glyph as loops for cm_triangulate_loops. */
typedef struct glyph_loops {
    double *xy;
    size_t sizes[MAX_LOOPS], loops;
} glyph_loops;

static int load(FT_Face face, char c, int outer, int hole, glyph_loops *g)
{
    outline o[MAX_LOOPS];
    int count = glyph_contours(face, (unsigned long)(unsigned char)c, o, MAX_LOOPS);
    if (count < 1) return -1;
    size_t total = 0;
    for (int l = 0; l < count; l++) total += (size_t)(l ? hole : outer);
    g->xy = malloc(2 * total * sizeof *g->xy);
    g->loops = (size_t)count;
    int ok = g->xy != NULL;
    for (int l = 0, at = 0; ok && l < count; l++) {
        int m = l ? hole : outer;
        g->sizes[l] = (size_t)m;
        ok = resample(&o[l], m, g->xy + 2 * at) == 0;
        at += m;
    }
    for (int l = 0; l < count; l++) outline_free(&o[l]);
    return ok ? 0 : -1;
}

/* Turns every hole of b (and, with outer_too, its outer loop) to the
 * start that fits the same loop of a best up to rotation, scale and
 * translation (the least squares residual over all cyclic shifts): each
 * loop's start chosen, vertex i still on vertex i. */
static void choose_starts(const glyph_loops *a, glyph_loops *b, int outer_too)
{
    for (size_t l = outer_too ? 0 : 1, at = outer_too ? 0 : b->sizes[0]; l < b->loops; at += b->sizes[l++]) {
        size_t m = b->sizes[l], best = 0;
        if (a->sizes[l] != m) continue;
        const double *p = a->xy + 2 * at;
        double *q = b->xy + 2 * at, pc[2] = {0, 0}, qc[2] = {0, 0}, best_fit = -1;
        for (size_t i = 0; i < m; i++)
            for (int c = 0; c < 2; c++) pc[c] += p[2 * i + c] / (double)m, qc[c] += q[2 * i + c] / (double)m;
        for (size_t shift = 0; shift < m; shift++) { /* |sum p conj(q)|^2 / |q|^2: the part a similarity explains */
            double re = 0, im = 0, qq = 0, pp = 0;
            for (size_t i = 0; i < m; i++) {
                const double *u = p + 2 * i, *v = q + 2 * ((i + shift) % m);
                double px = u[0] - pc[0], py = u[1] - pc[1], qx = v[0] - qc[0], qy = v[1] - qc[1];
                re += px * qx + py * qy, im += py * qx - px * qy, qq += qx * qx + qy * qy, pp += px * px + py * py;
            }
            double fit = (re * re + im * im) / (qq * pp);
            if (fit > best_fit) best_fit = fit, best = shift;
        }
        double *copy = malloc(2 * m * sizeof *copy);
        if (!copy) continue;
        for (size_t i = 0; i < m; i++) copy[2 * i] = q[2 * ((i + best) % m)], copy[2 * i + 1] = q[2 * ((i + best) % m) + 1];
        memcpy(q, copy, 2 * m * sizeof *q);
        free(copy);
    }
}

/* The outer loop's start as choose_starts chooses it, then every hole
 * turned to the start its points are nearest to under that one similarity
 * (the outer loop's): the holes keep their place in the glyph's frame. */
static void choose_starts_jointly(const glyph_loops *a, glyph_loops *b)
{
    choose_starts(a, b, 2);
    size_t m = b->sizes[0];
    if (a->sizes[0] != m) return;
    const double *p = a->xy, *q = b->xy;
    double pc[2] = {0, 0}, qc[2] = {0, 0}, re = 0, im = 0, pp = 0;
    for (size_t i = 0; i < m; i++)
        for (int c = 0; c < 2; c++) pc[c] += p[2 * i + c] / (double)m, qc[c] += q[2 * i + c] / (double)m;
    for (size_t i = 0; i < m; i++) { /* q - qc = z (p - pc), z = re + i im, least squares */
        double px = p[2 * i] - pc[0], py = p[2 * i + 1] - pc[1], qx = q[2 * i] - qc[0], qy = q[2 * i + 1] - qc[1];
        re += px * qx + py * qy, im += px * qy - py * qx, pp += px * px + py * py;
    }
    re /= pp, im /= pp;
    for (size_t l = 1, at = b->sizes[0]; l < b->loops; at += b->sizes[l++]) {
        size_t h = b->sizes[l], best = 0;
        if (a->sizes[l] != h) continue;
        double best_sum = -1, *hq = b->xy + 2 * at;
        const double *hp = a->xy + 2 * at;
        for (size_t shift = 0; shift < h; shift++) {
            double sum = 0;
            for (size_t i = 0; i < h; i++) {
                double px = hp[2 * i] - pc[0], py = hp[2 * i + 1] - pc[1];
                double x = qc[0] + re * px - im * py, y = qc[1] + im * px + re * py;
                const double *v = hq + 2 * ((i + shift) % h);
                sum += (x - v[0]) * (x - v[0]) + (y - v[1]) * (y - v[1]);
            }
            if (best_sum < 0 || sum < best_sum) best_sum = sum, best = shift;
        }
        double *copy = malloc(2 * h * sizeof *copy);
        if (!copy) continue;
        for (size_t i = 0; i < h; i++) copy[2 * i] = hq[2 * ((i + best) % h)], copy[2 * i + 1] = hq[2 * ((i + best) % h) + 1];
        memcpy(hq, copy, 2 * h * sizeof *hq);
        free(copy);
    }
}

/* The smallest corner of the material over every loop of both polygons
 * (degrees): a hole's corner is the outside of its loop. */
static double smallest_corner(const cm_loops *in, size_t count)
{
    double c = 360;
    for (size_t g = 0; g < count; g++)
        for (size_t l = 0, at = 0; l < in[g].num_loops; at += in[g].loop_sizes[l++]) {
            size_t m = in[g].loop_sizes[l];
            const double *xy = in[g].xy + 2 * at;
            double area2 = 0;
            for (size_t i = 0; i < m; i++)
                area2 += xy[2 * i] * xy[2 * ((i + 1) % m) + 1] - xy[2 * ((i + 1) % m)] * xy[2 * i + 1];
            double side = (area2 > 0) == (l == 0) ? 1 : -1; /* +1: the material on the left */
            for (size_t i = 0; i < m; i++) {
                const double *p = xy + 2 * ((i + m - 1) % m), *q = xy + 2 * i, *r = xy + 2 * ((i + 1) % m);
                double ux = q[0] - p[0], uy = q[1] - p[1], vx = r[0] - q[0], vy = r[1] - q[1];
                double turn = atan2(ux * vy - uy * vx, ux * vx + uy * vy) * 180 / 3.14159265358979323846;
                double corner = 180 - side * turn;
                if (corner < c) c = corner;
            }
        }
    return c;
}

/* Writes a pair's loops as dir/<name>_a.xy and _b.xy ('>' between loops,
 * what the command line reads), for its pictures. */
static void dump_pair(const char *dir, const char *name, const cm_loops in[2])
{
    for (int k = 0; k < 2; k++) {
        char path[512], clean[64];
        size_t j = 0;
        for (const char *c = name; *c && j + 1 < sizeof clean; c++) clean[j++] = *c == '/' || *c == ' ' || *c == ',' ? '_' : *c;
        clean[j] = 0;
        snprintf(path, sizeof path, "%s/%s_%c.xy", dir, clean, "ab"[k]);
        FILE *f = fopen(path, "w");
        if (!f) {
            fprintf(stderr, "cm_glyph_holes: cannot write %s\n", path);
            continue;
        }
        for (size_t l = 0, at = 0; l < in[k].num_loops; at += in[k].loop_sizes[l++]) {
            fprintf(f, "> %s\n", l ? "hole" : "outer loop");
            for (size_t i = at; i < at + in[k].loop_sizes[l]; i++) fprintf(f, "%.17g %.17g\n", in[k].xy[2 * i], in[k].xy[2 * i + 1]);
        }
        fclose(f);
    }
}

/* What run_pair measured. */
typedef struct pair_outcome {
    int valid, good;
} pair_outcome;

/* Triangulates one pair, checks it exactly and prints its row: plain, or
 * a Markdown row (source, pair, mode, holes, n, c, floor, the remesher's
 * aim, Steiner, smallest angles, valid, floor reached). good: both meshes reach min(15, c / 3). */
static pair_outcome run_pair(const char *source, const char *name, const cm_loops in[2], const cm_options *o,
                             int markdown)
{
    pair_outcome out = {0, 0};
    cm_result *r = NULL;
    cm_status s = cm_triangulate_loops(in, 2, o, &r);
    char why[256] = "";
    size_t loops = in[0].num_loops, n = 0;
    for (size_t l = 0; l < loops; l++) n += in[0].loop_sizes[l];
    /* Auto and arc length refine the loops (the other polygon's points
     * added on the edges): checked as the result reports them, loop by loop. */
    size_t refined_sizes[HF_MAX_LOOPS] = {0};
    cm_loops refined[2] = {in[0], in[1]};
    if (s == CM_OK && o->correspondence != CM_CORRESPOND_INDEX) {
        n = cm_result_stats(r)->n;
        for (size_t i = 0; i < n; i++) {
            double t;
            long e = cm_result_boundary_source(r, 0, i, &t);
            size_t l = 0, at = in[0].loop_sizes[0];
            while (l + 1 < loops && (size_t)e >= at) at += in[0].loop_sizes[++l];
            refined_sizes[l]++;
        }
        for (int k = 0; k < 2; k++) refined[k] = (cm_loops){cm_result_vertices(r, (size_t)k), refined_sizes, loops};
    }
    out.valid = s == CM_OK && rc_check_loops(r, refined, 2, why, sizeof why) &&
                rc_check_halfedges_holes(r, n, loops - 1, why, sizeof why);
    const char *mode = o->correspondence == CM_CORRESPOND_AUTO ? "auto" :
                       o->correspondence == CM_CORRESPOND_ARCLENGTH ? "arclength" : "index";
    double c = smallest_corner(in, 2), floor = c / 3 < 15 ? c / 3 : 15;
    if (!out.valid) {
        if (markdown)
            printf("| %s | %s | %s | %zu | | %.1f | %.2f | | | | **no**: %s | no |\n", source, name, mode, loops - 1, c,
                   floor, s == CM_OK ? why : cm_result_message(r));
        else
            printf("%s   FAILED: %s %s\n", name, cm_status_string(s), s == CM_OK ? why : cm_result_message(r));
        cm_result_free(r);
        return out;
    }
    const cm_stats *st = cm_result_stats(r);
    cm_quality qa, qb;
    cm_result_quality(r, 0, &qa), cm_result_quality(r, 1, &qb);
    out.good = o->remesh && qa.min_angle_deg >= floor && qb.min_angle_deg >= floor;
    if (markdown)
        printf("| %s | %s | %s | %zu | %zu | %.1f | %.2f | %.1f | %zu | %.1f / %.1f | yes | %s |\n", source, name, mode,
               st->holes, st->n, c, floor, st->remesh_aim_deg, st->steiner, qa.min_angle_deg, qb.min_angle_deg,
               out.good ? "yes" : "**no**");
    else
        printf("%-6s %5zu %6zu %8zu %8zu %8.1f %8.1f %8.1f %8.1f%s\n", name, st->holes, st->n, st->steiner_before_remesh,
               st->steiner, qa.min_angle_deg, qb.min_angle_deg, c, o->remesh ? st->remesh_aim_deg : 0,
               out.good || !o->remesh ? "" : "  (below min(15, c/3))");
    cm_result_free(r);
    return out;
}

int main(int argc, char **argv)
{
    const char *font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    int outer = 64, hole = 24, remesh = 1, min_good = -1, overlay = 0, fixtures = 0, markdown = 0, forced = 0;
    const char *dump = NULL;
    cm_correspondence correspondence = CM_CORRESPOND_INDEX;
    int starts = 0; /* 1: every hole's start chosen, 2: every loop's, 3: jointly */
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--font") && i + 1 < argc) font = argv[++i];
        else if (!strcmp(argv[i], "--outer") && i + 1 < argc) outer = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--hole") && i + 1 < argc) hole = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--no-remesh")) remesh = 0;
        else if (!strcmp(argv[i], "--method") && i + 1 < argc && !strcmp(argv[i + 1], "overlay")) overlay = 1, i++;
        else if (!strcmp(argv[i], "--method") && i + 1 < argc && !strcmp(argv[i + 1], "partition")) i++;
        else if (!strcmp(argv[i], "--auto")) correspondence = CM_CORRESPOND_AUTO, forced = 1;
        else if (!strcmp(argv[i], "--hole-starts")) starts = 1;
        else if (!strcmp(argv[i], "--starts")) starts = 2;
        else if (!strcmp(argv[i], "--joint-starts")) starts = 3;
        else if (!strcmp(argv[i], "--fixtures")) fixtures = 1;
        else if (!strcmp(argv[i], "--markdown")) markdown = 1;
        else if (!strcmp(argv[i], "--dump") && i + 1 < argc) dump = argv[++i];
        else if (!strcmp(argv[i], "--min-good") && i + 1 < argc) min_good = atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: cm_glyph_holes [--font PATH] [--outer N] [--hole M] [--no-remesh] [--min-good G]\n"
                            "                      [--method partition|overlay] [--auto] [--fixtures] [--markdown]\n"
                            "                      [--dump DIR]\n"
                            "                      [--hole-starts|--starts|--joint-starts]\n");
            return 2;
        }
    }
    cm_options o;
    cm_options_init(&o);
    o.remesh = remesh;
    if (overlay) o.method = CM_METHOD_OVERLAY;
    o.correspondence = correspondence;
    int failed = 0, good_angle = 0, total = 0;
    if (!markdown)
        printf("%-6s %5s %6s %8s %8s %8s %8s %8s %8s\n", "pair", "holes", "n", "built", "steiner", "angle_a", "angle_b",
               "c", "aim");
    if (fixtures) {
        const hole_fixture *list;
        size_t count = hole_fixture_list(&list);
        for (size_t f = 0; f < count; f++) {
            static shape a, b;
            memset(&a, 0, sizeof a), memset(&b, 0, sizeof b);
            list[f].build(&a, &b);
            int differ = a.loops != b.loops;
            for (size_t l = 0; l < a.loops && l < b.loops; l++) differ |= a.sizes[l] != b.sizes[l];
            /* the command line's and the Python module's default: index, auto where loop sizes differ */
            o.correspondence = forced ? correspondence : differ ? CM_CORRESPOND_AUTO : CM_CORRESPOND_INDEX;
            cm_loops in[2] = {{a.xy, a.sizes, a.loops}, {b.xy, b.sizes, b.loops}};
            if (dump) dump_pair(dump, list[f].name, in);
            pair_outcome po = run_pair("test_holes.c", list[f].name, in, &o, markdown);
            total++, failed += !po.valid, good_angle += po.good;
        }
    } else {
        FT_Library lib;
        FT_Face face;
        if (FT_Init_FreeType(&lib) || FT_New_Face(lib, font, 0, &face)) {
            fprintf(stderr, "cm_glyph_holes: cannot load %s (Debian package fonts-dejavu-core)\n", font);
            return 1;
        }
        for (size_t p = 0; p < sizeof pairs / sizeof pairs[0]; p++) {
            glyph_loops g[2] = {{0}, {0}};
            int loaded = load(face, pairs[p][0][0], outer, hole, &g[0]) == 0 &&
                         load(face, pairs[p][1][0], outer, hole, &g[1]) == 0;
            if (loaded && starts == 3) choose_starts_jointly(&g[0], &g[1]);
            else if (loaded && starts) choose_starts(&g[0], &g[1], starts == 2);
            char name[16];
            snprintf(name, sizeof name, "%s/%s", pairs[p][0], pairs[p][1]);
            total++;
            if (!loaded) {
                failed++;
                printf("%s   FAILED: glyph not loaded\n", name);
            } else {
                cm_loops in[2] = {{g[0].xy, g[0].sizes, g[0].loops}, {g[1].xy, g[1].sizes, g[1].loops}};
                if (dump) dump_pair(dump, name, in);
                pair_outcome po = run_pair("glyphs", name, in, &o, markdown);
                failed += !po.valid, good_angle += po.good;
            }
            free(g[0].xy), free(g[1].xy);
        }
        FT_Done_Face(face);
        FT_Done_FreeType(lib);
    }
    if (!markdown) {
        printf("cm_glyph_holes: %d pairs, %d valid, %d failed", total, total - failed, failed);
        if (remesh) printf(", %d with smallest angle >= min(15, c/3)", good_angle);
        printf("\n");
    }
    if (min_good < 0) min_good = (9 * total + 9) / 10;
    return failed || (remesh && good_angle < min_good) ? 1 : 0;
}
