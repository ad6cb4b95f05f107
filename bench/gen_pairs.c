/* cm_gen_pairs: writes the demo and benchmark polygon pairs as .xy files.
 *
 *   cm_gen_pairs --out DIR [--set demo|bench|hard|other|scale] [--font PATH]
 *
 * Each polygon goes to DIR/NAME_a.xy, DIR/NAME_b.xy (and NAME_c.xy for a
 * triple), one "x y" line per vertex, counter-clockwise, vertices in
 * correspondence by line number. DIR/pairs.txt lists one pair per line:
 * the pair name, then its file names.
 *
 * Glyph outlines come from a TrueType font through FreeType: the outer
 * contour of a glyph, curves flattened, then resampled by arc length to n
 * points keeping the sharp corners, so two glyphs get the same n. The other
 * shapes come from tests/core/random_polygons.h. Every polygon written is
 * checked simple with the exact brute-force test there.
 *
 * The hard set (remesh_bench.py) pairs single-contour glyphs of different
 * letters from fonts Debian ships other than DejaVu, each resampled by
 * plain arc length from its bottom-left point (resample_arclength), at
 * n = 48 and 160, letters drawn with a fixed seed. Its names say the half:
 * tune_* (two fonts, for tuning) and hold_* (the other fonts and random
 * simple polygons against discs and stars, held out).
 * The other set (other_*) is made the same way from six fonts the hard set
 * does not use, with another seed: pairs no setting was tuned on.
 * The scale set measures the partition's growth: two unrelated random
 * polygons and a random polygon against a disc at n = 1,000 to 30,000
 * (the random simple polygon generator's untangling takes minutes beyond)
 * and the same made by space partitioning (spa_*) at n = 1,000 to
 * 100,000, two unrelated random stars and a star against its twisted copy
 * at n = 1,000 to 100,000; and two glyph pairs at n = 160.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "glyph_outline.h"
#include "random_polygons.h"

#define DEFAULT_FONT "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#define MAX_K 3
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* ---- feature-matched correspondence ----------------------------------- */

/* A user pairing two glyphs pairs their features: the corners of the glyph
 * with the fewest are matched, in order, to as many corners of each other
 * glyph (an order-preserving choice that puts corners at similar places of
 * their bounding boxes), and the points between two matched corners are
 * shared by arc length, the same count in every glyph. Without this, the
 * ends of a U's arms would meet the middle of an S's strokes and no mesh
 * could be good in both. */

enum { MAX_CORNERS = 64 };

typedef struct corner_list {
    int at[MAX_CORNERS]; /* outline point indices, in outline order */
    int count;
    double box[4];       /* x0 y0 x1 y1 of the outline */
} corner_list;

static int list_corners(const outline *o, corner_list *c)
{
    c->count = 0;
    c->box[0] = c->box[2] = o->xy[0];
    c->box[1] = c->box[3] = o->xy[1];
    for (int i = 0; i < o->count; i++) {
        for (int d = 0; d < 2; d++) {
            c->box[d] = fmin(c->box[d], o->xy[2 * i + d]);
            c->box[2 + d] = fmax(c->box[2 + d], o->xy[2 * i + d]);
        }
        if (o->corner[i]) {
            if (c->count == MAX_CORNERS)
                return -1;
            c->at[c->count++] = i;
        }
    }
    return 0;
}

/* Squared distance of two corners in units of their boxes. */
static double corner_cost(const outline *a, const corner_list *ca, int i,
                          const outline *b, const corner_list *cb, int j)
{
    double d = 0;
    for (int k = 0; k < 2; k++) {
        double u = (a->xy[2 * ca->at[i] + k] - ca->box[k]) / (ca->box[2 + k] - ca->box[k]);
        double v = (b->xy[2 * cb->at[j] + k] - cb->box[k]) / (cb->box[2 + k] - cb->box[k]);
        d += (u - v) * (u - v);
    }
    return d;
}

/* Picks, for each of the m corners of `a`, a corner of `b` (m <= its
 * count), in cyclic order, at the least total cost: a dynamic program over
 * every rotation. match[i] is the index into cb->at. */
static void match_corners(const outline *a, const corner_list *ca, const outline *b,
                          const corner_list *cb, int *match)
{
    int m = ca->count, M = cb->count;
    static double cost[MAX_CORNERS][MAX_CORNERS];
    static int from[MAX_CORNERS][MAX_CORNERS];
    double best = INFINITY;
    for (int r = 0; r < M; r++) {
        /* cost[i][j]: corners 0..i of a matched, i to b's (r + j) % M. */
        for (int i = 0; i < m; i++)
            for (int j = 0; j < M; j++) {
                cost[i][j] = INFINITY;
                if (j < i || j > M - m + i)
                    continue;
                double here = corner_cost(a, ca, i, b, cb, (r + j) % M);
                if (i == 0) {
                    if (j == 0)
                        cost[i][j] = here;
                    continue;
                }
                for (int q = i - 1; q < j; q++)
                    if (cost[i - 1][q] + here < cost[i][j]) {
                        cost[i][j] = cost[i - 1][q] + here;
                        from[i][j] = q;
                    }
            }
        for (int j = m - 1; j < M; j++) {
            if (!(cost[m - 1][j] < best))
                continue;
            best = cost[m - 1][j];
            for (int i = m - 1, q = j; i >= 0; i--) {
                match[i] = (r + q) % M;
                if (i > 0)
                    q = from[i][q];
            }
        }
    }
}

/* Samples the piece of `o` from point `from` to point `to` with `count`
 * points (the first at `from`), each corner inside the piece kept as a
 * point: the sub-pieces between corners share the count by length. */
static int sample_piece(const outline *o, int from, int to, int count, double *xy)
{
    int cut[MAX_CORNERS + 1], nc = 0;
    for (int i = from; nc <= MAX_CORNERS; i = (i + 1) % o->count) {
        if (i == from || o->corner[i])
            cut[nc++] = i;
        if ((i + 1) % o->count == to)
            break;
    }
    if (nc > count)
        return -1;
    double len[MAX_CORNERS + 1];
    int share[MAX_CORNERS + 1];
    for (int k = 0; k < nc; k++)
        len[k] = piece_len(o, cut[k], k + 1 < nc ? cut[k + 1] : to);
    share_points(len, nc, count, share);
    for (int k = 0, out = 0; k < nc; k++)
        for (int j = 0; j < share[k]; j++, out++)
            point_along(o, cut[k], len[k] * j / share[k], xy + 2 * out);
    return 0;
}

/* Resamples k outlines to n points each, in feature-matched
 * correspondence, checking each result simple. Returns -1 when the glyph
 * with the fewest corners has none (nothing to match) or a result is not
 * simple. */
static int resample_matched(const outline *o, int k, int n, double *const *xy)
{
    corner_list c[MAX_K];
    memset(c, 0, sizeof c);
    int fewest = 0;
    for (int g = 0; g < k; g++) {
        if (list_corners(&o[g], &c[g]) != 0)
            return -1;
        if (c[g].count < c[fewest].count)
            fewest = g;
    }
    int m = c[fewest].count;
    if (m == 0)
        return -1;
    int anchor[MAX_K][MAX_CORNERS]; /* point index of matched corner i */
    for (int g = 0; g < k; g++) {
        int match[MAX_CORNERS];
        if (g == fewest)
            for (int i = 0; i < m; i++)
                match[i] = i;
        else
            match_corners(&o[fewest], &c[fewest], &o[g], &c[g], match);
        for (int i = 0; i < m; i++)
            anchor[g][i] = c[g].at[match[i]];
    }
    /* Points per piece: by the mean share of the outline's length. */
    double len[MAX_CORNERS] = {0};
    int count[MAX_CORNERS];
    for (int g = 0; g < k; g++) {
        double total = piece_len(&o[g], 0, 0);
        for (int i = 0; i < m; i++)
            len[i] += piece_len(&o[g], anchor[g][i], anchor[g][(i + 1) % m]) / total;
    }
    if (m > n)
        return -1;
    share_points(len, m, n, count);
    for (int g = 0; g < k; g++) {
        for (int i = 0, out = 0; i < m; out += count[i], i++)
            if (sample_piece(&o[g], anchor[g][i], anchor[g][(i + 1) % m], count[i],
                             xy[g] + 2 * out) != 0)
                return -1;
        rp_snap_all(xy[g], n);
        if (!rp_is_simple(xy[g], n) || rp_signed_area2(xy[g], n) <= 0)
            return -1;
    }
    return 0;
}

/* ---- writing ----------------------------------------------------------- */

typedef struct writer {
    const char *dir;
    FILE *list;
    FT_Library lib;
    FT_Face face;
    int pairs, failures;
} writer;

static int write_xy(const char *path, const double *xy, int n)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    for (int i = 0; i < n; i++)
        fprintf(f, "%.17g %.17g\n", xy[2 * i], xy[2 * i + 1]);
    return fclose(f) == 0 ? 0 : -1;
}

/* Writes NAME_a.xy, NAME_b.xy, ... and the pairs.txt line. */
static void emit(writer *w, const char *name, double *const *polys, int k, int n)
{
    char path[4096], files[MAX_K][256];
    for (int g = 0; g < k; g++) {
        if (!rp_is_simple(polys[g], n) || rp_signed_area2(polys[g], n) <= 0) {
            fprintf(stderr, "cm_gen_pairs: %s: polygon %c is not simple\n", name, 'a' + g);
            w->failures++;
            return;
        }
        snprintf(files[g], sizeof files[g], "%s_%c.xy", name, 'a' + g);
        snprintf(path, sizeof path, "%s/%s", w->dir, files[g]);
        if (write_xy(path, polys[g], n) != 0) {
            fprintf(stderr, "cm_gen_pairs: cannot write %s: %s\n", path, strerror(errno));
            w->failures++;
            return;
        }
    }
    fprintf(w->list, "%s", name);
    for (int g = 0; g < k; g++)
        fprintf(w->list, " %s", files[g]);
    fputc('\n', w->list);
    w->pairs++;
}

/* Buffers for up to MAX_K polygons of n vertices. */
typedef struct polys {
    double *xy[MAX_K];
} polys;

static int polys_alloc(polys *p, int n)
{
    for (int g = 0; g < MAX_K; g++)
        p->xy[g] = malloc(sizeof(double) * 2 * n);
    return p->xy[0] && p->xy[1] && p->xy[2] ? 0 : -1;
}

static void polys_free(polys *p)
{
    for (int g = 0; g < MAX_K; g++)
        free(p->xy[g]);
}

static void report_failure(writer *w, const char *name, const char *why)
{
    fprintf(stderr, "cm_gen_pairs: %s: %s\n", name, why);
    w->failures++;
}

/* ---- the pairs --------------------------------------------------------- */

/* Glyphs given as a string, one character per polygon, in feature-matched
 * correspondence (each resampled on its own, from its bottom-left, when
 * that fails). */
static void glyph_set(writer *w, const char *name, const char *chars, int n)
{
    polys p = {{0}};
    outline o[MAX_K] = {{0}};
    int k = (int)strlen(chars), ok = k <= MAX_K && polys_alloc(&p, n) == 0;
    for (int g = 0; ok && g < k; g++)
        ok = glyph_outline(w->face, (unsigned char)chars[g], &o[g]) == 0;
    if (ok && resample_matched(o, k, n, p.xy) != 0)
        for (int g = 0; ok && g < k; g++)
            ok = resample(&o[g], n, p.xy[g]) == 0;
    for (int g = 0; g < k; g++)
        outline_free(&o[g]);
    if (ok)
        emit(w, name, p.xy, k, n);
    else
        report_failure(w, name, "glyph outline could not be resampled simple");
    polys_free(&p);
}

static void glyph_pair(writer *w, const char *chars, int n)
{
    char name[64];
    snprintf(name, sizeof name, "glyph_%c_%c_n%d", chars[0], chars[1], n);
    glyph_set(w, name, chars, n);
}

/* Two unrelated polygons of one generator (seeds 2 seed and 2 seed + 1). */
static void unrelated_pair(writer *w, const char *name, int n, uint64_t seed,
                           int (*generate)(double *, int, uint64_t), const char *failure)
{
    polys p;
    if (polys_alloc(&p, n) == 0 && generate(p.xy[0], n, 2 * seed) == 0 && generate(p.xy[1], n, 2 * seed + 1) == 0)
        emit(w, name, p.xy, 2, n);
    else
        report_failure(w, name, failure);
    polys_free(&p);
}

/* Two unrelated random stars. */
static void star_pair(writer *w, const char *name, int n, uint64_t seed)
{
    unrelated_pair(w, name, n, seed, rp_star, "star generator failed");
}

/* A star against itself with the correspondence turned by `shift`. */
static void twist_pair(writer *w, const char *name, int n, int shift, uint64_t seed)
{
    polys p;
    if (polys_alloc(&p, n) == 0 && rp_star(p.xy[0], n, seed) == 0) {
        memcpy(p.xy[1], p.xy[0], sizeof(double) * 2 * n);
        rp_twist(p.xy[1], n, shift);
        emit(w, name, p.xy, 2, n);
    } else {
        report_failure(w, name, "star generator failed");
    }
    polys_free(&p);
}

/* A disc whose vertex 0 sits at `angle` (radians): lines up the starts. */
static int disc_from(double *xy, int n, double angle)
{
    if (rp_disc(xy, n) != 0)
        return -1;
    int shift = (int)lround(angle / (2 * RP_PI) * n);
    rp_twist(xy, n, shift);
    return 0;
}

static void spiral_pair(writer *w, const char *name, int n, double turns)
{
    polys p;
    if (polys_alloc(&p, n) == 0 && rp_spiral(p.xy[0], n, turns) == 0 &&
        disc_from(p.xy[1], n, 0) == 0)
        emit(w, name, p.xy, 2, n);
    else
        report_failure(w, name, "spiral generator failed");
    polys_free(&p);
}

/* The comb starts at its bottom-left corner, the disc at 225 degrees. */
static void comb_pair(writer *w, const char *name, int n, int teeth)
{
    polys p;
    if (polys_alloc(&p, n) == 0 && rp_comb(p.xy[0], n, teeth) == 0 &&
        disc_from(p.xy[1], n, 1.25 * RP_PI) == 0)
        emit(w, name, p.xy, 2, n);
    else
        report_failure(w, name, "comb generator failed");
    polys_free(&p);
}

/* A generated polygon against a disc starting at angle 0. */
static void against_disc(writer *w, const char *name, int n, uint64_t seed,
                         int (*generate)(double *, int, uint64_t), const char *failure)
{
    polys p;
    if (polys_alloc(&p, n) == 0 && generate(p.xy[0], n, seed) == 0 && disc_from(p.xy[1], n, 0) == 0)
        emit(w, name, p.xy, 2, n);
    else
        report_failure(w, name, failure);
    polys_free(&p);
}

static void random_pair(writer *w, const char *name, int n, uint64_t seed)
{
    against_disc(w, name, n, seed, rp_random_simple, "random simple polygon generator failed");
}

static void demo_set(writer *w)
{
    glyph_set(w, "U_S", "US", 60);
    glyph_set(w, "U_S_C", "USC", 60);
    glyph_set(w, "L_T", "LT", 40);
    star_pair(w, "stars", 40, 1);
    twist_pair(w, "twisted_star", 30, 10, 2);
    spiral_pair(w, "spiral_disc", 80, 2);
    comb_pair(w, "comb_disc", 64, 6);
}

static void bench_set(writer *w)
{
    static const char *glyphs[] = {"US", "CG", "LT", "2Z"};
    static const int glyph_n[] = {40, 80, 160, 320};
    static const int star_n[] = {16, 50, 100, 250, 500, 1000, 2000};
    static const int spiral_n[] = {50, 100, 250, 500, 1000, 2000};
    static const double spiral_turns[] = {2, 3, 4, 5, 6, 8};
    static const int twist_n[] = {16, 100, 500};
    static const int comb_n[] = {50, 100, 250, 500, 1000};
    static const int random_n[] = {16, 50, 100, 250};
    char name[64];
    for (int g = 0; g < COUNT(glyphs); g++)
        for (int i = 0; i < COUNT(glyph_n); i++)
            glyph_pair(w, glyphs[g], glyph_n[i]);
    for (int i = 0; i < COUNT(star_n); i++) {
        snprintf(name, sizeof name, "star_n%d", star_n[i]);
        star_pair(w, name, star_n[i], (uint64_t)star_n[i]);
    }
    for (int i = 0; i < COUNT(spiral_n); i++) {
        int n = spiral_n[i];
        snprintf(name, sizeof name, "spiral_disc_n%d", n);
        spiral_pair(w, name, n, spiral_turns[i]);
    }
    for (int i = 0; i < COUNT(twist_n); i++) {
        snprintf(name, sizeof name, "twisted_star_n%d", twist_n[i]);
        twist_pair(w, name, twist_n[i], twist_n[i] / 3, 1000 + (uint64_t)twist_n[i]);
    }
    for (int i = 0; i < COUNT(comb_n); i++) {
        snprintf(name, sizeof name, "comb_disc_n%d", comb_n[i]);
        int teeth = comb_n[i] / 10 < 24 ? comb_n[i] / 10 : 24;
        comb_pair(w, name, comb_n[i], teeth);
    }
    for (int i = 0; i < COUNT(random_n); i++) {
        snprintf(name, sizeof name, "random_disc_n%d", random_n[i]);
        random_pair(w, name, random_n[i], 2000 + (uint64_t)random_n[i]);
    }
}

/* ---- the scale set -------------------------------------------------------- */

/* Two unrelated random simple polygons. */
static void random_random_pair(writer *w, const char *name, int n, uint64_t seed)
{
    unrelated_pair(w, name, n, seed, rp_random_simple, "random simple polygon generator failed");
}

/* Two unrelated random polygons by space partitioning, and one against a
 * disc: random polygons to 100,000 vertices (2-opt stops near 30,000). */
static void spa_pair(writer *w, const char *name, int n, uint64_t seed)
{
    unrelated_pair(w, name, n, seed, rp_random_spa, "space-partitioning polygon generator failed");
}

static void spa_disc(writer *w, const char *name, int n, uint64_t seed)
{
    against_disc(w, name, n, seed, rp_random_spa, "space-partitioning polygon generator failed");
}

static void twist_third(writer *w, const char *name, int n, uint64_t seed)
{
    twist_pair(w, name, n, n / 3, seed);
}

/* The partition's growth with n: random polygons by 2-opt up to 30,000
 * vertices and by space partitioning up to 100,000, stars up to 100,000,
 * and glyph pairs at n = 160. */
static void scale_set(writer *w)
{
    static const int random_n[] = {1000, 3000, 10000, 30000, 0};
    static const int scale_n[] = {1000, 3000, 10000, 30000, 100000, 0};
    static const struct {
        const char *prefix;
        const int *sizes;
        void (*make)(writer *, const char *, int, uint64_t);
        uint64_t seed; /* plus n */
    } families[] = {
        {"random_pair", random_n, random_random_pair, 5000}, {"random_disc", random_n, random_pair, 2000},
        {"spa_pair", scale_n, spa_pair, 7000},               {"spa_disc", scale_n, spa_disc, 3000},
        {"star", scale_n, star_pair, 0},                     {"twisted_star", scale_n, twist_third, 1000},
    };
    char name[64];
    for (int f = 0; f < COUNT(families); f++)
        for (const int *n = families[f].sizes; *n; n++) {
            snprintf(name, sizeof name, "%s_n%d", families[f].prefix, *n);
            families[f].make(w, name, *n, families[f].seed + (uint64_t)*n);
        }
    glyph_pair(w, "US", 160);
    glyph_pair(w, "CG", 160);
}

/* ---- the hard set -------------------------------------------------------- */

#define HARD_FONT_DIR "/usr/share/fonts/"
#define HARD_SEED 20261124u
#define OTHER_SEED 20261129u

/* Font file (under HARD_FONT_DIR), its short name, its half (tune, hold:
 * the hard set; other: the other set), and how many letter pairs it
 * gives. */
typedef struct hard_font {
    const char *file, *name, *half;
    int pairs;
} hard_font;

static const hard_font hard_fonts[] = {
    {"truetype/freefont/FreeSerifItalic.ttf", "FreeSerifItalic", "tune", 10},
    {"opentype/urw-base35/P052-Roman.otf", "P052", "tune", 10},
    {"opentype/urw-base35/NimbusSans-Regular.otf", "NimbusSans", "hold", 4},
    {"opentype/urw-base35/Z003-MediumItalic.otf", "Z003", "hold", 4},
    {"opentype/urw-base35/URWBookman-Light.otf", "URWBookman", "hold", 4},
    {"opentype/urw-base35/C059-Roman.otf", "C059", "hold", 4},
    {"truetype/liberation/LiberationSerif-Regular.ttf", "LiberationSerif", "hold", 4},
    {"truetype/noto/NotoSans-Regular.ttf", "NotoSans", "hold", 4},
    /* the other set: none of the hard set's fonts */
    {"opentype/urw-base35/URWGothic-Book.otf", "URWGothic", "other", 5},
    {"opentype/urw-base35/NimbusRoman-Italic.otf", "NimbusRomanItalic", "other", 5},
    {"truetype/dejavu/DejaVuSans-Bold.ttf", "DejaVuSansBold", "other", 5},
    {"opentype/urw-base35/NimbusSansNarrow-Regular.otf", "NimbusSansNarrow", "other", 5},
    {"truetype/freefont/FreeSans.ttf", "FreeSans", "other", 5},
    {"truetype/liberation/LiberationSans-Bold.ttf", "LiberationSansBold", "other", 5},
};
static const int hard_n[] = {48, 160};
/* Letters and digits that have one contour in most fonts; a font's own
 * glyph is used only when it has exactly one. */
static const char hard_chars[] = "CEFGHIJKLMNSTUVWXYZ12357cfhklmnrstuvwxyz";

static int single_contour(FT_Face face, char c)
{
    return FT_Load_Char(face, (unsigned char)c, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0 &&
           face->glyph->format == FT_GLYPH_FORMAT_OUTLINE && face->glyph->outline.n_contours == 1;
}

/* Both glyphs resampled by arc length at every n of the hard set. */
static int hard_glyphs_sample(FT_Face face, char a, char b, polys *p)
{
    outline o[2] = {{0}};
    int ok = glyph_outline(face, (unsigned char)a, &o[0]) == 0 &&
             glyph_outline(face, (unsigned char)b, &o[1]) == 0;
    for (int i = 0; ok && i < COUNT(hard_n); i++)
        for (int g = 0; ok && g < 2; g++)
            ok = resample_arclength(&o[g], hard_n[i], p[i].xy[g]) == 0;
    outline_free(&o[0]);
    outline_free(&o[1]);
    return ok ? 0 : -1;
}

/* f->pairs pairs of different single-contour letters of one font, drawn
 * from rng without repeating a pair, each written at every n. */
static void hard_font_pairs(writer *w, const hard_font *f, rp_rng *rng)
{
    char path[4096], name[128], used[64][2];
    FT_Face face;
    snprintf(path, sizeof path, "%s%s", HARD_FONT_DIR, f->file);
    if (FT_New_Face(w->lib, path, 0, &face) != 0) {
        report_failure(w, path, "cannot open font (Debian packages fonts-urw-base35 "
                                "fonts-freefont-ttf fonts-liberation fonts-noto-core)");
        return;
    }
    char chars[sizeof hard_chars];
    int nchars = 0;
    for (const char *c = hard_chars; *c; c++)
        if (single_contour(face, *c))
            chars[nchars++] = *c;
    polys p[COUNT(hard_n)];
    for (int i = 0; i < COUNT(hard_n); i++)
        if (polys_alloc(&p[i], hard_n[i]) != 0) {
            report_failure(w, f->name, "out of memory");
            return;
        }
    int made = 0;
    for (int draw = 0; nchars >= 2 && made < f->pairs && draw < 1000; draw++) {
        char a = chars[rp_below(rng, nchars)], b = chars[rp_below(rng, nchars)];
        int seen = a == b;
        for (int k = 0; k < made; k++)
            seen |= (used[k][0] == a && used[k][1] == b) || (used[k][0] == b && used[k][1] == a);
        if (seen || hard_glyphs_sample(face, a, b, p) != 0)
            continue;
        used[made][0] = a;
        used[made++][1] = b;
        for (int i = 0; i < COUNT(hard_n); i++) {
            snprintf(name, sizeof name, "%s_%s_%c_%c_n%d", f->half, f->name, a, b, hard_n[i]);
            emit(w, name, p[i].xy, 2, hard_n[i]);
        }
    }
    if (made < f->pairs)
        report_failure(w, f->name, "too few letter pairs resample simple");
    for (int i = 0; i < COUNT(hard_n); i++)
        polys_free(&p[i]);
    FT_Done_Face(face);
}

/* A random simple polygon against a disc or a random star, both starting
 * at their bottom-left vertex. */
static void hard_shape_pair(writer *w, const char *other, int n, uint64_t seed)
{
    char name[64];
    polys p;
    snprintf(name, sizeof name, "hold_random_%s_n%d_s%llu", other, n, (unsigned long long)seed);
    int ok = polys_alloc(&p, n) == 0 && rp_random_simple(p.xy[0], n, seed) == 0 &&
             (strcmp(other, "disc") == 0 ? rp_disc(p.xy[1], n) : rp_star(p.xy[1], n, seed)) == 0;
    if (ok) {
        for (int g = 0; g < 2; g++)
            rp_twist(p.xy[g], n, bottom_left(p.xy[g], n));
        emit(w, name, p.xy, 2, n);
    } else {
        report_failure(w, name, "random polygon generator failed");
    }
    polys_free(&p);
}

/* The pairs of the fonts of one set (other: the other set's, else the
 * hard set's), letters drawn from seed. */
static void font_pairs(writer *w, int other, uint32_t seed)
{
    rp_rng rng = {seed};
    for (int f = 0; f < COUNT(hard_fonts); f++)
        if ((strcmp(hard_fonts[f].half, "other") == 0) == other) hard_font_pairs(w, &hard_fonts[f], &rng);
}

static void other_set(writer *w) { font_pairs(w, 1, OTHER_SEED); }

static void hard_set(writer *w)
{
    font_pairs(w, 0, HARD_SEED);
    for (int i = 0; i < COUNT(hard_n); i++)
        for (uint64_t s = 1; s <= 3; s++) {
            hard_shape_pair(w, "disc", hard_n[i], 3000 + s);
            hard_shape_pair(w, "star", hard_n[i], 4000 + s);
        }
}

/* ---- main -------------------------------------------------------------- */

static int usage(void)
{
    fprintf(stderr, "usage: cm_gen_pairs --out DIR [--set demo|bench|hard|other|scale] [--font PATH]\n");
    return 2;
}

static int make_dir(const char *dir)
{
    if (mkdir(dir, 0777) == 0 || errno == EEXIST)
        return 0;
    fprintf(stderr, "cm_gen_pairs: cannot create %s: %s\n", dir, strerror(errno));
    return -1;
}

static int open_font(const char *font, FT_Library *lib, FT_Face *face)
{
    if (FT_Init_FreeType(lib) != 0) {
        fprintf(stderr, "cm_gen_pairs: FreeType failed to start\n");
        return -1;
    }
    if (FT_New_Face(*lib, font, 0, face) != 0) {
        fprintf(stderr, "cm_gen_pairs: cannot open font %s (Debian package "
                        "fonts-dejavu-core, or pass --font)\n", font);
        FT_Done_FreeType(*lib);
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    const char *out = NULL, *set = "bench", *font = DEFAULT_FONT;
    for (int i = 1; i < argc; i++) {
        if (i + 1 < argc && strcmp(argv[i], "--out") == 0)
            out = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--set") == 0)
            set = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--font") == 0)
            font = argv[++i];
        else
            return usage();
    }
    int demo = strcmp(set, "demo") == 0, hard = strcmp(set, "hard") == 0, scale = strcmp(set, "scale") == 0;
    int other = strcmp(set, "other") == 0;
    if (!out || (!demo && !hard && !other && !scale && strcmp(set, "bench") != 0))
        return usage();

    FT_Library lib;
    writer w = {out, NULL, NULL, NULL, 0, 0};
    char list[4096];
    snprintf(list, sizeof list, "%s/pairs.txt", out);
    if (make_dir(out) != 0 || open_font(font, &lib, &w.face) != 0)
        return 1;
    w.lib = lib;
    w.list = fopen(list, "w");
    if (!w.list) {
        fprintf(stderr, "cm_gen_pairs: cannot write %s: %s\n", list, strerror(errno));
        return 1;
    }
    if (demo)
        demo_set(&w);
    else if (hard)
        hard_set(&w);
    else if (other)
        other_set(&w);
    else if (scale)
        scale_set(&w);
    else
        bench_set(&w);
    int closed = fclose(w.list);
    FT_Done_Face(w.face);
    FT_Done_FreeType(lib);
    printf("cm_gen_pairs: wrote %d %s pairs to %s\n", w.pairs, set, out);
    return w.failures || closed != 0 ? 1 : 0;
}
