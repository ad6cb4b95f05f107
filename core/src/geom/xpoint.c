/* Exact constructed points. Homogeneous coordinates (X, Y, W) with GMP
 * integers: the line through two points is their cross product and the
 * intersection of two lines is the cross product of the lines, so a
 * construction never divides and never rounds. Orientation is the sign of
 * the 3x3 determinant times the signs of the three W. */
#include "geom/xpoint.h"

#include <gmp.h>
#include <math.h>
#include <stdlib.h>

#include "geom/predicates.h"


typedef struct xpoint {
    double xy[2];
    double err;  /* bound on |approx - exact| per coordinate; 0 for input */
    mpz_t *hom;  /* 3 integers for constructed points, NULL for input */
} xpoint;

struct cm_xpool {
    xpoint *p;
    long n, cap;
    mpz_t s[3][3]; /* homogeneous scratch for up to three points */
    mpz_t t[8];    /* arithmetic scratch */
    mpz_t l[2][3]; /* the two lines of an intersection */
};

cm_xpool *cm_xpool_create(void)
{
    cm_xpool *pool = calloc(1, sizeof *pool);
    if (!pool) return NULL;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) mpz_init(pool->s[i][j]);
    for (int i = 0; i < 8; i++) mpz_init(pool->t[i]);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++) mpz_init(pool->l[i][j]);
    return pool;
}

static void free_point(xpoint *q)
{
    if (!q->hom) return;
    for (int i = 0; i < 3; i++) mpz_clear(q->hom[i]);
    free(q->hom);
    q->hom = NULL;
}

void cm_xpool_truncate(cm_xpool *pool, long count)
{
    while (pool->n > count) free_point(&pool->p[--pool->n]);
}

void cm_xpool_free(cm_xpool *pool)
{
    if (!pool) return;
    cm_xpool_truncate(pool, 0);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) mpz_clear(pool->s[i][j]);
    for (int i = 0; i < 8; i++) mpz_clear(pool->t[i]);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++) mpz_clear(pool->l[i][j]);
    free(pool->p);
    free(pool);
}

long cm_xpool_count(const cm_xpool *pool) { return pool->n; }
const double *cm_xpool_xy(const cm_xpool *pool, long id) { return pool->p[id].xy; }
int cm_xpool_is_input(const cm_xpool *pool, long id) { return pool->p[id].hom == NULL; }

static long append(cm_xpool *pool)
{
    if (pool->n == pool->cap) {
        long cap = pool->cap ? 2 * pool->cap : 64;
        xpoint *p = realloc(pool->p, (size_t)cap * sizeof *p);
        if (!p) return -1;
        pool->p = p;
        pool->cap = cap;
    }
    pool->p[pool->n].hom = NULL;
    pool->p[pool->n].err = 0.0;
    return pool->n++;
}

long cm_xpool_add(cm_xpool *pool, double x, double y)
{
    long id = append(pool);
    if (id < 0) return -1;
    pool->p[id].xy[0] = x;
    pool->p[id].xy[1] = y;
    return id;
}

/* v = m * 2^e with m a 53-bit integer: writes m into z, returns e. */
static long split_double(mpz_t z, double v)
{
    if (v == 0.0) {
        mpz_set_ui(z, 0);
        return 0;
    }
    int e;
    double f = frexp(v, &e);
    mpz_set_d(z, ldexp(f, 53));
    return (long)e - 53;
}

/* Homogeneous coordinates of point id into out[0..2] (W > 0 for inputs). */
static void homogeneous(cm_xpool *pool, long id, mpz_t out[3])
{
    const xpoint *q = &pool->p[id];
    if (q->hom) {
        for (int i = 0; i < 3; i++) mpz_set(out[i], q->hom[i]);
        return;
    }
    long ex = split_double(out[0], q->xy[0]), ey = split_double(out[1], q->xy[1]);
    long emin = ex < ey ? ex : ey;
    if (emin > 0) emin = 0;
    mpz_mul_2exp(out[0], out[0], (mp_bitcnt_t)(ex - emin));
    mpz_mul_2exp(out[1], out[1], (mp_bitcnt_t)(ey - emin));
    mpz_set_ui(out[2], 1);
    mpz_mul_2exp(out[2], out[2], (mp_bitcnt_t)(-emin));
}

/* out = u x v (3-vectors); out must not alias u or v. */
static void cross3(cm_xpool *pool, mpz_t out[3], mpz_t u[3], mpz_t v[3])
{
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        mpz_mul(out[i], u[j], v[k]);
        mpz_mul(pool->t[0], u[k], v[j]);
        mpz_sub(out[i], out[i], pool->t[0]);
    }
}

/* X / W as a double, relative error below 2^-50. */
static double ratio(const mpz_t x, const mpz_t w)
{
    if (mpz_sgn(x) == 0) return 0.0;
    long ex, ew;
    double dx = mpz_get_d_2exp(&ex, x), dw = mpz_get_d_2exp(&ew, w);
    return ldexp(dx / dw, (int)(ex - ew));
}

long cm_xpool_intersect(cm_xpool *pool, long a, long b, long c, long d)
{
    mpz_t *l1 = pool->l[0], *l2 = pool->l[1];
    homogeneous(pool, a, pool->s[0]);
    homogeneous(pool, b, pool->s[1]);
    cross3(pool, l1, pool->s[0], pool->s[1]);
    homogeneous(pool, c, pool->s[0]);
    homogeneous(pool, d, pool->s[1]);
    cross3(pool, l2, pool->s[0], pool->s[1]);
    cross3(pool, pool->s[2], l1, l2);
    if (mpz_sgn(pool->s[2][2]) == 0) return -2;

    long id = append(pool);
    if (id < 0) return -1;
    xpoint *q = &pool->p[id];
    q->hom = malloc(3 * sizeof *q->hom);
    if (!q->hom) {
        pool->n--;
        return -1;
    }
    /* Divide out common powers of two: keeps the integers short. */
    mp_bitcnt_t shift = mpz_scan1(pool->s[2][2], 0);
    for (int i = 0; i < 2; i++)
        if (mpz_sgn(pool->s[2][i]) != 0) {
            mp_bitcnt_t z = mpz_scan1(pool->s[2][i], 0);
            if (z < shift) shift = z;
        }
    for (int i = 0; i < 3; i++) {
        mpz_init(q->hom[i]);
        mpz_fdiv_q_2exp(q->hom[i], pool->s[2][i], shift);
    }
    q->xy[0] = ratio(q->hom[0], q->hom[2]);
    q->xy[1] = ratio(q->hom[1], q->hom[2]);
    double big = fmax(fabs(q->xy[0]), fabs(q->xy[1]));
    q->err = big * 0x1p-48 + 0x1p-1000;
    if (!isfinite(q->xy[0]) || !isfinite(q->xy[1])) q->err = INFINITY;
    return id;
}

/* Sign of the 3x3 determinant of three homogeneous points. */
static int exact_orient(cm_xpool *pool, long a, long b, long c)
{
    long id[3] = {a, b, c};
    for (int i = 0; i < 3; i++) homogeneous(pool, id[i], pool->s[i]);
    mpz_t *r0 = pool->s[0], *r1 = pool->s[1], *r2 = pool->s[2];
    /* det = r0 . (r1 x r2) */
    mpz_set_ui(pool->t[1], 0);
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        mpz_mul(pool->t[2], r1[j], r2[k]);
        mpz_mul(pool->t[3], r1[k], r2[j]);
        mpz_sub(pool->t[2], pool->t[2], pool->t[3]);
        mpz_addmul(pool->t[1], r0[i], pool->t[2]);
    }
    int sign = mpz_sgn(pool->t[1]);
    for (int i = 0; i < 3; i++) sign *= mpz_sgn(pool->s[i][2]);
    return sign;
}

int cm_xorient(cm_xpool *pool, long a, long b, long c)
{
    if (a == b || b == c || a == c) return 0; /* spares the exact path */
    const xpoint *pa = &pool->p[a], *pb = &pool->p[b], *pc = &pool->p[c];
    if (!pa->hom && !pb->hom && !pc->hom) return cm_orient2d(pa->xy, pb->xy, pc->xy);
    double e = pa->err + pb->err + pc->err;
    if (isfinite(e)) {
        double bax = pb->xy[0] - pa->xy[0], bay = pb->xy[1] - pa->xy[1];
        double cax = pc->xy[0] - pa->xy[0], cay = pc->xy[1] - pa->xy[1];
        double l = bax * cay, r = bay * cax, det = l - r;
        double bound = e * (fabs(bax) + fabs(bay) + fabs(cax) + fabs(cay)) + 2.0 * e * e +
                       8.0 * CM_EPS * (fabs(l) + fabs(r));
        if (det > 1.01 * bound) return 1;
        if (-det > 1.01 * bound) return -1;
    }
    return exact_orient(pool, a, b, c);
}

int cm_xcompare(cm_xpool *pool, long p, long q, int axis)
{
    const xpoint *pp = &pool->p[p], *pq = &pool->p[q];
    double diff = pp->xy[axis] - pq->xy[axis];
    if (!pp->hom && !pq->hom) return (diff > 0) - (diff < 0);
    double bound = 1.01 * (pp->err + pq->err + CM_EPS * fabs(diff));
    if (isfinite(bound) && fabs(diff) > bound) return (diff > 0) - (diff < 0);
    homogeneous(pool, p, pool->s[0]);
    homogeneous(pool, q, pool->s[1]);
    /* P/Wp - Q/Wq has the sign of (P Wq - Q Wp) Wp Wq */
    mpz_mul(pool->t[1], pool->s[0][axis], pool->s[1][2]);
    mpz_mul(pool->t[2], pool->s[1][axis], pool->s[0][2]);
    mpz_sub(pool->t[1], pool->t[1], pool->t[2]);
    return mpz_sgn(pool->t[1]) * mpz_sgn(pool->s[0][2]) * mpz_sgn(pool->s[1][2]);
}
