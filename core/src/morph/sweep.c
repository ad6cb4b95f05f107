/* The swept volume: sections of a morph stacked into 6-node prisms.
 *
 * A prism's Jacobian at height fraction s is its triangle blended
 * linearly between the bottom and the top section, so the prism is valid
 * everywhere only if that blended triangle stays counter-clockwise for
 * all s in [0, 1] (cm_blend_positive decides the quadratic exactly). Where
 * it does not, a section is inserted halfway in morph time: the morph is
 * a smooth path of valid sections, so blends over short enough steps are
 * valid. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "morph/morph.h"
#include "morph/prism_split.h"
#include "base/progress.h"
#include "geom/angle.h"
#include "geom/predicates.h"
#include "morph/cell_shape.h"
#include "morph/loft.h"
#include "morph/sweep_boundary.h"

typedef struct section {
    size_t g;   /* segment between geometries g and g + 1 */
    double s;   /* local time in [0, 1] */
    double z;
    double *xy; /* 2 * nv */
    /* With tets: the corner order of each triangle's prism up to the next
     * section (prism_split.h), and the smallest dihedral angle it gives. */
    unsigned char *split;
    double worst_dihedral;
} section;

struct cm_sweep {
    cm_error error;
    size_t nv, ns, np, ntet;
    double *z, *nodes, volume;
    int32_t *prisms, *tets;
    int default_height;
    cm_morph_method morph_method; /* of the morph whose sections were used */
    cm_sweep_quality quality;
    /* The boundary's groups, its faces over the prisms and over the
     * tetrahedra. */
    cm_sweep_walls walls;
    cm_sweep_boundary boundary, boundary_tets;
};

void cm_sweep_options_init(cm_sweep_options *options)
{
    memset(options, 0, sizeof *options);
    options->sections = 11;
    options->height = 0.0;
    options->max_refine = 1000;
}

static cm_status check_options(cm_sweep *w, const cm_morph *m, const cm_sweep_options *o)
{
    if (o->sections == 1 || o->sections > CM_SWEEP_MAX_SECTIONS)
        return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: sections must be 0 (as many as the edges ask) or 2 to %d, got %zu",
                       CM_SWEEP_MAX_SECTIONS, o->sections);
    if (o->heights) {
        for (size_t g = 0; g < m->k; g++)
            if (!isfinite(o->heights[g]))
                return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: heights[%zu] is not finite", g);
        for (size_t g = 0; g + 1 < m->k; g++)
            if (!(o->heights[g + 1] > o->heights[g]))
                return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: heights must increase strictly: heights[%zu] = %g, heights[%zu] = %g",
                            g, o->heights[g], g + 1, o->heights[g + 1]);
    } else if (!(o->height >= 0 && isfinite(o->height))) {
        return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: height must be positive and finite (or 0 for the default), got %g",
                       o->height);
    }
    if (!(o->wall_corner_deg >= 0 && o->wall_corner_deg < 180))
        return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: wall_corner_deg must be in [0, 180), got %g",
                       o->wall_corner_deg);
    return CM_OK;
}

/* The largest bounding-box diagonal of the geometries (1 if they are all
 * points or it overflows). */
static double largest_diagonal(const cm_morph *m)
{
    const cm_mesh *mesh = &m->result->mesh;
    double size = 0;
    for (size_t g = 0; g < mesh->k && mesh->nv > 0; g++) {
        const double *xy = mesh->xy[g];
        double lo[2] = {xy[0], xy[1]}, hi[2] = {xy[0], xy[1]};
        for (size_t i = 1; i < mesh->nv; i++)
            for (int c = 0; c < 2; c++) lo[c] = fmin(lo[c], xy[2 * i + c]), hi[c] = fmax(hi[c], xy[2 * i + c]);
        size = fmax(size, hypot(hi[0] - lo[0], hi[1] - lo[1]));
    }
    return size > 0 && isfinite(size) ? size : 1.0;
}

/* Height of geometry g for total height `height`. */
static double level(const cm_morph *m, const cm_sweep_options *o, double height, size_t g)
{
    return o->heights ? o->heights[g] : height * (double)g / (double)(m->k - 1);
}

static int double_less(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return (a > b) - (a < b);
}

/* Sections per segment for sections = 0: layers about as tall as the
 * inputs' triangulations' median edge, in the tallest segment (near
 * cubic prisms, so that their tetrahedra are well shaped), at least one
 * layer, at most CM_SWEEP_MAX_SECTIONS sections. 0 out of memory. */
static size_t sections_for_edges(const cm_morph *m, const cm_sweep_options *o, double height)
{
    const cm_mesh *mesh = &m->result->mesh;
    size_t n = 3 * mesh->nt * mesh->k;
    double *length = malloc((n + 1) * sizeof *length), tallest = 0;
    if (!length) return 0;
    for (size_t g = 0, i = 0; g < mesh->k; g++)
        for (size_t t = 0; t < mesh->nt; t++)
            for (int c = 0; c < 3; c++) {
                const double *p = mesh->xy[g] + 2 * mesh->tri[3 * t + c], *q = mesh->xy[g] + 2 * mesh->tri[3 * t + (c + 1) % 3];
                length[i++] = hypot(q[0] - p[0], q[1] - p[1]);
            }
    qsort(length, n, sizeof *length, double_less);
    double median = n ? length[n / 2] : 0;
    free(length);
    for (size_t g = 0; g + 1 < m->k; g++) tallest = fmax(tallest, level(m, o, height, g + 1) - level(m, o, height, g));
    double layers = ceil(tallest / median); /* NaN where median is 0 */
    if (!(layers >= 1)) layers = 1;
    return (size_t)fmin(layers, CM_SWEEP_MAX_SECTIONS - 1) + 1;
}

/* z0 + (z1 - z0) s, also where z1 - z0 overflows. */
static double between(double z0, double z1, double s)
{
    double z = z0 + (z1 - z0) * s;
    return isfinite(z) ? z : z0 * (1 - s) + z1 * s;
}

static double midway(double a, double b)
{
    double z = 0.5 * (a + b);
    return isfinite(z) ? z : 0.5 * a + 0.5 * b;
}

/* The section (g, s) of the morph; a message on w if it fails. */
static cm_status make_section(cm_sweep *w, cm_morph *m, section *sec)
{
    size_t inverted = 0;
    if (!(sec->xy = malloc(2 * m->nv * sizeof *sec->xy))) return cm_fail_status(&w->error, CM_ERR_NO_MEMORY);
    cm_status s = cm_morph_section_at(m, sec->g, sec->s, sec->xy, &inverted, NULL);
    if (s != CM_OK) return cm_fail(&w->error, s, "sweep: %s", cm_morph_message(m));
    if (inverted)
        return cm_fail(&w->error, CM_ERR_INTERNAL, "sweep: the section at segment %zu, time %g has %zu inverted triangles "
                    "(the linear morph inverts; use CM_MORPH_CONVEX)", sec->g, sec->s, inverted);
    return CM_OK;
}

static void node_xyz(const section *sec, int32_t local, size_t nv, double p[3])
{
    const section *x = sec + (local >= (int32_t)nv);
    size_t v = (size_t)local % nv;
    p[0] = x->xy[2 * v], p[1] = x->xy[2 * v + 1], p[2] = x->z;
}

/* x y z of every vertex of a section, for the split's shape measures. */
static void section_xyz(const section *sec, size_t nv, double *xyz)
{
    for (size_t v = 0; v < nv; v++)
        xyz[3 * v] = sec->xy[2 * v], xyz[3 * v + 1] = sec->xy[2 * v + 1], xyz[3 * v + 2] = sec->z;
}

/* What splits the layers into tetrahedra: the mesh's edges and two
 * sections' coordinates. */
typedef struct layer_splitter {
    cm_prism_split split;
    double *bottom, *top; /* 3 * nv */
} layer_splitter;

/* Longest edge of triangle c in section sec. */
static double longest_edge(const section *sec, const int32_t *c)
{
    double longest = 0;
    for (int i = 0; i < 3; i++) {
        const double *a = sec->xy + 2 * (size_t)c[i], *b = sec->xy + 2 * (size_t)c[(i + 1) % 3];
        longest = fmax(longest, hypot(b[0] - a[0], b[1] - a[1]));
    }
    return longest;
}

/* The split of triangle t's prism between lo and lo + 1 is poor: a dihedral
 * angle under half the smallest angle of its two triangles (a right prism
 * of them would reach that angle), while the prism is at least half as
 * tall as its longest triangle edge. Such a prism is tilted or twisted by a
 * long morph step, which a shorter step straightens; a flatter one would
 * only get flatter. */
static int poorly_split(const section *lo, const int32_t *c, double split_deg)
{
    double allowed = fmin(cm_triangle_min_angle(lo[0].xy + 2 * (size_t)c[0], lo[0].xy + 2 * (size_t)c[1], lo[0].xy + 2 * (size_t)c[2]),
                          cm_triangle_min_angle(lo[1].xy + 2 * (size_t)c[0], lo[1].xy + 2 * (size_t)c[1], lo[1].xy + 2 * (size_t)c[2]));
    if (!(split_deg < 0.5 * allowed * 180 / CM_PI)) return 0;
    return lo[1].z - lo[0].z >= 0.5 * fmax(longest_edge(lo, c), longest_edge(lo + 1, c));
}

/* Checks the prisms between sections lo and lo + 1: *bad is the first
 * triangle whose prism is invalid (blend or, with a splitter, a
 * tetrahedron of its chosen split not positive; *tets_only 1 for the
 * latter), or -1; *poor the first
 * whose split is poor (poorly_split), or -1. With a splitter, lo->split
 * and lo->worst_dihedral are (re)computed. */
static cm_status check_layer(cm_sweep *w, const cm_morph *m, section *lo, layer_splitter *splitter, long *bad,
                             int *tets_only, long *poor)
{
    *poor = -1, *tets_only = 0;
    double flattest = 0; /* longest triangle edge of the layer */
    const int32_t *tri = m->result->mesh.tri;
    size_t nv = m->nv;
    *bad = -1;
    if (splitter) {
        if (!lo->split && !(lo->split = malloc(m->nt + 1))) return cm_fail_status(&w->error, CM_ERR_NO_MEMORY);
        section_xyz(lo, nv, splitter->bottom), section_xyz(lo + 1, nv, splitter->top);
        lo->worst_dihedral = cm_prism_split_choose(&splitter->split, splitter->bottom, splitter->top, lo->split);
    }
    for (size_t t = 0; t < m->nt; t++) {
        const int32_t *c = tri + 3 * t;
        const double *p0 = lo[0].xy, *p1 = lo[1].xy;
        if (!cm_blend_positive(p0 + 2 * (size_t)c[0], p0 + 2 * (size_t)c[1], p0 + 2 * (size_t)c[2],
                               p1 + 2 * (size_t)c[0], p1 + 2 * (size_t)c[1], p1 + 2 * (size_t)c[2])) {
            *bad = (long)t;
            return CM_OK;
        }
        if (!splitter) continue;
        if (*poor < 0 && poorly_split(lo, c, splitter->split.score[6 * t + lo->split[t]])) *poor = (long)t;
        flattest = fmax(flattest, fmax(longest_edge(lo, c), longest_edge(lo + 1, c)));
        int32_t v[6] = {c[0], c[1], c[2], c[0] + (int32_t)nv, c[1] + (int32_t)nv, c[2] + (int32_t)nv}, q[12];
        cm_prism_split_tets(v, lo->split[t], q);
        for (int j = 0; j < 3; j++) {
            double a[3], b[3], cc[3], d[3];
            node_xyz(lo, q[4 * j], nv, a), node_xyz(lo, q[4 * j + 1], nv, b);
            node_xyz(lo, q[4 * j + 2], nv, cc), node_xyz(lo, q[4 * j + 3], nv, d);
            if (cm_orient3d(a, b, cc, d) <= 0) {
                *bad = (long)t, *tets_only = 1;
                return CM_OK;
            }
        }
    }
    /* Halving must not make the layer's largest triangles flat: it stays
     * within half the flat ratio (its tetrahedra keep about 10 degrees). */
    if (2 * flattest > 0.5 * CM_SWEEP_FLAT_RATIO * (lo[1].z - lo[0].z)) *poor = -1;
    return CM_OK;
}

static void free_sections(section *secs, size_t count)
{
    if (secs)
        for (size_t i = 0; i < count; i++) free(secs[i].xy), free(secs[i].split);
    free(secs);
}

/* Volume of the prisms between two sections: per triangle, the height
 * times the mean of its blended area, (A0 + M + A1) / 3 for the Bernstein
 * form of the doubled area, halved. */
static long double slab_volume(const cm_morph *m, const section *lo)
{
    const int32_t *tri = m->result->mesh.tri;
    long double sum = 0;
    for (size_t t = 0; t < m->nt; t++) {
        const double *a0 = lo[0].xy + 2 * (size_t)tri[3 * t], *b0 = lo[0].xy + 2 * (size_t)tri[3 * t + 1],
                     *c0 = lo[0].xy + 2 * (size_t)tri[3 * t + 2];
        const double *a1 = lo[1].xy + 2 * (size_t)tri[3 * t], *b1 = lo[1].xy + 2 * (size_t)tri[3 * t + 1],
                     *c1 = lo[1].xy + 2 * (size_t)tri[3 * t + 2];
        long double u0x = b0[0] - a0[0], u0y = b0[1] - a0[1], v0x = c0[0] - a0[0], v0y = c0[1] - a0[1];
        long double u1x = b1[0] - a1[0], u1y = b1[1] - a1[1], v1x = c1[0] - a1[0], v1y = c1[1] - a1[1];
        long double area0 = u0x * v0y - u0y * v0x, area1 = u1x * v1y - u1y * v1x;
        long double mixed = 0.5L * (u0x * v1y - u0y * v1x + u1x * v0y - u1y * v0x);
        sum += (area0 + mixed + area1) / 6.0L;
    }
    return sum * ((long double)lo[1].z - (long double)lo[0].z);
}

/* The quality of the exported cells and the flatness of the prisms. */
void cm_cells_quality(const double *nodes, const int32_t *cells, size_t num_cells, int tets, cm_sweep_quality *q)
{
    memset(q, 0, sizeof *q);
    q->min_dihedral_deg = 180, q->min_scaled_jacobian = INFINITY;
    size_t per = tets ? 4 : 6;
    for (size_t i = 0; i < num_cells; i++) {
        double p[6][3];
        for (size_t c = 0; c < per; c++) memcpy(p[c], nodes + 3 * (size_t)cells[per * i + c], sizeof p[c]);
        cm_cell_shape shape;
        if (tets) cm_tet_shape((const double(*)[3])p, &shape);
        else cm_prism_shape((const double(*)[3])p, &shape);
        q->min_dihedral_deg = fmin(q->min_dihedral_deg, shape.min_dihedral_deg);
        q->max_dihedral_deg = fmax(q->max_dihedral_deg, shape.max_dihedral_deg);
        q->min_scaled_jacobian = fmin(q->min_scaled_jacobian, shape.scaled_jacobian);
        q->max_aspect_ratio = fmax(q->max_aspect_ratio, shape.aspect_ratio);
    }
}

static void measure(cm_sweep *w, const cm_morph *m)
{
    cm_sweep_quality *q = &w->quality;
    cm_cells_quality(w->nodes, w->tets ? w->tets : w->prisms, w->tets ? w->ntet : w->np, w->tets != NULL, q);
    const int32_t *tri = m->result->mesh.tri;
    for (size_t i = 0; i + 1 < w->ns; i++)
        for (size_t t = 0; t < m->nt; t++) {
            double longest = 0;
            for (size_t layer = i; layer <= i + 1; layer++)
                for (int c = 0; c < 3; c++) {
                    const double *a = w->nodes + 3 * (layer * w->nv + (size_t)tri[3 * t + c]);
                    const double *b = w->nodes + 3 * (layer * w->nv + (size_t)tri[3 * t + (c + 1) % 3]);
                    longest = fmax(longest, hypot(b[0] - a[0], b[1] - a[1]));
                }
            double flatness = longest / (w->z[i + 1] - w->z[i]);
            q->max_flatness = fmax(q->max_flatness, flatness);
            if (flatness > CM_SWEEP_FLAT_RATIO) q->flat_prisms++;
        }
}

static cm_status build_prisms(cm_sweep *w, cm_morph *m, const cm_sweep_options *o)
{
    cm_progress progress;
    cm_progress_init(&progress, o->progress, o->progress_user);
    w->default_height = !o->heights && o->height == 0;
    double height = w->default_height ? largest_diagonal(m) : o->height;
    size_t sections = o->sections ? o->sections : sections_for_edges(m, o, height);
    if (!sections) return cm_fail_status(&w->error, CM_ERR_NO_MEMORY);
    size_t per = sections - 1, count = (m->k - 1) * per + 1, cap = count + 16;
    section *secs = calloc(cap, sizeof *secs);
    layer_splitter splitter = {0}, *split = o->tets ? &splitter : NULL;
    cm_status s = CM_OK;
    if (!secs) return cm_fail_status(&w->error, CM_ERR_NO_MEMORY);
    if (split) {
        s = cm_prism_split_init(&splitter.split, m->result->mesh.tri, m->nt, m->nv, &w->error);
        splitter.bottom = malloc((3 * m->nv + 1) * sizeof *splitter.bottom);
        splitter.top = malloc((3 * m->nv + 1) * sizeof *splitter.top);
        if (s == CM_OK && (!splitter.bottom || !splitter.top)) s = cm_fail_status(&w->error, CM_ERR_NO_MEMORY);
    }
    for (size_t i = 0; i < count && s == CM_OK; i++) {
        size_t g = i / per, j = i % per;
        if (g == m->k - 1) g--, j = per; /* the last section ends the last segment */
        secs[i].g = g;
        secs[i].s = (double)j / (double)per;
        double z0 = level(m, o, height, g), z1 = level(m, o, height, g + 1);
        secs[i].z = j == per ? z1 : between(z0, z1, secs[i].s);
        s = make_section(w, m, &secs[i]);
    }
    /* Poor splits may spend half of max_refine; invalid cells keep the
     * rest, so improving shapes early never leaves a later cell invalid. */
    size_t refined = 0, refined_poor = 0;
    for (size_t i = 0; i + 1 < count && s == CM_OK;) {
        if (cm_progress_report(&progress, CM_STAGE_SWEEP, (double)i / (double)count)) {
            s = cm_fail_status(&w->error, CM_ERR_CANCELLED);
            break;
        }
        long bad, poor;
        int tets_only;
        s = check_layer(w, m, secs + i, split, &bad, &tets_only, &poor);
        if (s != CM_OK) break;
        /* End of this segment: the next section starts the next one. */
        double s_end = secs[i + 1].g == secs[i].g ? secs[i + 1].s : 1.0;
        double s_mid = 0.5 * (secs[i].s + s_end);
        /* Poor splits are improved while refinement and doubles allow;
         * invalid cells must be. */
        if (bad < 0 && (poor < 0 || refined_poor >= o->max_refine / 2 || !(s_mid > secs[i].s && s_mid < s_end))) {
            i++;
            continue;
        }
        if (refined == o->max_refine && tets_only) {
            /* The prism is valid; its triangle is too thin for a split
             * into three positive tetrahedra at any step the budget allows. */
            const int32_t *c = m->result->mesh.tri + 3 * (size_t)bad;
            const double *xy = secs[i].xy;
            double angle = cm_triangle_min_angle(xy + 2 * (size_t)c[0], xy + 2 * (size_t)c[1], xy + 2 * (size_t)c[2]);
            s = cm_fail(&w->error, CM_ERR_INTERNAL,
                        "sweep: the prism of triangle %ld between z = %g and z = %g is valid, but its tetrahedra "
                        "are not all positive after %zu inserted sections (max_refine): the triangle's smallest "
                        "angle is %.3g degrees there; sweep into prisms, or remesh to a larger smallest angle",
                        bad, secs[i].z, secs[i + 1].z, refined, angle * 180.0 / CM_PI);
            break;
        }
        if (refined == o->max_refine) {
            s = cm_fail(&w->error, CM_ERR_INTERNAL,
                     "sweep: the prism of triangle %ld between z = %g and z = %g is not valid along its blend "
                     "after %zu inserted sections (max_refine)",
                     bad, secs[i].z, secs[i + 1].z, refined);
            break;
        }
        if (count == cap) {
            section *grown = realloc(secs, 2 * cap * sizeof *secs);
            if (!grown) {
                s = cm_fail_status(&w->error, CM_ERR_NO_MEMORY);
                break;
            }
            memset(grown + cap, 0, cap * sizeof *secs);
            secs = grown, cap *= 2;
        }
        section mid = {secs[i].g, s_mid, midway(secs[i].z, secs[i + 1].z), NULL, NULL, 0};
        if (!(mid.s > secs[i].s && mid.s < s_end)) {
            s = cm_fail(&w->error, CM_ERR_PRECISION, "sweep: the prism of triangle %ld at z = %g needs a finer step than doubles allow",
                     bad, secs[i].z);
            break;
        }
        memmove(secs + i + 2, secs + i + 1, (count - i - 1) * sizeof *secs);
        secs[i + 1] = mid;
        count++, refined++, refined_poor += bad < 0;
        s = make_section(w, m, &secs[i + 1]);
    }
    if (s == CM_OK) {
        size_t nv = m->nv, nt = m->nt;
        w->nv = nv, w->ns = count, w->np = (count - 1) * nt, w->ntet = o->tets ? 3 * w->np : 0;
        w->z = malloc(count * sizeof *w->z);
        w->nodes = malloc(3 * count * nv * sizeof *w->nodes);
        w->prisms = malloc(6 * w->np * sizeof *w->prisms);
        w->tets = o->tets ? malloc(4 * w->ntet * sizeof *w->tets) : NULL;
        if (!w->z || !w->nodes || !w->prisms || (o->tets && !w->tets)) s = cm_fail_status(&w->error, CM_ERR_NO_MEMORY);
        else if (count * nv > INT32_MAX) s = cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: %zu nodes exceed 32-bit indices", count * nv);
    }
    if (s == CM_OK) {
        const int32_t *tri = m->result->mesh.tri;
        long double volume = 0;
        for (size_t i = 0; i < count; i++) {
            w->z[i] = secs[i].z;
            for (size_t v = 0; v < w->nv; v++) {
                double *p = w->nodes + 3 * (i * w->nv + v);
                p[0] = secs[i].xy[2 * v], p[1] = secs[i].xy[2 * v + 1], p[2] = secs[i].z;
            }
            if (i + 1 < count) volume += slab_volume(m, secs + i);
        }
        w->volume = (double)volume; /* HUGE_VAL beyond the double range */
        for (size_t i = 0; i < 3 * count * w->nv && s == CM_OK; i++)
            if (!isfinite(w->nodes[i]))
                s = cm_fail(&w->error, CM_ERR_ARGUMENT,
                            "sweep: node %zu between z = %g and z = %g is beyond the double range",
                            i / 3, secs[0].z, secs[count - 1].z);
        size_t p = 0;
        for (size_t i = 0; i + 1 < count; i++)
            for (size_t t = 0; t < m->nt; t++, p++) {
                int32_t *q = w->prisms + 6 * p;
                for (int c = 0; c < 3; c++) {
                    q[c] = (int32_t)(i * w->nv) + tri[3 * t + c];
                    q[3 + c] = (int32_t)((i + 1) * w->nv) + tri[3 * t + c];
                }
                if (w->tets) cm_prism_split_tets(q, secs[i].split[t], w->tets + 12 * p);
            }
    }
    if (s == CM_OK) s = cm_sweep_walls_build(&w->walls, m->result, o->wall_corner_deg, &w->error);
    if (s == CM_OK) s = cm_sweep_boundary_build(&w->boundary, m->result, &w->walls, count, NULL, &w->error);
    if (s == CM_OK && w->tets)
        s = cm_sweep_boundary_build(&w->boundary_tets, m->result, &w->walls, count, w->tets, &w->error);
    if (s == CM_OK) measure(w, m);
    free_sections(secs, count);
    if (split) cm_prism_split_free(&splitter.split);
    free(splitter.bottom), free(splitter.top);
    return s;
}

/* The convex-combination morph can keep a triangle thin over a long
 * stretch of time; its prisms (and more so their tetrahedra) then need
 * more sections than max_refine. The intrinsic morph interpolates each
 * star's angles and edge lengths, so such a triangle opens up: the sweep
 * is built again from its sections. The first message is kept when that
 * fails too. */
static cm_status retry_intrinsic(cm_sweep *w, cm_morph *morph, const cm_sweep_options *o)
{
    cm_morph_options mo;
    cm_morph_options_init(&mo);
    mo.method = CM_MORPH_INTRINSIC;
    mo.progress = o->progress, mo.progress_user = o->progress_user;
    cm_error first = w->error;
    cm_morph *alt = NULL;
    cm_status s = cm_morph_create(morph->result, &mo, &alt);
    if (s == CM_OK) {
        cm_error_init(&w->error);
        s = build_prisms(w, alt, o);
    }
    cm_morph_free(alt);
    if (s == CM_OK) {
        w->morph_method = CM_MORPH_INTRINSIC;
        return CM_OK;
    }
    if (s == CM_ERR_CANCELLED || s == CM_ERR_NO_MEMORY) return cm_fail_status(&w->error, s);
    w->error = first;
    return first.status;
}

static void free_mesh(cm_sweep *w);

/* The ruled sweep: the sections on straight lines between consecutive
 * inputs (the linear morph of the morph's result), as a CAD loft makes
 * them. CM_OK when every prism stays valid along it; CM_ERR_INTERNAL, with
 * nothing kept and the error cleared, where a section inverts a triangle,
 * for the caller to sweep the morph's sections instead. */
static cm_status build_ruled(cm_sweep *w, const cm_morph *morph, const cm_sweep_options *o)
{
    cm_morph_options mo;
    cm_morph_options_init(&mo);
    mo.method = CM_MORPH_LINEAR;
    mo.progress = o->progress, mo.progress_user = o->progress_user;
    cm_morph *linear = NULL;
    cm_status s = cm_morph_create(morph->result, &mo, &linear);
    if (s == CM_OK) s = build_prisms(w, linear, o);
    else cm_fail(&w->error, s, "sweep: %s", cm_morph_message(linear));
    cm_morph_free(linear);
    if (s == CM_OK) {
        w->morph_method = CM_MORPH_LINEAR;
    } else if (s != CM_ERR_CANCELLED && s != CM_ERR_NO_MEMORY) {
        free_mesh(w);
        cm_error_init(&w->error);
        s = CM_ERR_INTERNAL;
    }
    return s;
}

/* The centre of each geometry, the mean of its boundary vertices, in its
 * plane coordinates (2 per geometry, at out). */
static const double *section_centres(const cm_morph *m, double *out)
{
    const cm_mesh *mesh = &m->result->mesh;
    size_t n = m->result->n;
    for (size_t g = 0; g < mesh->k; g++) {
        long double x = 0, y = 0;
        for (size_t v = 0; v < n; v++) x += mesh->xy[g][2 * v], y += mesh->xy[g][2 * v + 1];
        out[2 * g] = (double)(x / (long double)n), out[2 * g + 1] = (double)(y / (long double)n);
    }
    return out;
}

/* The loft's step (cm_sweep_options.frames): the nodes placed in space
 * between the planes, each cell checked there, the volume and the cells'
 * quality measured there. */
static cm_status place_in_space(cm_sweep *w, const double *frames, const double *levels, size_t k)
{
    size_t count = w->ns * w->nv, nt = w->ns > 1 ? w->np / (w->ns - 1) : 1;
    cm_loft_place(frames, levels, k, w->nodes, count);
    for (size_t i = 0; i < 3 * count; i++)
        if (!isfinite(w->nodes[i]))
            return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: node %zu of the loft is beyond the double range", i / 3);
    int tets = w->tets != NULL;
    const int32_t *cells = tets ? w->tets : w->prisms;
    size_t cell_count = tets ? w->ntet : w->np;
    long bad = cm_loft_first_inverted(w->nodes, cells, cell_count, tets);
    if (bad >= 0) {
        size_t layer = (tets ? (size_t)bad / 3 : (size_t)bad) / nt;
        return cm_fail(&w->error, CM_ERR_ARGUMENT,
                       "sweep: the loft's %s %ld, between sections %zu and %zu, is not positive in space: the "
                       "straight blend between the planes folds there (planes too close for their turn, planes "
                       "crossing inside the polygons, or a polygon given the other way round)",
                       tets ? "tetrahedron" : "prism", bad, layer, layer + 1);
    }
    w->volume = cm_loft_volume(w->nodes, w->prisms, w->np);
    cm_sweep_quality flat = w->quality;
    cm_cells_quality(w->nodes, cells, cell_count, tets, &w->quality);
    w->quality.max_flatness = flat.max_flatness, w->quality.flat_prisms = flat.flat_prisms;
    return CM_OK;
}

static void free_mesh(cm_sweep *w)
{
    free(w->z), free(w->nodes), free(w->prisms), free(w->tets);
    w->z = w->nodes = NULL, w->prisms = w->tets = NULL;
    cm_sweep_walls_free(&w->walls);
    cm_sweep_boundary_free(&w->boundary);
    cm_sweep_boundary_free(&w->boundary_tets);
}

cm_status cm_sweep_create(cm_morph *morph, const cm_sweep_options *options, cm_sweep **sweep)
{
    if (!sweep) return CM_ERR_ARGUMENT;
    cm_sweep *w = *sweep = calloc(1, sizeof **sweep);
    if (!w) return CM_ERR_NO_MEMORY;
    cm_sweep_options defaults;
    if (!options) cm_sweep_options_init(&defaults), options = &defaults;
    if (!morph) return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: morph is NULL");
    if (!morph->result) return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: the morph failed to build (%s)", cm_morph_message(morph));
    cm_status s = check_options(w, morph, options);
    const double *frames = options->frames;
    double *levels = NULL;
    cm_sweep_options lofted;
    if (s == CM_OK && frames) { /* the loft: built with its levels as heights, then placed */
        if (options->heights || options->height != 0)
            s = cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: frames place the geometries; give no heights or height with them");
        else if (!(levels = malloc(3 * morph->k * sizeof *levels)))
            s = cm_fail_status(&w->error, CM_ERR_NO_MEMORY);
        else
            s = cm_loft_levels(frames, section_centres(morph, levels + morph->k), morph->k, levels, &w->error);
        lofted = *options, lofted.heights = levels, options = &lofted;
    }
    w->morph_method = morph->method;
    int built = 0;
    if (s == CM_OK && options->ruled && morph->method != CM_MORPH_LINEAR) {
        s = build_ruled(w, morph, options);
        built = s == CM_OK;
        if (s == CM_ERR_INTERNAL) s = CM_OK; /* a straight blend inverts: the morph's sections */
    }
    if (s == CM_OK && !built) {
        s = build_prisms(w, morph, options);
        if (s == CM_ERR_INTERNAL && morph->method == CM_MORPH_CONVEX) s = retry_intrinsic(w, morph, options);
    }
    if (s == CM_OK && frames) s = place_in_space(w, frames, levels, morph->k);
    free(levels);
    if (s != CM_OK) {
        free_mesh(w);
        w->ns = w->np = w->ntet = w->nv = 0, w->volume = 0;
    }
    return cm_error_close(&w->error, s);
}

void cm_sweep_free(cm_sweep *w)
{
    if (!w) return;
    free_mesh(w);
    free(w);
}

const char *cm_sweep_message(const cm_sweep *w) { return w ? w->error.message : "no sweep"; }
size_t cm_sweep_num_sections(const cm_sweep *w) { return w ? w->ns : 0; }
const double *cm_sweep_section_z(const cm_sweep *w) { return w ? w->z : NULL; }
size_t cm_sweep_num_nodes(const cm_sweep *w) { return w ? w->ns * w->nv : 0; }
const double *cm_sweep_nodes(const cm_sweep *w) { return w ? w->nodes : NULL; }
size_t cm_sweep_num_prisms(const cm_sweep *w) { return w ? w->np : 0; }
const int32_t *cm_sweep_prisms(const cm_sweep *w) { return w ? w->prisms : NULL; }
size_t cm_sweep_num_tets(const cm_sweep *w) { return w ? w->ntet : 0; }
const int32_t *cm_sweep_tets(const cm_sweep *w) { return w ? w->tets : NULL; }
double cm_sweep_volume(const cm_sweep *w) { return w ? w->volume : 0.0; }
double cm_sweep_height(const cm_sweep *w) { return w && w->ns ? w->z[w->ns - 1] - w->z[0] : 0.0; }
int cm_sweep_height_is_default(const cm_sweep *w) { return w && w->ns ? w->default_height : 0; }
size_t cm_sweep_num_boundary_groups(const cm_sweep *w) { return w && w->ns ? w->walls.groups : 0; }

const char *cm_sweep_boundary_group_name(const cm_sweep *w, size_t group)
{
    return w && w->ns && group < w->walls.groups ? w->walls.names[group] : NULL;
}

static const cm_sweep_boundary *boundary_of(const cm_sweep *w, int tets)
{
    return !w ? NULL : tets ? &w->boundary_tets : &w->boundary;
}
size_t cm_sweep_num_boundary_faces(const cm_sweep *w, int tets) { return w ? boundary_of(w, tets)->nf : 0; }
const int32_t *cm_sweep_boundary_faces(const cm_sweep *w, int tets) { return w ? boundary_of(w, tets)->faces : NULL; }
const int32_t *cm_sweep_boundary_groups(const cm_sweep *w, int tets) { return w ? boundary_of(w, tets)->groups : NULL; }
const size_t *cm_sweep_boundary_group_offsets(const cm_sweep *w, int tets)
{
    return w ? boundary_of(w, tets)->offsets : NULL;
}
const int64_t *cm_sweep_boundary_cells(const cm_sweep *w, int tets)
{
    return w ? boundary_of(w, tets)->cells : NULL;
}

cm_morph_method cm_sweep_morph_method(const cm_sweep *w) { return w ? w->morph_method : CM_MORPH_CONVEX; }

void cm_sweep_get_quality(const cm_sweep *w, cm_sweep_quality *quality)
{
    if (w && w->ns) *quality = w->quality;
    else memset(quality, 0, sizeof *quality);
}
