#include <compatmesh/compatmesh.h>

#include <stdio.h>

int main(void)
{
    /* Two polygons of n = 4 vertices, k * n * 2 doubles, vertex i of one
     * corresponding to vertex i of the other. */
    const double xy[] = {0, 0, 4, 0, 4, 3, 0, 3,   /* a rectangle */
                         0, 0, 4, 1, 3, 4, -1, 2}; /* a quadrilateral */
    cm_result *r = NULL;
    if (cm_triangulate(xy, 2, 4, NULL, &r) != CM_OK) {
        fprintf(stderr, "%s\n", cm_result_message(r));
        cm_result_free(r);
        return 1;
    }
    const int32_t *t = cm_result_triangles(r);
    for (size_t i = 0; i < cm_result_num_triangles(r); i++)
        printf("triangle %d %d %d\n", t[3 * i], t[3 * i + 1], t[3 * i + 2]);
    cm_result_free(r);
    return 0;
}
