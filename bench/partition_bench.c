/* cm_partition_bench: the partition method against the overlay
 * construction, side by side, without remeshing.
 *
 *   cm_partition_bench [--pairs DIR] [--hard DIR] [--cgal PATH] [--min-cpu S]
 *                      [--tsv FILE] [--out FILE] [--max-n N]
 *
 * Pairs: random star pairs (several seeds per size), stars against a
 * twisted copy, spiral against disc, comb against disc, random simple
 * polygons against each other (a stress family outside the targets), and
 * the glyph pairs of DIR/pairs.txt as written by cm_gen_pairs (--set
 * bench), and every pair of the --hard directory (--set hard). For each:
 * Steiner vertices before remeshing, fallback count, validity (the library
 * returns CM_OK only after its exact check), the time of each stage, and
 * the partition's own breakdown (visibility tables, Steiner-free program,
 * link distances and paths, overlay fallback). Writes a markdown table
 * (default bench/PARTITION.md) and prints the summary.
 *
 * Against CGAL (--cgal: bench/cgal_single.cc's binary): the partition's
 * process CPU time in this process (validate + build + check, no
 * remeshing, no ceiling; the mean over as many runs as fill --min-cpu
 * seconds, default 0.05) beside CGAL's meshing of every polygon of the
 * pair at 25 degrees, each timed inside its own process the same way
 * (process start and file reading excluded); per pair the ratio, the
 * median ratio at n <= 160, and per family the exponent of time in n
 * (least squares on log-log) where the family has several sizes. --tsv
 * writes these per pair for comparing two builds.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <time.h>
#include <unistd.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "read_xy.h"
#include "compatmesh/compatmesh.h"
#include "api/result.h"
#include "geom/polytri.h"
#include "construct/partition.h"
#include "random_polygons.h"
#include "construct/steinerfree.h"
#include "geom/visibility.h"

#define MAX_K 3
#define TARGET_N 160

typedef struct pair {
    char name[64], family[16];
    int k, n;
    double *xy[MAX_K];
} pair;

typedef struct run {
    int ok;
    size_t steiner, fallbacks;
    double validate, build, check;
    double cpu; /* process CPU seconds of one run (mean over repeats) */
} run;

typedef struct row {
    pair p;
    run part, over;
    cm_partition_stats inner;
    int possible; /* the Steiner-free program on the whole input: 1 yes,
                     0 no, -1 not run (too large) */
    double cgal;  /* CGAL's CPU seconds meshing all k polygons, -1 not run */
} row;

typedef struct bench {
    row *rows;
    int count, cap, max_n;
    const char *cgal, *tmp; /* CGAL's binary, a scratch directory */
    double min_cpu;
} bench;

/* ---- pairs ---------------------------------------------------------------- */

static pair *new_pair(bench *b, const char *name, const char *family, int k, int n)
{
    if (n > b->max_n) return NULL;
    if (b->count == b->cap) {
        int cap = b->cap ? 2 * b->cap : 64;
        row *r = realloc(b->rows, sizeof *r * (size_t)cap);
        if (!r) return NULL;
        b->rows = r, b->cap = cap;
    }
    row *r = &b->rows[b->count];
    memset(r, 0, sizeof *r);
    snprintf(r->p.name, sizeof r->p.name, "%s", name);
    snprintf(r->p.family, sizeof r->p.family, "%s", family);
    r->p.k = k, r->p.n = n;
    for (int g = 0; g < k; g++) {
        r->p.xy[g] = malloc(sizeof(double) * 2 * (size_t)n);
        if (!r->p.xy[g]) return NULL;
    }
    return &r->p;
}

static void keep(bench *b, pair *p, int ok)
{
    if (!p) return;
    if (ok == 0) {
        b->count++;
        return;
    }
    for (int g = 0; g < p->k; g++) free(p->xy[g]);
    fprintf(stderr, "cm_partition_bench: %s: generator failed\n", p->name);
}

/* A disc whose vertex 0 sits at `angle`, as cm_gen_pairs does. */
static int disc_from(double *xy, int n, double angle)
{
    if (rp_disc(xy, n) != 0) return -1;
    rp_twist(xy, n, (int)lround(angle / (2 * RP_PI) * n));
    return 0;
}

static void synthetic_pairs(bench *b)
{
    static const int star_n[] = {16, 50, 100, 160, 250, 500, 1000, 2000};
    static const int twist_n[] = {16, 50, 100, 160, 500, 1000};
    static const int spiral_n[] = {50, 100, 160, 500, 1000, 2000};
    static const int comb_n[] = {50, 100, 160, 500, 1000};
    static const int random_n[] = {16, 32, 50, 100};
    char name[64];
    for (size_t i = 0; i < sizeof star_n / sizeof *star_n; i++)
        for (int seed = 1; seed <= (star_n[i] <= TARGET_N ? 5 : 1); seed++) {
            int n = star_n[i];
            snprintf(name, sizeof name, "star_n%d_s%d", n, seed);
            pair *p = new_pair(b, name, "star", 2, n);
            keep(b, p, p ? rp_star(p->xy[0], n, 2 * (uint64_t)(n + seed)) | rp_star(p->xy[1], n, 2 * (uint64_t)(n + seed) + 1) : 0);
        }
    for (size_t i = 0; i < sizeof twist_n / sizeof *twist_n; i++) {
        int n = twist_n[i];
        snprintf(name, sizeof name, "twisted_star_n%d", n);
        pair *p = new_pair(b, name, "twisted", 2, n);
        int ok = p ? rp_star(p->xy[0], n, 1000 + (uint64_t)n) : 0;
        if (p && ok == 0) {
            memcpy(p->xy[1], p->xy[0], sizeof(double) * 2 * (size_t)n);
            rp_twist(p->xy[1], n, n / 3);
        }
        keep(b, p, ok);
    }
    for (size_t i = 0; i < sizeof spiral_n / sizeof *spiral_n; i++) {
        int n = spiral_n[i];
        snprintf(name, sizeof name, "spiral_disc_n%d", n);
        pair *p = new_pair(b, name, "spiral", 2, n);
        keep(b, p, p ? rp_spiral(p->xy[0], n, n < 100 ? 2 : n < 250 ? 3 : 4) | disc_from(p->xy[1], n, 0) : 0);
    }
    for (size_t i = 0; i < sizeof comb_n / sizeof *comb_n; i++) {
        int n = comb_n[i];
        snprintf(name, sizeof name, "comb_disc_n%d", n);
        pair *p = new_pair(b, name, "comb", 2, n);
        keep(b, p, p ? rp_comb(p->xy[0], n, n / 10 < 24 ? n / 10 : 24) | disc_from(p->xy[1], n, 1.25 * RP_PI) : 0);
    }
    for (size_t i = 0; i < sizeof random_n / sizeof *random_n; i++)
        for (int seed = 1; seed <= 3; seed++) {
            int n = random_n[i];
            snprintf(name, sizeof name, "random_pair_n%d_s%d", n, seed);
            pair *p = new_pair(b, name, "random", 2, n);
            keep(b, p, p ? rp_random_simple(p->xy[0], n, 7 * (uint64_t)(n + seed)) | rp_random_simple(p->xy[1], n, 7 * (uint64_t)(n + seed) + 3) : 0);
        }
}

/* The glyph pairs and triples of a cm_gen_pairs directory; hard: all of
 * its pairs (the hard set), in the families hard_glyph and hard_random. */
static int glyph_pairs(bench *b, const char *dir, int hard)
{
    char path[4096], line[1024];
    snprintf(path, sizeof path, "%s/pairs.txt", dir);
    FILE *list = fopen(path, "r");
    if (!list) {
        fprintf(stderr, "cm_partition_bench: cannot read %s: %s\n", path, strerror(errno));
        return -1;
    }
    while (fgets(line, sizeof line, list)) {
        char name[64], file[MAX_K][256];
        int k = sscanf(line, "%63s %255s %255s %255s", name, file[0], file[1], file[2]) - 1;
        if (k < 2 || (!hard && strncmp(name, "glyph", 5) != 0)) continue;
        const char *family = !hard ? "glyph" : strstr(name, "_random_") ? "hard_random" : "hard_glyph";
        double *xy[MAX_K] = {NULL};
        int n = -1, ok = 1;
        for (int g = 0; g < k; g++) {
            snprintf(path, sizeof path, "%s/%s", dir, file[g]);
            int m = read_xy(path, &xy[g]);
            ok &= m >= 3 && (n < 0 || m == n);
            n = m;
        }
        pair *p = ok ? new_pair(b, name, family, k, n) : NULL;
        for (int g = 0; g < k; g++) {
            if (p) memcpy(p->xy[g], xy[g], sizeof(double) * 2 * (size_t)n);
            free(xy[g]);
        }
        if (p) b->count++;
    }
    fclose(list);
    return 0;
}

/* ---- runs ----------------------------------------------------------------- */

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static run measure(const pair *p, cm_method method)
{
    cm_options o;
    cm_options_init(&o);
    o.method = method, o.remesh = 0, o.ceiling = 0;
    size_t counts[MAX_K] = {(size_t)p->n, (size_t)p->n, (size_t)p->n};
    cm_result *r = NULL;
    run out = {0};
    double t0 = cpu_now();
    out.ok = cm_triangulate_polygons((const double *const *)p->xy, counts, (size_t)p->k, &o, &r) == CM_OK;
    out.cpu = cpu_now() - t0;
    if (r) {
        const cm_stats *s = cm_result_stats(r);
        out.steiner = s->steiner_before_remesh, out.fallbacks = s->fallback_count;
        out.validate = s->seconds_validate, out.build = s->seconds_build, out.check = s->seconds_check;
        if (!out.ok) fprintf(stderr, "cm_partition_bench: %s: %s\n", p->name, cm_result_message(r));
    }
    cm_result_free(r);
    return out;
}

/* The partition's CPU time per run: the mean over as many runs as fill
 * min_cpu seconds (at least one). */
static double partition_cpu(const pair *p, double min_cpu, double first)
{
    double total = first;
    int runs = 1;
    while (total < min_cpu) {
        total += measure(p, CM_METHOD_PARTITION).cpu;
        runs++;
    }
    return total / runs;
}

/* CGAL's CPU seconds meshing each polygon of the pair on its own at 25
 * degrees, summed; -1 on failure. The polygons go through files in tmp. */
static double cgal_cpu(const bench *b, const pair *p)
{
    double total = 0;
    for (int g = 0; g < p->k; g++) {
        char path[4096], cmd[8400], line[512];
        snprintf(path, sizeof path, "%s/polygon.xy", b->tmp);
        FILE *f = fopen(path, "w");
        if (!f) return -1;
        for (int i = 0; i < p->n; i++) fprintf(f, "%.17g %.17g\n", p->xy[g][2 * i], p->xy[g][2 * i + 1]);
        if (fclose(f) != 0) return -1;
        snprintf(cmd, sizeof cmd, "'%s' '%s' 25 %g", b->cgal, path, b->min_cpu);
        FILE *out = popen(cmd, "r");
        if (!out) return -1;
        const char *at = fgets(line, sizeof line, out) ? strstr(line, "mesh_cpu_s ") : NULL;
        double s = -1;
        if (!at || sscanf(at + 11, "%lf", &s) != 1) s = -1;
        if (pclose(out) != 0 || s < 0) {
            fprintf(stderr, "cm_partition_bench: %s: %s failed on polygon %d\n", p->name, b->cgal, g);
            return -1;
        }
        total += s;
    }
    return total;
}

/* The partition's own stage times, through the internal entry (the input
 * is counter-clockwise, as the generators write it). */
static void inner_stages(const pair *p, cm_partition_stats *st)
{
    int32_t *tris[MAX_K] = {NULL}, *idx = malloc(sizeof(int32_t) * (size_t)p->n);
    cm_result *r = calloc(1, sizeof *r);
    int ok = idx && r;
    for (int i = 0; ok && i < p->n; i++) idx[i] = i;
    for (int g = 0; ok && g < p->k; g++) {
        tris[g] = malloc(sizeof(int32_t) * 3 * (size_t)p->n);
        ok = tris[g] && cm_polygon_triangulate(p->xy[g], idx, p->n, tris[g], NULL) == 0;
    }
    if (ok) cm_partition((const double *const *)p->xy, (const int32_t *const *)tris, (size_t)p->k, (size_t)p->n, NULL,
                         &r->mesh, st, &r->error);
    for (int g = 0; g < p->k; g++) free(tris[g]);
    free(idx);
    cm_result_free(r);
}

/* Does a Steiner-free compatible triangulation exist? The exact program
 * on the whole input (common diagonals from the visibility tables), run
 * here independently of the method's own choices. */
static int steinerfree_possible(const pair *p)
{
    size_t n = (size_t)p->n;
    if (n > 2500) return -1;
    unsigned char *common = malloc(n * n), *vis = malloc(n * n);
    int32_t *tri = malloc(sizeof(int32_t) * 3 * n), *idx = malloc(sizeof(int32_t) * n);
    int result = -1;
    if (!common || !vis || !tri || !idx) goto done;
    for (size_t i = 0; i < n; i++) idx[i] = (int32_t)i;
    memset(common, 1, n * n);
    for (int g = 0; g < p->k; g++) {
        if (cm_polygon_triangulate(p->xy[g], idx, p->n, tri, NULL) != 0 || cm_visibility_table(p->xy[g], p->n, tri, vis) != 0)
            goto done;
        for (size_t i = 0; i < n * n; i++) common[i] &= vis[i];
    }
    cm_sf_plan plan;
    cm_diagset set;
    if (cm_diagset_from_matrix(&set, p->n, common) != 0) goto done;
    cm_diagview view = {&set, NULL};
    if (cm_steinerfree_plan(p->n, &view, (const double *const *)p->xy, (size_t)p->k, NULL, 0, &plan) == 0) {
        result = plan.cost == 0;
        cm_sf_plan_clear(&plan);
    }
    cm_diagset_clear(&set);
done:
    free(common), free(vis), free(tri), free(idx);
    return result;
}

/* ---- report --------------------------------------------------------------- */

static int compare_size(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return (x > y) - (x < y);
}

static double median(size_t *v, int count)
{
    if (count == 0) return 0;
    qsort(v, (size_t)count, sizeof *v, compare_size);
    return count % 2 ? (double)v[count / 2] : 0.5 * (double)(v[count / 2 - 1] + v[count / 2]);
}

static int in_targets(const row *r)
{
    static const char *families[] = {"star", "twisted", "spiral", "comb", "glyph", "hard_glyph"};
    for (size_t i = 0; i < sizeof families / sizeof *families; i++)
        if (strcmp(r->p.family, families[i]) == 0) return r->p.n <= TARGET_N;
    return 0;
}

static void write_table(FILE *f, const bench *b)
{
    fprintf(f, "| pair | k | n | Steiner-free exists | partition Steiner | fallbacks | valid | partition CPU ms |"
               " CGAL CPU ms | partition / CGAL | validate s | build s | check s |"
               " visibility s | Steiner-free DP s | link paths s | fallback s | overlay Steiner | overlay valid | overlay build s |\n");
    fprintf(f, "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < b->count; i++) {
        const row *r = &b->rows[i];
        char cgal[32] = "-", ratio[32] = "-";
        if (r->cgal > 0) {
            snprintf(cgal, sizeof cgal, "%.3f", 1e3 * r->cgal);
            snprintf(ratio, sizeof ratio, "%.1f", r->part.cpu / r->cgal);
        }
        fprintf(f, "| %s | %d | %d | %s | %zu | %zu | %s | %.3f | %s | %s | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %zu | %s | %.4f |\n",
                r->p.name, r->p.k, r->p.n, r->possible < 0 ? "-" : r->possible ? "yes" : "no", r->part.steiner, r->part.fallbacks, r->part.ok ? "yes" : "**no**",
                1e3 * r->part.cpu, cgal, ratio,
                r->part.validate, r->part.build, r->part.check, r->inner.seconds_visibility, r->inner.seconds_dp,
                r->inner.seconds_link, r->inner.seconds_fallback, r->over.steiner, r->over.ok ? "yes" : "**no**",
                r->over.build);
    }
}

static const char *families[] = {"star", "twisted", "spiral", "comb", "glyph", "random", "hard_glyph", "hard_random"};
#define NFAMILIES (int)(sizeof families / sizeof *families)

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median_d(double *v, int count)
{
    if (count == 0) return NAN;
    qsort(v, (size_t)count, sizeof *v, compare_double);
    return count % 2 ? v[count / 2] : 0.5 * (v[count / 2 - 1] + v[count / 2]);
}

/* Least-squares slope of log t against log n over the family's pairs
 * (cgal: CGAL's times); NAN when the family has a single size. */
static double growth(const bench *b, const char *family, int cgal)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int c = 0, n0 = -1, sizes = 0;
    for (int i = 0; i < b->count; i++) {
        const row *r = &b->rows[i];
        double t = cgal ? r->cgal : r->part.cpu;
        if (strcmp(r->p.family, family) != 0 || !(t > 0)) continue;
        double x = log(r->p.n), y = log(t);
        sx += x, sy += y, sxx += x * x, sxy += x * y, c++;
        if (n0 < 0) n0 = r->p.n;
        sizes |= r->p.n != n0;
    }
    if (!sizes) return NAN;
    return (c * sxy - sx * sy) / (c * sxx - sx * sx);
}

/* Partition against CGAL: median ratio at n <= TARGET_N, overall and per
 * family, and the growth exponents. */
static void write_cgal_summary(FILE *f, const bench *b)
{
    double *v = malloc(sizeof(double) * (size_t)(b->count + 1));
    if (!v) return;
    int c = 0;
    for (int i = 0; i < b->count; i++)
        if (b->rows[i].cgal > 0 && b->rows[i].p.n <= TARGET_N) v[c++] = b->rows[i].part.cpu / b->rows[i].cgal;
    fprintf(f, "- partition CPU / CGAL CPU (both polygons), median at n <= %d: %.2f over %d pairs\n", TARGET_N,
            median_d(v, c), c);
    for (int fam = 0; fam < NFAMILIES; fam++) {
        int cf = 0;
        for (int i = 0; i < b->count; i++) {
            const row *r = &b->rows[i];
            if (r->cgal > 0 && r->p.n <= TARGET_N && strcmp(r->p.family, families[fam]) == 0)
                v[cf++] = r->part.cpu / r->cgal;
        }
        double e = growth(b, families[fam], 0), ec = growth(b, families[fam], 1);
        if (!cf && isnan(e)) continue;
        char es[32] = "- (one size)", ecs[32] = "-";
        if (!isnan(e)) snprintf(es, sizeof es, "%.2f", e);
        if (!isnan(ec)) snprintf(ecs, sizeof ecs, "%.2f", ec);
        fprintf(f, "  - %s: median ratio %.2f over %d pairs; time ~ n^e: e = %s (partition), %s (CGAL)\n",
                families[fam], median_d(v, cf), cf, es, ecs);
    }
    free(v);
}

static void write_summary(FILE *f, const bench *b)
{
    size_t *target = malloc(sizeof(size_t) * (size_t)(b->count + 1)), fallbacks = 0;
    int nt = 0, valid = 0, free_pairs = 0, possible = 0, missed = 0;
    double star1000 = -1;
    for (int i = 0; i < b->count; i++) {
        const row *r = &b->rows[i];
        valid += r->part.ok && r->over.ok;
        fallbacks += r->part.fallbacks;
        free_pairs += r->part.ok && r->part.steiner == 0;
        possible += r->possible == 1;
        missed += r->possible == 1 && r->part.steiner != 0;
        if (in_targets(r)) target[nt++] = r->part.steiner;
        if (strcmp(r->p.family, "star") == 0 && r->p.n == 1000)
            star1000 = r->part.validate + r->part.build + r->part.check;
    }
    fprintf(f, "- pairs: %d, valid results (both methods): %d of %d\n", b->count, valid, b->count);
    fprintf(f, "- partition fallbacks to the overlay construction, all pairs: %zu\n", fallbacks);
    fprintf(f, "- Steiner-free results: %d; pairs where the program says one exists: %d, of them with Steiner vertices: %d\n",
            free_pairs, possible, missed);
    fprintf(f, "- median Steiner count before remeshing, n <= %d, star / twisted / spiral / comb / glyph pairs: %.1f (%d pairs)\n",
            TARGET_N, median(target, nt), nt);
    for (int fam = 0; fam < NFAMILIES; fam++) {
        int c = 0;
        for (int i = 0; i < b->count; i++)
            if (strcmp(b->rows[i].p.family, families[fam]) == 0 && b->rows[i].p.n <= TARGET_N)
                target[c++] = b->rows[i].part.steiner;
        if (c) fprintf(f, "  - %s: median %.1f over %d pairs\n", families[fam], median(target, c), c);
    }
    if (star1000 >= 0) fprintf(f, "- 1000-vertex star pair, partition total (validate + build + check): %.3f s\n", star1000);
    free(target);
}

static int usage(void)
{
    fprintf(stderr, "usage: cm_partition_bench [--pairs DIR] [--hard DIR] [--cgal PATH] [--min-cpu S] [--tsv FILE]\n"
                    "                          [--commit REV] [--out FILE] [--max-n N]\n");
    return 2;
}

int main(int argc, char **argv)
{
    const char *dir = NULL, *hard = NULL, *out = "bench/PARTITION.md", *tsv = NULL, *commit = NULL;
    bench b = {NULL, 0, 0, 1 << 30, NULL, NULL, 0.05};
    char tmp[] = "/tmp/cm_partition_bench.XXXXXX";
    for (int i = 1; i < argc; i++) {
        if (i + 1 < argc && strcmp(argv[i], "--pairs") == 0) dir = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--hard") == 0) hard = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--cgal") == 0) b.cgal = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--min-cpu") == 0) b.min_cpu = atof(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--tsv") == 0) tsv = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--commit") == 0) commit = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--out") == 0) out = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--max-n") == 0) b.max_n = atoi(argv[++i]);
        else return usage();
    }
    synthetic_pairs(&b);
    if (dir && glyph_pairs(&b, dir, 0) != 0) return 1;
    if (hard && glyph_pairs(&b, hard, 1) != 0) return 1;
    if (b.cgal && !(b.tmp = mkdtemp(tmp))) {
        fprintf(stderr, "cm_partition_bench: cannot make a directory in /tmp: %s\n", strerror(errno));
        return 1;
    }
    for (int i = 0; i < b.count; i++) {
        row *r = &b.rows[i];
        r->part = measure(&r->p, CM_METHOD_PARTITION);
        r->part.cpu = partition_cpu(&r->p, b.min_cpu, r->part.cpu);
        r->cgal = b.cgal ? cgal_cpu(&b, &r->p) : -1;
        r->over = measure(&r->p, CM_METHOD_OVERLAY);
        inner_stages(&r->p, &r->inner);
        r->possible = steinerfree_possible(&r->p);
        printf("%-22s n=%-5d partition %5zu Steiner, %zu fallbacks, %.3f s (CPU %.2f ms, CGAL %.2f ms) | overlay %6zu Steiner, %.3f s\n",
               r->p.name, r->p.n, r->part.steiner, r->part.fallbacks, r->part.build, 1e3 * r->part.cpu, 1e3 * r->cgal,
               r->over.steiner, r->over.build);
    }
    if (b.tmp) {
        char path[128];
        snprintf(path, sizeof path, "%s/polygon.xy", b.tmp);
        remove(path), rmdir(b.tmp);
    }
    FILE *t = tsv ? fopen(tsv, "w") : NULL;
    if (tsv && !t) {
        fprintf(stderr, "cm_partition_bench: cannot write %s: %s\n", tsv, strerror(errno));
        return 1;
    }
    for (int i = 0; t && i < b.count; i++) {
        const row *r = &b.rows[i];
        fprintf(t, "%s\t%s\t%d\t%zu\t%.9f\t%.9f\n", r->p.name, r->p.family, r->p.n, r->part.steiner, r->part.cpu, r->cgal);
    }
    if (t && fclose(t) != 0) {
        fprintf(stderr, "cm_partition_bench: cannot write %s\n", tsv);
        return 1;
    }
    FILE *f = fopen(out, "w");
    if (!f) {
        fprintf(stderr, "cm_partition_bench: cannot write %s: %s\n", out, strerror(errno));
        return 1;
    }
    fprintf(f, "# The partition against the overlay and against CGAL\n\n");
    char date[32] = "";
    time_t now = time(NULL);
    strftime(date, sizeof date, "%Y-%m-%d", gmtime(&now));
    fprintf(f, "Written by `cm_partition_bench%s%s%s` (bench/partition_bench.c)%s%s on %s%s%s. Both methods\n"
               "without remeshing: Steiner counts are those of the first compatible triangulation.\n"
               "Times in seconds; the partition's breakdown comes from a second run through its\n"
               "internal entry. \"Steiner-free exists\": the exact program run on the whole input.\n"
               "Partition CPU: validate + build + check in this process (mean over runs filling\n"
               "%g s); CGAL CPU: its Delaunay mesher at 25 degrees on each polygon alone, summed,\n"
               "timed inside its process (start and reading excluded).\n\n",
            dir ? " --pairs DIR" : "", hard ? " --hard HARD" : "", b.cgal ? " --cgal cm_cgal_single" : "",
            dir ? ", DIR from `cm_gen_pairs --out DIR --set bench`" : "",
            hard ? ", HARD from `cm_gen_pairs --out HARD --set hard`" : "", date, commit ? ", commit " : "",
            commit ? commit : "", b.min_cpu);
    if (b.cgal) write_cgal_summary(f, &b);
    write_summary(f, &b);
    fprintf(f, "\n");
    write_table(f, &b);
    fclose(f);
    if (b.cgal) write_cgal_summary(stdout, &b);
    write_summary(stdout, &b);
    int bad = 0;
    for (int i = 0; i < b.count; i++) {
        bad |= !b.rows[i].part.ok || !b.rows[i].over.ok;
        bad |= b.rows[i].possible == 1 && b.rows[i].part.steiner != 0;
        for (int g = 0; g < b.rows[i].p.k; g++) free(b.rows[i].p.xy[g]);
    }
    free(b.rows);
    return bad;
}
