/* cm_font_soak: compatible triangulations of real glyph pairs, each result
 * checked by the independent exact checker (tests/core/result_check.h).
 *
 *   cm_font_soak [--pairs N] [--first I] [--seed S] [--nmin A] [--nmax B]
 *                [--time-limit SEC] [--method partition|overlay]
 *                [--no-remesh] [--morph] [--max-shift E] [--out DIR]
 *                [--font-dir DIR]... [--verbose]
 *
 * Pair i (i = first .. first + N - 1) is drawn from the seed and i alone,
 * so any pair can be rerun by itself with --first i --pairs 1. It takes two
 * single-contour glyphs of different code points from the installed fonts
 * (URW base35, FreeFont, Liberation, Noto, DejaVu; or the --font-dir
 * directories), resamples both by arc length to the same n in [A, B]
 * (glyph_outline.h, as cm_gen_pairs does), and gives each polygon a random
 * rotation; one polygon in five also gets a random scale in 1e-8..1e8 and
 * a shift of up to 10^E times its size (E = 3 unless --max-shift; 15 puts
 * unit features where doubles are 1/8 apart), one pair in ten is made
 * clockwise. The default pipeline runs on it
 * (--method overlay forces the fallback construction everywhere; with
 * --no-remesh the construction is returned as built), with a time limit
 * per pair through the progress callback's cancel.
 *
 * Every pair ends as one of: valid (CM_OK and the exact check passes),
 * refused (an input error: the transformed polygons are not simple, say),
 * beyond precision (CM_ERR_PRECISION: no double positions were found for
 * Steiner vertices, e.g. a small glyph shifted far from the origin),
 * failed (CM_ERR_INTERNAL, CM_ERR_NO_MEMORY, or CM_OK that the checker
 * rejects) or timed out. Each failure is printed with what reproduces it
 * and, with --out, its polygons are written to DIR/pair_I_a.xy and _b.xy.
 * With --morph, every valid result is also morphed (convex combinations)
 * and sections at t = 0.1 .. 0.9 are checked, then swept into prisms split
 * into tetrahedra (default options: the sweep checks every prism and
 * tetrahedron exactly, so the soak asks a success and a finite volume);
 * morph and sweep failures are counted separately. Exit status 1 when anything failed. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "compatmesh/compatmesh.h"
#include "glyph_outline.h"
#include "result_check.h"

static const char *const default_dirs[] = {
    "/usr/share/fonts/opentype/urw-base35", "/usr/share/fonts/truetype/freefont",
    "/usr/share/fonts/truetype/liberation", "/usr/share/fonts/truetype/noto",
    "/usr/share/fonts/truetype/dejavu",
};

/* ---- fonts and their code points ----------------------------------------- */

typedef struct font {
    char *path;
    unsigned long *codes; /* every mapped code point */
    long ncodes;
} font;

typedef struct font_set {
    font *f;
    long count, cap;
} font_set;

static int has_font_suffix(const char *name)
{
    size_t len = strlen(name);
    return len > 4 && (strcmp(name + len - 4, ".ttf") == 0 || strcmp(name + len - 4, ".otf") == 0);
}

static int compare_paths(const void *a, const void *b)
{
    return strcmp(((const font *)a)->path, ((const font *)b)->path);
}

static int compare_codes(const void *a, const void *b)
{
    unsigned long x = *(const unsigned long *)a, y = *(const unsigned long *)b;
    return (x > y) - (x < y);
}

/* Fonts sorted by path and code points sorted: the same pairs on every
 * machine with the same fonts, whatever order the directory lists them. */
static int load_fonts(FT_Library lib, const char *const *dirs, int ndirs, font_set *s)
{
    for (int d = 0; d < ndirs; d++) {
        DIR *dir = opendir(dirs[d]);
        if (!dir) continue;
        struct dirent *e;
        while ((e = readdir(dir))) {
            if (!has_font_suffix(e->d_name)) continue;
            if (s->count == s->cap) {
                s->cap = s->cap ? 2 * s->cap : 64;
                s->f = realloc(s->f, (size_t)s->cap * sizeof *s->f);
                if (!s->f) return -1;
            }
            font *f = &s->f[s->count++];
            memset(f, 0, sizeof *f);
            f->path = malloc(strlen(dirs[d]) + strlen(e->d_name) + 2);
            if (!f->path) return -1;
            sprintf(f->path, "%s/%s", dirs[d], e->d_name);
        }
        closedir(dir);
    }
    qsort(s->f, (size_t)s->count, sizeof *s->f, compare_paths);
    long kept = 0;
    for (long i = 0; i < s->count; i++) {
        font *f = &s->f[i];
        FT_Face face;
        if (FT_New_Face(lib, f->path, 0, &face) != 0) { free(f->path); continue; }
        long cap = 0;
        FT_UInt index;
        for (FT_ULong c = FT_Get_First_Char(face, &index); index != 0;
             c = FT_Get_Next_Char(face, c, &index)) {
            if (f->ncodes == cap) {
                cap = cap ? 2 * cap : 256;
                f->codes = realloc(f->codes, (size_t)cap * sizeof *f->codes);
                if (!f->codes) return -1;
            }
            f->codes[f->ncodes++] = c;
        }
        FT_Done_Face(face);
        if (f->ncodes < 2) { free(f->path), free(f->codes); continue; }
        qsort(f->codes, (size_t)f->ncodes, sizeof *f->codes, compare_codes);
        s->f[kept++] = *f;
    }
    s->count = kept;
    return 0;
}

/* ---- seeded randomness -------------------------------------------------- */

static uint64_t mix(uint64_t z)
{
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static uint64_t next(uint64_t *state) { return mix((*state)++ * 0xD1B54A32D192ED03ull); }
static double uniform(uint64_t *state) { return (double)(next(state) >> 11) * 0x1.0p-53; }

/* ---- one pair ------------------------------------------------------------ */

typedef struct glyph_pick {
    long font;
    unsigned long code;
} glyph_pick;

/* A random glyph with exactly one contour, resampled to n points; tries a
 * bounded number of draws (most code points of most fonts qualify). */
static int pick_glyph(FT_Library lib, const font_set *s, uint64_t *rng, int n,
                      unsigned long avoid, glyph_pick *pick, double *xy)
{
    for (int attempt = 0; attempt < 200; attempt++) {
        long fi = (long)(next(rng) % (uint64_t)s->count);
        const font *f = &s->f[fi];
        unsigned long code = f->codes[next(rng) % (uint64_t)f->ncodes];
        if (code == avoid) continue;
        FT_Face face;
        if (FT_New_Face(lib, f->path, 0, &face) != 0) continue;
        int ok = FT_Load_Char(face, code, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0 &&
                 face->glyph->format == FT_GLYPH_FORMAT_OUTLINE &&
                 face->glyph->outline.n_contours == 1;
        outline o = {0};
        ok = ok && glyph_outline(face, code, &o) == 0 && resample(&o, n, xy) == 0;
        outline_free(&o);
        FT_Done_Face(face);
        if (ok) {
            pick->font = fi, pick->code = code;
            return 0;
        }
    }
    return -1;
}

typedef struct transform {
    double angle, scale, dx, dy;
} transform;

/* Rotation about the origin, then scale and shift. The scale is a power of
 * ten in 1e-8..1e8 for one polygon in five, else 1; the shift is up to
 * 10^max_shift times the polygon's size. */
static void random_transform(uint64_t *rng, double max_shift, transform *t)
{
    t->angle = 2 * RP_PI * uniform(rng);
    t->scale = 1, t->dx = 0, t->dy = 0;
    if (uniform(rng) < 0.2) {
        t->scale = pow(10.0, floor(17 * uniform(rng)) - 8);
        double reach = t->scale * pow(10.0, max_shift * uniform(rng));
        t->dx = reach * (2 * uniform(rng) - 1);
        t->dy = reach * (2 * uniform(rng) - 1);
    }
}

static void apply(const transform *t, double *xy, int n)
{
    double c = cos(t->angle), s = sin(t->angle);
    for (int i = 0; i < n; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        xy[2 * i] = (c * x - s * y) * t->scale + t->dx;
        xy[2 * i + 1] = (s * x + c * y) * t->scale + t->dy;
    }
}

/* ---- the run ------------------------------------------------------------- */

typedef struct deadline {
    struct timespec start;
    double limit;
    int expired;
} deadline;

static double elapsed(const struct timespec *start)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - start->tv_sec) + 1e-9 * (double)(now.tv_nsec - start->tv_nsec);
}

static int on_progress(void *user, double fraction, const char *stage)
{
    (void)fraction, (void)stage;
    deadline *d = user;
    if (d->limit > 0 && elapsed(&d->start) > d->limit) d->expired = 1;
    return d->expired;
}

static int write_xy(const char *path, const double *xy, int n)
{
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    for (int i = 0; i < n; i++) fprintf(f, "%.17g %.17g\n", xy[2 * i], xy[2 * i + 1]);
    return fclose(f) == 0 ? 0 : -1;
}

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

typedef struct counts {
    long valid, refused, precision, failed, timeout, skipped, morph_ok, morph_precision, morph_failed;
    double seconds;
} counts;

/* Sections strictly inside (0, 1): the ends are the result itself; then
 * the sweep. Returns 1 when both hold, 0 when one failed, 2 when one ended
 * beyond double precision (CM_ERR_PRECISION). */
static int morph_check(const cm_result *r, char *why, size_t size)
{
    cm_morph_options mo;
    cm_morph_options_init(&mo);
    cm_morph *m = NULL;
    cm_status s = cm_morph_create(r, &mo, &m);
    int ok = s == CM_OK;
    if (!ok) snprintf(why, size, "morph: %s: %s", cm_status_string(s), m ? cm_morph_message(m) : "");
    double *xy = malloc(2 * cm_result_num_vertices(r) * sizeof *xy);
    for (int step = 1; ok && xy && step < 10; step++) {
        size_t inverted = 0;
        s = cm_morph_section(m, step / 10.0, xy, &inverted, NULL);
        if (s != CM_OK || inverted) {
            snprintf(why, size, "morph section t=%.1f: %s, %zu inverted: %s", step / 10.0,
                     cm_status_string(s), inverted, cm_morph_message(m));
            ok = 0;
        }
    }
    free(xy);
    if (ok) {
        cm_sweep_options so;
        cm_sweep_options_init(&so);
        so.tets = 1;
        cm_sweep *w = NULL;
        s = cm_sweep_create(m, &so, &w);
        cm_sweep_quality q;
        cm_sweep_get_quality(w, &q);
        if (s != CM_OK || !isfinite(cm_sweep_volume(w))) {
            snprintf(why, size, "sweep: %s, smallest scaled Jacobian %g: %s", cm_status_string(s),
                     q.min_scaled_jacobian, w ? cm_sweep_message(w) : "");
            ok = 0;
        }
        cm_sweep_free(w);
    }
    cm_morph_free(m);
    return ok ? 1 : s == CM_ERR_PRECISION ? 2 : 0;
}

int main(int argc, char **argv)
{
    long pairs = 1000, first = 0;
    uint64_t seed = 1;
    int nmin = 30, nmax = 300, remesh = 1, morph = 0, verbose = 0;
    double limit = 60, max_shift = 3;
    cm_method method = CM_METHOD_PARTITION;
    const char *out = NULL;
    const char *dirs[64];
    int ndirs = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--no-remesh") == 0) remesh = 0;
        else if (strcmp(a, "--morph") == 0) morph = 1;
        else if (strcmp(a, "--verbose") == 0) verbose = 1;
        else if (!v) goto usage;
        else if (strcmp(a, "--pairs") == 0) pairs = atol(v), i++;
        else if (strcmp(a, "--first") == 0) first = atol(v), i++;
        else if (strcmp(a, "--seed") == 0) seed = strtoull(v, NULL, 10), i++;
        else if (strcmp(a, "--nmin") == 0) nmin = atoi(v), i++;
        else if (strcmp(a, "--nmax") == 0) nmax = atoi(v), i++;
        else if (strcmp(a, "--time-limit") == 0) limit = atof(v), i++;
        else if (strcmp(a, "--max-shift") == 0) max_shift = atof(v), i++;
        else if (strcmp(a, "--out") == 0) out = v, i++;
        else if (strcmp(a, "--font-dir") == 0 && ndirs < 64) dirs[ndirs++] = v, i++;
        else if (strcmp(a, "--method") == 0 && strcmp(v, "overlay") == 0) method = CM_METHOD_OVERLAY, i++;
        else if (strcmp(a, "--method") == 0 && strcmp(v, "partition") == 0) method = CM_METHOD_PARTITION, i++;
        else goto usage;
    }
    if (pairs < 0 || first < 0 || nmin < 3 || nmax < nmin) goto usage;
    if (out && mkdir(out, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "cm_font_soak: cannot create %s: %s\n", out, strerror(errno));
        return 2;
    }

    FT_Library lib;
    font_set fonts = {0};
    if (FT_Init_FreeType(&lib) != 0) return 2;
    if (ndirs == 0)
        for (size_t d = 0; d < sizeof default_dirs / sizeof *default_dirs; d++) dirs[ndirs++] = default_dirs[d];
    if (load_fonts(lib, dirs, ndirs, &fonts) != 0 || fonts.count == 0) {
        fprintf(stderr, "cm_font_soak: no fonts found (Debian packages fonts-urw-base35 "
                        "fonts-freefont-ttf fonts-liberation fonts-noto-core fonts-dejavu-core)\n");
        return 2;
    }
    printf("cm_font_soak: %ld fonts, pairs %ld..%ld, seed %llu, n %d..%d, %s%s, limit %g s\n",
           fonts.count, first, first + pairs - 1, (unsigned long long)seed, nmin, nmax,
           method == CM_METHOD_OVERLAY ? "overlay" : "partition", remesh ? " + remesh" : "", limit);
    fflush(stdout);

    double *xy = malloc(2 * (size_t)nmax * 2 * sizeof *xy);
    counts c = {0};
    struct timespec all;
    clock_gettime(CLOCK_MONOTONIC, &all);
    for (long i = first; i < first + pairs; i++) {
        uint64_t rng = mix(seed * 0x100000001B3ull ^ mix((uint64_t)i));
        int n = nmin + (int)(next(&rng) % (uint64_t)(nmax - nmin + 1));
        glyph_pick g[2];
        transform t[2];
        double *p[2] = {xy, xy + 2 * (size_t)n};
        if (pick_glyph(lib, &fonts, &rng, n, (unsigned long)-1, &g[0], p[0]) != 0 ||
            pick_glyph(lib, &fonts, &rng, n, g[0].code, &g[1], p[1]) != 0) {
            c.skipped++;
            continue;
        }
        for (int j = 0; j < 2; j++) {
            random_transform(&rng, max_shift, &t[j]);
            apply(&t[j], p[j], n);
        }
        int clockwise = uniform(&rng) < 0.1;
        if (clockwise)
            for (int j = 0; j < 2; j++) rp_reverse(p[j], 0, n - 1);

        deadline d = {.limit = limit};
        clock_gettime(CLOCK_MONOTONIC, &d.start);
        cm_options o;
        cm_options_init(&o);
        o.method = method, o.remesh = remesh;
        o.progress = on_progress, o.progress_user = &d;
        cm_result *r = NULL;
        cm_status s = cm_triangulate(xy, 2, (size_t)n, &o, &r);
        char why[512] = "";
        const char *verdict;
        if (s == CM_OK && !rc_check(r, (const double *const *)p, 2, (size_t)n, why, sizeof why)) {
            verdict = "failed", c.failed++;
        } else if (s == CM_OK) {
            verdict = "valid", c.valid++;
            if (morph) {
                int m = morph_check(r, why, sizeof why);
                if (m == 1) c.morph_ok++;
                else if (m == 2) verdict = "morph-precision", c.morph_precision++;
                else verdict = "morph-failed", c.morph_failed++;
            }
        } else if (s == CM_ERR_PRECISION) {
            verdict = "precision", c.precision++;
            snprintf(why, sizeof why, "%s: %s", cm_status_string(s), r ? cm_result_message(r) : "");
        } else if (s == CM_ERR_CANCELLED && d.expired) {
            verdict = "timeout", c.timeout++;
        } else if (s == CM_ERR_INTERNAL || s == CM_ERR_NO_MEMORY || s == CM_ERR_CANCELLED) {
            verdict = "failed", c.failed++;
            snprintf(why, sizeof why, "%s: %s", cm_status_string(s), r ? cm_result_message(r) : "");
        } else {
            verdict = "refused", c.refused++;
            snprintf(why, sizeof why, "%s: %s", cm_status_string(s), r ? cm_result_message(r) : "");
        }
        double sec = elapsed(&d.start);
        int bad = strcmp(verdict, "valid") != 0 && strcmp(verdict, "refused") != 0;
        if (bad || verbose) {
            printf("pair %ld %s n=%d %s U+%04lX / %s U+%04lX", i, verdict, n,
                   base_name(fonts.f[g[0].font].path), g[0].code,
                   base_name(fonts.f[g[1].font].path), g[1].code);
            for (int j = 0; j < 2; j++)
                if (t[j].scale != 1) printf(" %c:scale=%g,shift=(%g,%g)", 'a' + j, t[j].scale, t[j].dx, t[j].dy);
            printf("%s %.2fs%s%s\n", clockwise ? " clockwise" : "", sec, why[0] ? " " : "", why);
            fflush(stdout);
        }
        if (bad && out) {
            char path[4096];
            for (int j = 0; j < 2; j++) {
                snprintf(path, sizeof path, "%s/pair_%ld_%c.xy", out, i, 'a' + j);
                if (write_xy(path, p[j], n) != 0)
                    fprintf(stderr, "cm_font_soak: cannot write %s: %s\n", path, strerror(errno));
            }
        }
        cm_result_free(r);
    }
    c.seconds = elapsed(&all);
    printf("cm_font_soak: %ld valid, %ld refused, %ld beyond precision, %ld failed, %ld timed out, %ld skipped",
           c.valid, c.refused, c.precision, c.failed, c.timeout, c.skipped);
    if (morph)
        printf("; morph and sweep %ld valid, %ld beyond precision, %ld failed", c.morph_ok, c.morph_precision,
               c.morph_failed);
    printf("; %.1f s\n", c.seconds);
    free(xy);
    for (long i = 0; i < fonts.count; i++) free(fonts.f[i].path), free(fonts.f[i].codes);
    free(fonts.f);
    FT_Done_FreeType(lib);
    return c.failed || c.morph_failed ? 1 : 0;
usage:
    fprintf(stderr, "usage: cm_font_soak [--pairs N] [--first I] [--seed S] [--nmin A] [--nmax B]\n"
                    "                    [--time-limit SEC] [--method partition|overlay] [--no-remesh]\n"
                    "                    [--morph] [--max-shift E] [--out DIR] [--font-dir DIR]...\n"
                    "                    [--verbose]\n");
    return 2;
}
