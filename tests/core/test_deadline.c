/* The call's time limit (base/deadline.c) and cm_options.time_limit: a
 * limit spent before the remesher starts stops it at its first safe point
 * with a valid, exactly checked result; one never reached changes nothing;
 * calls inside calls keep the earlier deadline. */
#include <stdlib.h>
#include <string.h>

#include "base/deadline.h"
#include "check.h"
#include "random_polygons.h"
#include "result_check.h"

/* Spends some of the thread's CPU time. */
static void spin(void)
{
    volatile double x = 0;
    for (int i = 0; i < 2000000; i++) x += 1e-9 * i;
}

static void test_nesting(void)
{
    CHECK(!cm_deadline_passed()); /* no call, no limit */
    cm_deadline none = cm_deadline_begin(0);
    spin();
    CHECK(!cm_deadline_passed());
    CHECK(cm_deadline_end(none) == 0);

    cm_deadline outer = cm_deadline_begin(1000);
    CHECK(!cm_deadline_passed());
    cm_deadline inner = cm_deadline_begin(0); /* keeps the outer deadline */
    CHECK(!cm_deadline_passed());
    CHECK(cm_deadline_end(inner) == 0);
    inner = cm_deadline_begin(1e-9); /* an earlier one of its own */
    spin();
    CHECK(cm_deadline_passed());
    CHECK(cm_deadline_end(inner) == 1);
    CHECK(!cm_deadline_passed()); /* the outer deadline is in force again */
    CHECK(cm_deadline_end(outer) == 0);

    outer = cm_deadline_begin(1e-9);
    spin();
    inner = cm_deadline_begin(0); /* the same deadline, passed */
    CHECK(cm_deadline_passed());
    CHECK(cm_deadline_end(inner) == 1);
    CHECK(cm_deadline_passed());
    CHECK(cm_deadline_end(outer) == 1);
    CHECK(!cm_deadline_passed());
}

enum { N = 40 };

/* Two stars of N vertices, index correspondence: the remesher refines. */
static cm_result *run(const double *xy, double time_limit)
{
    cm_options o;
    cm_options_init(&o);
    o.time_limit = time_limit;
    cm_result *r = NULL;
    CHECK(cm_triangulate(xy, 2, N, &o, &r) == CM_OK);
    char why[256] = "";
    const double *polygons[2] = {xy, xy + 2 * N};
    CHECK_MSG(r && rc_check(r, polygons, 2, N, why, sizeof why), "limit %g: %s", time_limit, why);
    return r;
}

static void test_options(void)
{
    double xy[4 * N];
    CHECK(rp_star(xy, N, 3) == 0 && rp_star(xy + 2 * N, N, 4) == 0);
    cm_result *free_run = run(xy, 0), *spent = run(xy, 1e-9), *ample = run(xy, 1e6);
    const cm_stats *f = cm_result_stats(free_run), *s = cm_result_stats(spent), *a = cm_result_stats(ample);
    CHECK(!f->time_limit_reached && f->remesh_iterations > 0);
    CHECK(s->time_limit_reached && s->remesh_iterations == 0 && s->steiner <= s->steiner_before_remesh);
    CHECK(!a->time_limit_reached && a->steiner == f->steiner && a->remesh_iterations == f->remesh_iterations);
    size_t nv = cm_result_num_vertices(free_run);
    CHECK(cm_result_num_vertices(ample) == nv);
    for (size_t g = 0; g < 2 && cm_result_num_vertices(ample) == nv; g++)
        CHECK(memcmp(cm_result_vertices(free_run, g), cm_result_vertices(ample, g), 2 * nv * sizeof(double)) == 0);
    cm_result_free(free_run), cm_result_free(spent), cm_result_free(ample);

    cm_options o;
    cm_options_init(&o);
    o.time_limit = -1;
    cm_result *r = NULL;
    CHECK(cm_triangulate(xy, 2, N, &o, &r) == CM_ERR_ARGUMENT && strstr(cm_result_message(r), "time_limit"));
    cm_result_free(r);
}

int main(void)
{
    test_nesting();
    test_options();
    return check_summary("test_deadline");
}
