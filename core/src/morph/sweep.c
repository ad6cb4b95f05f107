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
#include <stdlib.h>
#include <string.h>

#include "morph/morph.h"
#include "base/progress.h"
#include "geom/predicates.h"

typedef struct section {
    size_t g;   /* segment between geometries g and g + 1 */
    double s;   /* local time in [0, 1] */
    double z;
    double *xy; /* 2 * nv */
} section;

struct cm_sweep {
    cm_error error;
    size_t nv, ns, np, ntet;
    double *z, *nodes, volume;
    int32_t *prisms, *tets;
};

void cm_sweep_options_init(cm_sweep_options *options)
{
    memset(options, 0, sizeof *options);
    options->sections = 11;
    options->height = 1.0;
    options->max_refine = 1000;
}

static cm_status check_options(cm_sweep *w, const cm_morph *m, const cm_sweep_options *o)
{
    if (o->sections < 2) return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: sections must be >= 2, got %zu", o->sections);
    if (o->heights) {
        for (size_t g = 0; g < m->k; g++)
            if (!isfinite(o->heights[g]))
                return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: heights[%zu] is not finite", g);
        for (size_t g = 0; g + 1 < m->k; g++)
            if (!(o->heights[g + 1] > o->heights[g]))
                return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: heights must increase strictly: heights[%zu] = %g, heights[%zu] = %g",
                            g, o->heights[g], g + 1, o->heights[g + 1]);
    } else if (!(o->height > 0 && isfinite(o->height))) {
        return cm_fail(&w->error, CM_ERR_ARGUMENT, "sweep: height must be positive and finite, got %g", o->height);
    }
    return CM_OK;
}

/* Height of geometry g. */
static double level(const cm_morph *m, const cm_sweep_options *o, size_t g)
{
    return o->heights ? o->heights[g] : o->height * (double)g / (double)(m->k - 1);
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

static const int prism_rotations[6][6] = {
    {0, 1, 2, 3, 4, 5}, {1, 2, 0, 4, 5, 3}, {2, 0, 1, 5, 3, 4},
    {3, 5, 4, 0, 2, 1}, {4, 3, 5, 1, 0, 2}, {5, 4, 3, 2, 1, 0},
};

/* Dompierre et al.: turn the prism so its smallest global index is
 * corner 0; the quad face opposite it is cut along the diagonal from its
 * own smallest index. Every face is cut by its smallest vertex, so
 * neighbouring prisms agree. Writes 3 tets (12 local corners). */
static void split_prism(const int32_t v[6], int32_t out[12])
{
    int lo = 0;
    for (int i = 1; i < 6; i++)
        if (v[i] < v[lo]) lo = i;
    int32_t w[6];
    for (int i = 0; i < 6; i++) w[i] = v[prism_rotations[lo][i]];
    int32_t a = w[1] < w[5] ? w[1] : w[5], b = w[2] < w[4] ? w[2] : w[4];
    const int32_t first[12] = {w[0], w[1], w[2], w[5], w[0], w[1], w[5], w[4], w[0], w[4], w[5], w[3]};
    const int32_t second[12] = {w[0], w[1], w[2], w[4], w[0], w[4], w[2], w[5], w[0], w[4], w[5], w[3]};
    memcpy(out, a < b ? first : second, sizeof first);
}

static void node_xyz(const section *sec, int32_t local, size_t nv, double p[3])
{
    const section *x = sec + (local >= (int32_t)nv);
    size_t v = (size_t)local % nv;
    p[0] = x->xy[2 * v], p[1] = x->xy[2 * v + 1], p[2] = x->z;
}

/* First triangle whose prism between sections lo and lo + 1 is invalid
 * (blend or, with tets, a tetrahedron not positive), or -1. */
static long first_invalid(const cm_morph *m, const section *lo, int tets)
{
    const int32_t *tri = m->result->mesh.tri;
    size_t nv = m->nv;
    for (size_t t = 0; t < m->nt; t++) {
        const int32_t *c = tri + 3 * t;
        const double *p0 = lo[0].xy, *p1 = lo[1].xy;
        if (!cm_blend_positive(p0 + 2 * (size_t)c[0], p0 + 2 * (size_t)c[1], p0 + 2 * (size_t)c[2],
                               p1 + 2 * (size_t)c[0], p1 + 2 * (size_t)c[1], p1 + 2 * (size_t)c[2]))
            return (long)t;
        if (!tets) continue;
        int32_t v[6] = {c[0], c[1], c[2], c[0] + (int32_t)nv, c[1] + (int32_t)nv, c[2] + (int32_t)nv}, q[12];
        split_prism(v, q);
        for (int j = 0; j < 3; j++) {
            double a[3], b[3], cc[3], d[3];
            node_xyz(lo, q[4 * j], nv, a), node_xyz(lo, q[4 * j + 1], nv, b);
            node_xyz(lo, q[4 * j + 2], nv, cc), node_xyz(lo, q[4 * j + 3], nv, d);
            if (cm_orient3d(a, b, cc, d) <= 0) return (long)t;
        }
    }
    return -1;
}

static void free_sections(section *secs, size_t count)
{
    if (secs)
        for (size_t i = 0; i < count; i++) free(secs[i].xy);
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

static cm_status build_prisms(cm_sweep *w, cm_morph *m, const cm_sweep_options *o)
{
    cm_progress progress;
    cm_progress_init(&progress, o->progress, o->progress_user);
    size_t per = o->sections - 1, count = (m->k - 1) * per + 1, cap = count + 16;
    section *secs = calloc(cap, sizeof *secs);
    cm_status s = CM_OK;
    if (!secs) return cm_fail_status(&w->error, CM_ERR_NO_MEMORY);
    for (size_t i = 0; i < count && s == CM_OK; i++) {
        size_t g = i / per, j = i % per;
        if (g == m->k - 1) g--, j = per; /* the last section ends the last segment */
        secs[i].g = g;
        secs[i].s = (double)j / (double)per;
        double z0 = level(m, o, g), z1 = level(m, o, g + 1);
        secs[i].z = j == per ? z1 : between(z0, z1, secs[i].s);
        s = make_section(w, m, &secs[i]);
    }
    size_t refined = 0;
    for (size_t i = 0; i + 1 < count && s == CM_OK;) {
        if (cm_progress_report(&progress, CM_STAGE_SWEEP, (double)i / (double)count)) {
            s = cm_fail_status(&w->error, CM_ERR_CANCELLED);
            break;
        }
        long bad = first_invalid(m, secs + i, o->tets);
        if (bad < 0) {
            i++;
            continue;
        }
        /* End of this segment: the next section starts the next one. */
        double s_end = secs[i + 1].g == secs[i].g ? secs[i + 1].s : 1.0;
        if (refined == o->max_refine) {
            s = cm_fail(&w->error, CM_ERR_INTERNAL,
                     "sweep: the prism of triangle %ld between z = %g and z = %g is not valid along its blend%s "
                     "after %zu inserted sections (max_refine)",
                     bad, secs[i].z, secs[i + 1].z, o->tets ? " or its tetrahedra" : "", refined);
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
        section mid = {secs[i].g, 0.5 * (secs[i].s + s_end), midway(secs[i].z, secs[i + 1].z), NULL};
        if (!(mid.s > secs[i].s && mid.s < s_end)) {
            s = cm_fail(&w->error, CM_ERR_INTERNAL, "sweep: the prism of triangle %ld at z = %g needs a finer step than doubles allow",
                     bad, secs[i].z);
            break;
        }
        memmove(secs + i + 2, secs + i + 1, (count - i - 1) * sizeof *secs);
        secs[i + 1] = mid;
        count++, refined++;
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
                if (w->tets) split_prism(q, w->tets + 12 * p);
            }
    }
    free_sections(secs, count);
    return s;
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
    if (s == CM_OK) s = build_prisms(w, morph, options);
    if (s != CM_OK) {
        free(w->z), free(w->nodes), free(w->prisms), free(w->tets);
        w->z = w->nodes = NULL, w->prisms = w->tets = NULL;
        w->ns = w->np = w->ntet = w->nv = 0, w->volume = 0;
    }
    return cm_error_close(&w->error, s);
}

void cm_sweep_free(cm_sweep *w)
{
    if (!w) return;
    free(w->z), free(w->nodes), free(w->prisms), free(w->tets);
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
