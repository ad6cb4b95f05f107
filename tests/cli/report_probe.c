/* Writes a morph report through the tool's own writer (cli/write_report.c)
 * with chosen doubles, for test_report_numbers.py:
 *
 *     report_probe OUT.json X1 X2 ...
 *
 * Frame f gets t = Xf and smallest angle Xf (read by strtod, so C99 hex
 * floats give the exact doubles); the triangulation is a square with itself.
 * Exit 0 when written; 1 with the writer's message on stderr otherwise. */
#include <stdio.h>
#include <stdlib.h>

#include <compatmesh/compatmesh.h>

#include "write_report.h"

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: report_probe OUT.json X1 X2 ...\n");
        return 2;
    }
    static const double square[] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 2, 0, 2, 2, 0, 2};
    cm_result *result = NULL;
    if (cm_triangulate(square, 2, 4, NULL, &result) != CM_OK) {
        fprintf(stderr, "report_probe: the square does not triangulate\n");
        cm_result_free(result);
        return 1;
    }
    size_t frames = (size_t)argc - 2;
    double *values = malloc(frames * sizeof *values);
    size_t *inverted = calloc(frames, sizeof *inverted);
    const char **files = malloc(frames * sizeof *files);
    if (!values || !inverted || !files) return 1;
    for (size_t f = 0; f < frames; f++) {
        values[f] = strtod(argv[2 + f], NULL);
        files[f] = "frame.off";
    }
    static const char *const inputs[] = {"a.xy", "b.xy"};
    morph_report_info info = {result, "partition", "convex", inputs, frames, files,
                              values, values, inverted};
    cli_error error;
    int code = write_morph_report(argv[1], &info, &error);
    if (code != CLI_EXIT_OK) fprintf(stderr, "report_probe: %s\n", error.message);
    free(values), free(inverted), free(files);
    cm_result_free(result);
    return code;
}
