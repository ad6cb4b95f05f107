/* libFuzzer harness for the CLI's polygon reader (core/cli/read_polygon.c).
 * Built once per format, with FUZZ_PATH "input.xy", "input.obj" and "input.ply", so each format
 * gets its own corpus. Whatever the bytes, the reader must either return a
 * polygon (at least one finite vertex, a source line for each) or a
 * one-line "PATH..." message with a usage status; ASan and UBSan catch the
 * rest, LeakSanitizer the leaks. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "read_polygon.h"

#ifndef FUZZ_PATH
#error "define FUZZ_PATH"
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text) return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    polygon_input polygon;
    cli_error error = {{0}};
    int code = parse_polygon_text(FUZZ_PATH, text, size, &polygon, &error);
    free(text);
    if (code == CLI_EXIT_OK) {
        if (polygon.count == 0 || !polygon.xy || !polygon.source_line) abort();
        for (size_t i = 0; i < polygon.count; i++)
            if (!isfinite(polygon.xy[2 * i]) || !isfinite(polygon.xy[2 * i + 1]) ||
                polygon.source_line[i] < (polygon.by_index ? 0 : 1))
                abort();
    } else {
        if (code != CLI_EXIT_USAGE) abort();
        if (strncmp(error.message, FUZZ_PATH, strlen(FUZZ_PATH)) != 0) abort();
        if (strchr(error.message, '\n')) abort();
        if (polygon.count != 0 || polygon.xy || polygon.source_line) abort();
    }
    polygon_input_free(&polygon);
    return 0;
}
