/* The bad-input matrix (tests/bad_input/cases.txt) through the C API, both
 * entry points: the expected status, a one-line message with the expected
 * fragment, the error location, no geometry on a failed result, and a
 * result valid by the independent exact check on the legal cases. */
#include <string.h>

#include "bad_input_cases.h"
#include "check.h"
#include "result_check.h"

static void check_case(const bic_case *c, cm_result *r, cm_status s, const char *entry)
{
    CHECK_MSG(s == c->status, "%s, %s: got %s (%s), want %s", c->name, entry, cm_status_string(s),
              cm_result_message(r), cm_status_string(c->status));
    CHECK_MSG(r && cm_result_status(r) == s, "%s, %s: the handle carries the status", c->name, entry);
    const char *message = cm_result_message(r);
    CHECK_MSG(strstr(message, c->fragment) && !strchr(message, '\n'),
              "%s, %s: message '%s' lacks '%s' or is not one line", c->name, entry, message, c->fragment);
    if (s != CM_OK) {
        CHECK_MSG(message[0] != '\0', "%s, %s: empty message", c->name, entry);
        long p = -3, v = -3;
        cm_result_error_location(r, &p, &v, NULL);
        CHECK_MSG((c->polygon == BIC_NOT_CHECKED || p == c->polygon) &&
                      (c->vertex == BIC_NOT_CHECKED || v == c->vertex),
                  "%s, %s: location (%ld, %ld), want (%ld, %ld)", c->name, entry, p, v, c->polygon, c->vertex);
        CHECK_MSG(cm_result_num_triangles(r) == 0 && !cm_result_triangles(r) && !cm_result_vertices(r, 0),
                  "%s, %s: a failed result exposes no geometry", c->name, entry);
    } else {
        char why[256] = "";
        CHECK_MSG(rc_check(r, (const double *const *)c->xy, c->k, c->counts[0], why, sizeof why),
                  "%s, %s: invalid result: %s", c->name, entry, why);
    }
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "tests/bad_input/cases.txt";
    bic_case *cases;
    size_t count;
    if (bic_load(path, &cases, &count) != 0) return 1;
    for (size_t i = 0; i < count; i++) {
        const bic_case *c = &cases[i];
        cm_result *r = NULL;
        cm_status s = cm_triangulate_polygons((const double *const *)c->xy, c->counts, c->k, NULL, &r);
        check_case(c, r, s, "cm_triangulate_polygons");
        cm_result_free(r);
        /* cm_triangulate takes one array: only for equal counts. */
        int equal = 1;
        for (size_t g = 1; g < c->k; g++) equal &= c->counts[g] == c->counts[0];
        if (!equal) continue;
        size_t n = c->counts[0];
        double *xy = malloc(sizeof(double) * 2 * n * c->k + 1);
        for (size_t g = 0; g < c->k; g++) memcpy(xy + 2 * n * g, c->xy[g], sizeof(double) * 2 * n);
        s = cm_triangulate(xy, c->k, n, NULL, &r);
        check_case(c, r, s, "cm_triangulate");
        cm_result_free(r);
        free(xy);
    }
    printf("%zu cases\n", count);
    bic_free(cases, count);
    return check_summary("test_input_matrix");
}
