/* The ceiling's cost and value on the pairs of a cm_gen_pairs directory.
 *   cm_ceiling_bench DIR [RUNS]
 * prints one tab-separated line per pair: name, n, ceiling, corner-fan cap,
 * correspondence bound (degrees), certified modulus distortion K, and the
 * median and the least over RUNS (default 5) of stats.seconds_ceiling (the
 * least is the cost on a machine busy with other work). The construction
 * runs too (remeshing off), so the times are those of a real call. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compatmesh/compatmesh.h"
#include "read_xy.h"

#define MAX_K 3

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: cm_ceiling_bench DIR [RUNS]\n");
        return 2;
    }
    int runs = argc > 2 ? atoi(argv[2]) : 5;
    if (runs < 1 || runs > 100) runs = 5;
    char path[4096], line[1024];
    snprintf(path, sizeof path, "%s/pairs.txt", argv[1]);
    FILE *list = fopen(path, "r");
    if (!list) {
        fprintf(stderr, "cm_ceiling_bench: cannot read %s: %s\n", path, strerror(errno));
        return 1;
    }
    printf("pair\tn\tceiling_deg\tcorner_fan_cap_deg\tcorrespondence_bound_deg\tK\tseconds\tleast_seconds\n");
    int status = 0;
    while (fgets(line, sizeof line, list)) {
        char name[64], file[MAX_K][256];
        int k = sscanf(line, "%63s %255s %255s %255s", name, file[0], file[1], file[2]) - 1;
        if (k < 2) continue;
        double *xy[MAX_K] = {NULL};
        size_t counts[MAX_K];
        for (int g = 0; g < k; g++) {
            snprintf(path, sizeof path, "%s/%s", argv[1], file[g]);
            int m = read_xy(path, &xy[g]);
            counts[g] = m > 0 ? (size_t)m : 0;
        }
        cm_options o;
        cm_options_init(&o);
        o.remesh = 0;
        if (counts[0] != counts[1] || (k > 2 && counts[0] != counts[2])) o.correspondence = CM_CORRESPOND_AUTO;
        double seconds[100];
        cm_stats st = {0};
        for (int r = 0; r < runs; r++) {
            cm_result *res = NULL;
            cm_status s = cm_triangulate_polygons((const double *const *)xy, counts, (size_t)k, &o, &res);
            if (s != CM_OK) {
                fprintf(stderr, "cm_ceiling_bench: %s: %s\n", name, res ? cm_result_message(res) : "out of memory");
                status = 1;
                cm_result_free(res);
                break;
            }
            st = *cm_result_stats(res);
            seconds[r] = st.seconds_ceiling;
            cm_result_free(res);
        }
        qsort(seconds, (size_t)runs, sizeof *seconds, by_value);
        printf("%s\t%zu\t%.3f\t%.3f\t%.3f\t%.4g\t%.5f\t%.5f\n", name, st.n, st.ceiling_deg, st.corner_fan_cap_deg,
               st.correspondence_bound_deg, st.modulus_distortion, seconds[runs / 2], seconds[0]);
        for (int g = 0; g < k; g++) free(xy[g]);
    }
    fclose(list);
    return status;
}
