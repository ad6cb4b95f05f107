/* The pairs of polygons with holes that tests/core/test_holes.c (and
 * test_alloc_failures.c) check,
 * built in one place so that bench/glyph_holes.c (--fixtures) measures the
 * same pairs: each pair's loops, outer loop first, and the builders. */
#ifndef CM_HOLE_FIXTURES_H
#define CM_HOLE_FIXTURES_H

#include <complex.h>
#include <math.h>
#include <stddef.h>

#define HF_MAX_LOOPS 8
#define HF_MAX_VERTICES 512

/* One polygon with holes under construction. */
typedef struct shape {
    double xy[2 * HF_MAX_VERTICES];
    size_t sizes[HF_MAX_LOOPS], loops, n;
} shape;

static inline void add_point(shape *s, double x, double y)
{
    s->xy[2 * s->n] = x, s->xy[2 * s->n + 1] = y;
    s->n++, s->sizes[s->loops - 1]++;
}

static inline void begin_loop(shape *s) { s->sizes[s->loops++] = 0; }

/* A circle of m points from angle `from` (radians), counter-clockwise
 * (dir 1) or clockwise (-1). */
static inline void add_circle_from(shape *s, double cx, double cy, double radius, size_t m, int dir, double from)
{
    begin_loop(s);
    for (size_t i = 0; i < m; i++) {
        double a = dir * 2 * 3.14159265358979323846 * (double)i / (double)m + from;
        add_point(s, cx + radius * cos(a), cy + radius * sin(a));
    }
}

/* A circle of m points from angle 0. */
static inline void add_circle(shape *s, double cx, double cy, double radius, size_t m, int dir)
{
    add_circle_from(s, cx, cy, radius, m, dir, 0);
}

/* An axis-aligned square of side 2 h around (cx, cy), m points (m a
 * multiple of 4), from its lower left corner, either way. */
static inline void add_square(shape *s, double cx, double cy, double h, size_t m, int dir)
{
    begin_loop(s);
    size_t side = m / 4;
    double corners[5][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    if (dir < 0) corners[1][0] = -1, corners[1][1] = 1, corners[3][0] = 1, corners[3][1] = -1;
    for (size_t c = 0; c < 4; c++)
        for (size_t i = 0; i < side; i++) {
            double t = (double)i / (double)side;
            add_point(s, cx + h * ((1 - t) * corners[c][0] + t * corners[c + 1][0]),
                      cy + h * ((1 - t) * corners[c][1] + t * corners[c + 1][1]));
        }
}

/* A triangle hole (clockwise) of circumradius r around (cx, cy), turned by a. */
static inline void add_triangle(shape *s, double cx, double cy, double r, double a)
{
    begin_loop(s);
    for (int i = 0; i < 3; i++) add_point(s, cx + r * cos(a - 2.0944 * i), cy + r * sin(a - 2.0944 * i));
}

/* A square with a square hole against a disc with an off-centre round hole. */
static inline void hf_square_disc(shape *a, shape *b)
{
    add_square(a, 0, 0, 1, 16, 1);
    add_square(a, 0, 0, 0.4, 8, -1);
    add_circle(b, 0, 0, 1, 16, 1);
    add_circle(b, 0.3, 0.2, 0.35, 8, -1);
}

/* The same with the holes given counter-clockwise, the outer loops clockwise. */
static inline void hf_square_disc_reversed(shape *a, shape *b)
{
    add_square(a, 0, 0, 1, 16, -1);
    add_square(a, 0, 0, 0.4, 8, 1);
    add_circle(b, 0, 0, 1, 16, -1);
    add_circle(b, 0.3, 0.2, 0.35, 8, 1);
}

/* A plate with 3 bolt holes against a rotated, sheared copy with the holes
 * moved apart. */
static inline void hf_plate(shape *a, shape *b)
{
    add_square(a, 0, 0, 2, 24, 1);
    double centres[3][2] = {{-1, -1}, {1, -0.8}, {0, 1}};
    for (int h = 0; h < 3; h++) add_circle(a, centres[h][0], centres[h][1], 0.45, 10, -1);
    *b = *a;
    double c = cos(0.5), s = sin(0.5);
    for (size_t i = 0; i < b->n; i++) {
        double x = a->xy[2 * i], y = a->xy[2 * i + 1];
        if (i >= 24) x += 0.15 * centres[(i - 24) / 10][0], y += 0.1; /* holes moved apart */
        x += 0.4 * y; /* shear */
        b->xy[2 * i] = c * x - s * y, b->xy[2 * i + 1] = s * x + c * y;
    }
}

/* An annulus (outer radius 1, m points; hole radius 0.6, h points) whose
 * hole is turned half a turn in the second polygon (hole vertex i sits
 * opposite where it was): no straight chord from the hole to the outer loop
 * is inside the material in both. */
static inline void hf_turned_annulus(shape *a, shape *b, size_t m, size_t h)
{
    add_circle(a, 0, 0, 1, m, 1);
    add_circle(a, 0, 0, 0.6, h, -1);
    *b = *a;
    for (size_t i = m; i < m + h; i++) b->xy[2 * i] = -a->xy[2 * i], b->xy[2 * i + 1] = -a->xy[2 * i + 1];
}

static inline void hf_turned_hole(shape *a, shape *b) { hf_turned_annulus(a, b, 24, 12); }

static inline void hf_turned_hole_small(shape *a, shape *b) { hf_turned_annulus(a, b, 12, 6); }

/* Two holes in a disc, each turned half a turn about its centre. */
static inline void hf_two_turned_holes(shape *a, shape *b)
{
    add_circle(a, 0, 0, 1, 32, 1);
    add_circle(a, -0.45, 0, 0.3, 10, -1);
    add_circle(a, 0.45, 0, 0.3, 10, -1);
    *b = *a;
    for (size_t i = 32; i < 52; i++) {
        double cx = i < 42 ? -0.45 : 0.45;
        b->xy[2 * i] = 2 * cx - a->xy[2 * i], b->xy[2 * i + 1] = -a->xy[2 * i + 1];
    }
}

/* Five triangle holes in a four-cornered square, in a row in one polygon
 * and on a circle, turned, in the other: the bridges' pieces need two paths
 * per hole that share no vertex, 20 ends among 19 vertices. */
static inline void hf_five_triangles(shape *a, shape *b)
{
    begin_loop(a);
    add_point(a, 0, 0), add_point(a, 10, 0), add_point(a, 10, 10), add_point(a, 0, 10);
    *b = *a;
    for (int h = 0; h < 5; h++) {
        add_triangle(a, 1.5 + 1.75 * h, 5, 0.6, 0);
        add_triangle(b, 5 + 3 * cos(1.2566 * h), 5 + 3 * sin(1.2566 * h), 0.6, 1.0 + h);
    }
}

/* A small hole right of a central one in one polygon and left of it in the
 * other: the central hole's shortest common chords, up and down, leave the
 * small hole in the right piece of one and the left piece of the other,
 * where no path from it is inside the material in both. */
static inline void hf_swapped_sides(shape *a, shape *b)
{
    add_square(a, 0, 0, 1, 8, 1);
    add_square(a, 0, 0, 0.3, 4, -1);
    *b = *a;
    add_triangle(a, 0.65, 0, 0.15, 0);
    add_triangle(b, -0.65, 0, 0.15, 0);
}

/* Seven round holes of 6 vertices on a grid in a disc of 40, their places
 * permuted in the other polygon, whose disc has outer_b vertices and each
 * hole hole_b. */
static inline void seven_holes(shape *a, shape *b, size_t outer_b, size_t hole_b)
{
    add_circle(a, 0, 0, 2, 40, 1);
    add_circle(b, 0, 0, 2, outer_b, 1);
    double places[7][2] = {{-1, -0.6}, {0, -0.6}, {1, -0.6}, {-1, 0.6}, {0, 0.6}, {1, 0.6}, {0, 1.4}};
    int order[7] = {5, 3, 6, 0, 2, 4, 1};
    for (int h = 0; h < 7; h++) {
        add_circle(a, places[h][0], places[h][1], 0.25, 6, -1);
        add_circle(b, places[order[h]][0], places[order[h]][1], 0.25, hole_b, -1);
    }
}

/* The seven holes with the same counts: the bridges of one polygon's tree
 * run between holes that are far apart in the other. */
static inline void hf_seven_permuted(shape *a, shape *b) { seven_holes(a, b, 40, 6); }

/* The seven holes with other vertex counts in the other polygon (48 on
 * the disc, 8 on each hole), so that auto is the default: a section's
 * holes listed in another order than its neighbour's. */
static inline void hf_seven_permuted_counts(shape *a, shape *b) { seven_holes(a, b, 48, 8); }

/* A rectangle of half sides w by h, m points a side, counter-clockwise from
 * its corner (-w, -h), the list started at its point `start`, moved by
 * (dx, dy). */
static inline void add_rectangle(shape *s, double w, double h, size_t m, size_t start, double dx, double dy)
{
    begin_loop(s);
    double corners[5][2] = {{-w, -h}, {w, -h}, {w, h}, {-w, h}, {-w, -h}};
    for (size_t i = 0; i < 4 * m; i++) {
        size_t j = (i + start) % (4 * m), c = j / m;
        double t = (double)(j % m) / (double)m;
        add_point(s, dx + (1 - t) * corners[c][0] + t * corners[c + 1][0],
                  dy + (1 - t) * corners[c][1] + t * corners[c + 1][1]);
    }
}

/* A rectangular plate with three bolt holes, and the same plate moved, its
 * outline listed from the opposite corner: a half turn takes the outline
 * onto itself, only the holes tell the two ways apart. exact: the same
 * loops moved (an affine image); else the second plate a little wider and
 * lower, 7 points a side, its holes moved a little and of 12 vertices. */
static inline void hf_rectangle_plates(shape *a, shape *b, int exact)
{
    double centres[3][2] = {{-2.5, -0.8}, {1, 0.9}, {2.8, -1.0}};
    add_rectangle(a, 4, 2, 6, 0, 0, 0);
    add_rectangle(b, exact ? 4 : 4.1, exact ? 2 : 1.9, exact ? 6 : 7, exact ? 12 : 14, 0.3, 10);
    for (int h = 0; h < 3; h++) {
        add_circle(a, centres[h][0], centres[h][1], 0.4, 10, -1);
        add_circle(b, centres[h][0] + 0.3 + (exact ? 0 : 0.05), centres[h][1] + 10 - (exact ? 0 : 0.03),
                   exact ? 0.4 : 0.38, exact ? 10 : 12, -1);
    }
}

static inline void hf_rectangle_plates_exact(shape *a, shape *b) { hf_rectangle_plates(a, b, 1); }
static inline void hf_rectangle_plates_near(shape *a, shape *b) { hf_rectangle_plates(a, b, 0); }

/* A square with an off-centre square hole (16 + 8 vertices) against a disc
 * with an off-centre round hole of other sizes (23 + 11), the disc's loops
 * the other way round: loops of different sizes. */
static inline void hf_sizes_differ(shape *a, shape *b)
{
    add_square(a, 0, 0, 1, 16, 1);
    add_square(a, 0.1, 0, 0.4, 8, -1);
    add_circle(b, 0, 0, 1, 23, -1);
    add_circle(b, 0.3, 0.2, 0.35, 11, 1);
}

/* A square (16 vertices) with a round hole of 24 vertices, 16 of them
 * crowded into 30 degrees, against a disc (20) with an off-centre hexagon
 * hole, the disc's loops the other way round (dir -1: outer clockwise,
 * hole counter-clockwise). Arc length puts the crowded stretch on one
 * edge of the hexagon, beside long pieces of the hole loop. */
static inline void hf_crowded_hole(shape *a, shape *b, int dir)
{
    const double pi = 3.14159265358979323846;
    add_square(a, 0, 0, 1, 16, 1);
    begin_loop(a);
    for (size_t i = 0; i < 24; i++) {
        double t = i < 16 ? (pi / 6) * (double)i / 16 : pi / 6 + (2 * pi - pi / 6) * (double)(i - 16) / 8;
        add_point(a, 0.5 * cos(-t), 0.5 * sin(-t));
    }
    add_circle(b, 0, 0, 1, 20, dir);
    add_circle(b, 0.2, 0.1, 0.4, 6, -dir);
}

static inline void hf_crowded_hole_reversed(shape *a, shape *b) { hf_crowded_hole(a, b, -1); }

/* An egg with a regular 12-gon hole, and its image under a similarity
 * (scale 2, turned 100 degrees, moved) renumbered from outer vertex 3,
 * whose hole is the image of the 24-gon through the 12-gon's vertices,
 * numbered so that vertex 19 is the image of the 12-gon's vertex 0. */
static inline void hf_egg(shape *a, shape *b)
{
    const double pi = 3.14159265358979323846, turn = 100 * pi / 180;
    const double complex scale = 2 * cexp(I * turn), shift = 5 + 3 * I;
    double complex egg[20], hole[24];
    for (size_t i = 0; i < 20; i++) {
        double t = 2 * pi * (double)i / 20;
        egg[i] = cos(t) * (1 + 0.3 * cos(t)) + 0.7 * I * sin(t);
    }
    for (size_t i = 0; i < 24; i++) hole[i] = 0.3 + 0.1 * I + 0.2 * cexp(-I * 2 * pi * (double)i / 24);
    begin_loop(a), begin_loop(b);
    for (size_t i = 0; i < 20; i++) {
        double complex w = scale * egg[(i + 3) % 20] + shift;
        add_point(a, creal(egg[i]), cimag(egg[i])), add_point(b, creal(w), cimag(w));
    }
    begin_loop(a), begin_loop(b);
    for (size_t i = 0; i < 12; i++) add_point(a, creal(hole[2 * i]), cimag(hole[2 * i]));
    for (size_t i = 0; i < 24; i++) {
        double complex w = scale * hole[(i + 5) % 24] + shift;
        add_point(b, creal(w), cimag(w));
    }
}

/* A loop through the m corners c, each edge cut into pieces of about h
 * (at least one). */
static inline void add_corners(shape *s, const double (*c)[2], size_t m, double h)
{
    begin_loop(s);
    for (size_t i = 0; i < m; i++) {
        const double *p = c[i], *q = c[(i + 1) % m];
        long pieces = lround(hypot(q[0] - p[0], q[1] - p[1]) / h);
        if (pieces < 1) pieces = 1;
        for (long j = 0; j < pieces; j++) {
            double t = (double)j / (double)pieces;
            add_point(s, p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]));
        }
    }
}

/* A square ring (side 2, 32 vertices; a square hole of side 0.8, 12)
 * against the same ring with a stem of height 4 on its right (a "d", 64
 * vertices), edges cut at about 0.25: loops of different sizes. The stem
 * takes most of the d's outline, so arc length from a start puts the
 * square's sides along it; the conformal correspondence of the filled
 * outer loops keeps the ring on the ring. */
static inline void hf_ring_and_stem(shape *a, shape *b)
{
    static const double ring[4][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    static const double stem[6][2] = {{0, 0}, {2, 0}, {2, 6}, {1.4, 6}, {1.4, 2}, {0, 2}};
    static const double hole[4][2] = {{0.6, 0.6}, {0.6, 1.4}, {1.4, 1.4}, {1.4, 0.6}}; /* clockwise */
    add_corners(a, ring, 4, 0.25), add_corners(a, hole, 4, 0.25);
    add_corners(b, stem, 6, 0.25), add_corners(b, hole, 4, 0.25);
}

/* Two sections of a pipe: circles of radius 2 (48 points from angle 0;
 * 40 from 0.3 radians) around holes of radius 1 (24 from 0; 20 from 0.1),
 * loops of other sizes, so auto pairs them. Every turn of a circle fits
 * a circle alike; a sweep wants the one that does not twist. */
static inline void hf_pipe(shape *a, shape *b)
{
    add_circle_from(a, 0, 0, 2, 48, 1, 0), add_circle_from(a, 0, 0, 1, 24, -1, 0);
    add_circle_from(b, 0, 0, 2, 40, 1, 0.3), add_circle_from(b, 0, 0, 1, 20, -1, 0.1);
}

/* A flange: a disc of radius 2 (48 points) with six bolt holes of radius
 * 0.3 (10 points) on the circle of radius 1.4, against the same flange
 * turned by 15 degrees (40 outline points from 0.3 radians), its holes
 * listed in the same order. The outline fixes no turn; of the turns that
 * put holes on holes (15 degrees plus multiples of 60), the least. */
static inline void hf_flange_turned(shape *a, shape *b)
{
    const double pi = 3.14159265358979323846, turn = 15 * pi / 180;
    add_circle_from(a, 0, 0, 2, 48, 1, 0), add_circle_from(b, 0, 0, 2, 40, 1, 0.3);
    for (int j = 0; j < 6; j++) {
        double at = j * pi / 3;
        add_circle_from(a, 1.4 * cos(at), 1.4 * sin(at), 0.3, 10, -1, 0);
        add_circle_from(b, 1.4 * cos(at + turn), 1.4 * sin(at + turn), 0.3, 10, -1, turn);
    }
}

/* A hexagonal plate (circumradius 2, `per` points a side) with six bolt
 * holes of radius 0.25 (10 points) on the circle of radius 1.2, between
 * its corners, all turned by `turn` radians. Six turns, 60 degrees apart,
 * take it onto itself. */
static inline void hex_flange(shape *s, double turn, size_t per)
{
    const double pi = 3.14159265358979323846;
    begin_loop(s);
    for (int k = 0; k < 6; k++) {
        double p[2] = {2 * cos(k * pi / 3 + turn), 2 * sin(k * pi / 3 + turn)};
        double q[2] = {2 * cos((k + 1) * pi / 3 + turn), 2 * sin((k + 1) * pi / 3 + turn)};
        for (size_t j = 0; j < per; j++) {
            double f = (double)j / (double)per;
            add_point(s, p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1]));
        }
    }
    for (int j = 0; j < 6; j++) {
        double at = j * pi / 3 + pi / 6 + turn;
        add_circle_from(s, 1.2 * cos(at), 1.2 * sin(at), 0.25, 10, -1, turn);
    }
}

/* The hexagonal flange (10 points a side) against itself turned by 15
 * degrees (8 points a side). */
static inline void hf_hex_flange_turned(shape *a, shape *b)
{
    hex_flange(a, 0, 10), hex_flange(b, 15 * 3.14159265358979323846 / 180, 8);
}

/* Every pair test_holes.c triangulates, once each (the overlay-method run of
 * square/disc is the same pair). */
typedef struct hole_fixture {
    const char *name;
    void (*build)(shape *, shape *);
} hole_fixture;

static inline size_t hole_fixture_list(const hole_fixture **list)
{
    static const hole_fixture fixtures[] = {
        {"square/disc", hf_square_disc},
        {"square/disc reversed loops", hf_square_disc_reversed},
        {"plate", hf_plate},
        {"turned hole", hf_turned_hole},
        {"turned hole, 12 + 6 (test_alloc_failures.c)", hf_turned_hole_small},
        {"two turned holes", hf_two_turned_holes},
        {"five triangle holes", hf_five_triangles},
        {"holes on swapped sides", hf_swapped_sides},
        {"seven holes permuted", hf_seven_permuted},
        {"seven holes permuted, other counts", hf_seven_permuted_counts},
        {"rectangular plates, half turned list", hf_rectangle_plates_near},
        {"square/disc, sizes differ", hf_sizes_differ},
        {"egg, hole renumbered", hf_egg},
        {"crowded hole", hf_crowded_hole_reversed},
        {"ring and stem", hf_ring_and_stem},
        {"pipe, turned", hf_pipe},
        {"flange, turned 15 degrees", hf_flange_turned},
    };
    *list = fixtures;
    return sizeof fixtures / sizeof fixtures[0];
}

#endif
