/* A static tree of boxes; see boxtree.h. */
#include "geom/boxtree.h"

#include <math.h>
#include <stdlib.h>

#define LEAF 4 /* items per leaf at most */

typedef struct keyed { uint32_t key; int32_t id; } keyed;

static int keyed_cmp(const void *a, const void *b)
{
    const keyed *p = a, *q = b;
    if (p->key != q->key) return p->key < q->key ? -1 : 1;
    return (p->id > q->id) - (p->id < q->id);
}

/* The low 16 bits of v spread to the even bits. */
static uint32_t spread(uint32_t v)
{
    v &= 0xffff;
    v = (v | v << 8) & 0x00ff00ff;
    v = (v | v << 4) & 0x0f0f0f0f;
    v = (v | v << 2) & 0x33333333;
    return (v | v << 1) & 0x55555555;
}

static uint32_t quantize(double v, double lo, double f)
{
    double q = floor((v - lo) * f);
    return q > 0 ? (q < 65535 ? (uint32_t)q : 65535) : 0; /* also NaN */
}

static int is_leaf(size_t lo, size_t hi) { return hi - lo <= LEAF; }

/* Node `node` over leaf-order items lo .. hi - 1: its box, from its
 * children's. */
static void fill(cm_boxtree *t, size_t node, size_t lo, size_t hi)
{
    double *b = t->node_box + 4 * node;
    b[0] = b[1] = HUGE_VAL, b[2] = b[3] = -HUGE_VAL;
    if (is_leaf(lo, hi)) {
        for (size_t i = lo; i < hi; i++) {
            const double *q = t->item_box + 4 * i;
            b[0] = fmin(b[0], q[0]), b[1] = fmin(b[1], q[1]), b[2] = fmax(b[2], q[2]), b[3] = fmax(b[3], q[3]);
        }
        return;
    }
    size_t mid = lo + (hi - lo) / 2;
    fill(t, 2 * node, lo, mid);
    fill(t, 2 * node + 1, mid, hi);
    for (size_t c = 2 * node; c <= 2 * node + 1; c++) {
        const double *q = t->node_box + 4 * c;
        b[0] = fmin(b[0], q[0]), b[1] = fmin(b[1], q[1]), b[2] = fmax(b[2], q[2]), b[3] = fmax(b[3], q[3]);
    }
}

int cm_boxtree_build(cm_boxtree *t, const double *box, size_t n)
{
    *t = (cm_boxtree){0};
    if (n == 0) return 0;
    size_t depth = 0;
    while ((n + ((size_t)1 << depth) - 1) >> depth > LEAF) depth++;
    t->n = n, t->nodes = (size_t)2 << depth;
    keyed *order = malloc(n * sizeof *order);
    t->item = malloc(n * sizeof *t->item);
    t->item_box = malloc(4 * n * sizeof *t->item_box);
    t->node_box = malloc(4 * t->nodes * sizeof *t->node_box);
    if (!order || !t->item || !t->item_box || !t->node_box) {
        free(order);
        cm_boxtree_free(t);
        return -1;
    }
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < 2; a++) {
            double c = 0.5 * (box[4 * i + a] + box[4 * i + a + 2]);
            lo[a] = fmin(lo[a], c), hi[a] = fmax(hi[a], c);
        }
    double f[2];
    for (int a = 0; a < 2; a++) f[a] = hi[a] > lo[a] ? 65535.0 / (hi[a] - lo[a]) : 0.0;
    for (size_t i = 0; i < n; i++) {
        uint32_t qx = quantize(0.5 * (box[4 * i] + box[4 * i + 2]), lo[0], f[0]);
        uint32_t qy = quantize(0.5 * (box[4 * i + 1] + box[4 * i + 3]), lo[1], f[1]);
        order[i] = (keyed){spread(qx) | spread(qy) << 1, (int32_t)i};
    }
    qsort(order, n, sizeof *order, keyed_cmp);
    for (size_t i = 0; i < n; i++) {
        t->item[i] = order[i].id;
        for (int a = 0; a < 4; a++) t->item_box[4 * i + a] = box[4 * (size_t)order[i].id + a];
    }
    free(order);
    fill(t, 1, 0, n);
    return 0;
}

void cm_boxtree_free(cm_boxtree *t)
{
    free(t->item), free(t->item_box), free(t->node_box);
    *t = (cm_boxtree){0};
}

typedef struct span { size_t node, lo, hi; } span; /* a node and its items */

static int meets(const double *b, const double *q)
{
    return b[0] <= q[2] && q[0] <= b[2] && b[1] <= q[3] && q[1] <= b[3];
}

/* Squared distance between the centres of boxes b and q, doubled. */
static double centre_gap(const double *b, const double *q)
{
    double dx = b[0] + b[2] - q[0] - q[2], dy = b[1] + b[3] - q[1] - q[3];
    return dx * dx + dy * dy;
}

int cm_boxtree_query(const cm_boxtree *t, double q[4], cm_boxtree_visit visit, void *ctx)
{
    if (t->n == 0) return 0;
    span stack[2 * 8 * sizeof(size_t) + 2]; /* depth <= bits of size_t, two per level */
    int top = 0;
    stack[top++] = (span){1, 0, t->n};
    while (top > 0) {
        size_t node = stack[--top].node, lo = stack[top].lo, hi = stack[top].hi;
        if (!meets(t->node_box + 4 * node, q)) continue;
        if (is_leaf(lo, hi)) {
            for (size_t i = lo; i < hi; i++) {
                if (!meets(t->item_box + 4 * i, q)) continue;
                int s = visit(ctx, t->item[i], q);
                if (s) return s;
            }
            continue;
        }
        size_t mid = lo + (hi - lo) / 2, l = 2 * node, r = 2 * node + 1;
        int left_first = centre_gap(t->node_box + 4 * l, q) <= centre_gap(t->node_box + 4 * r, q);
        if (left_first) { /* pushed last, popped first */
            stack[top++] = (span){r, mid, hi};
            stack[top++] = (span){l, lo, mid};
        } else {
            stack[top++] = (span){l, lo, mid};
            stack[top++] = (span){r, mid, hi};
        }
    }
    return 0;
}
