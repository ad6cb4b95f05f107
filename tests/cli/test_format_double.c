/* The text writers' numbers (cli/format_double.h): every double, printed by
 * format_double and by the OFF/OBJ/PLY and VTU writers, reads back through
 * strtod bit for bit, and is never longer than the shortest "%.*e" that
 * reads back. Random bit patterns cover every exponent, subnormals
 * included; the edge values are listed.
 *   test_format_double WORK_DIR */
#include <float.h>
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "format_double.h"
#include "interrupt.h"
#include "write_mesh.h"
#include "write_vtu.h"

/* outdir.c's flags, which interrupt.c (signal handling, not tested here)
 * defines in the tool. */
volatile sig_atomic_t interrupted, writing_output;

static int failures;

#define CHECK(cond, ...)                                                                           \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);                                   \
            fprintf(stderr, __VA_ARGS__);                                                          \
            fputc('\n', stderr);                                                                   \
            if (++failures > 20) exit(1);                                                          \
        }                                                                                          \
    } while (0)

static uint64_t bits_of(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    return bits;
}

static double double_of(uint64_t bits)
{
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

/* xorshift64*: the same numbers on every run. */
static uint64_t random_state = 0x9E3779B97F4A7C15u;
static uint64_t random_bits(void)
{
    random_state ^= random_state >> 12;
    random_state ^= random_state << 25;
    random_state ^= random_state >> 27;
    return random_state * 0x2545F4914F6CDD1Du;
}

/* A finite double: random bits (every exponent alike), a subnormal, or a
 * coordinate-like value of a few digits, in turn. */
static double random_double(size_t i)
{
    for (;;) {
        uint64_t bits = random_bits();
        double x;
        switch (i % 4) {
        case 0: x = double_of(bits); break;
        case 1: x = double_of(bits & 0x800FFFFFFFFFFFFFu); break; /* exponent 0 */
        case 2: x = (double)(int64_t)(bits >> 40) / 1024.0 - 4096.0; break;
        default: x = fmod(double_of(bits), 1000.0); break; /* NaN for inf: drawn again */
        }
        if (isfinite(x)) return x;
    }
}

static const double edge_values[] = {
    0.0, -0.0, 1.0, -1.0, 0.1, -0.1, 1.0 / 3.0, 2.0 / 3.0, 5e-324, -5e-324, DBL_MIN, -DBL_MIN,
    0x1.fffffffffffffp-1023 /* largest subnormal */, DBL_MAX, -DBL_MAX, DBL_EPSILON,
    1e-6, 9.999999999999999e-7, 1e-7, 1e16, 1e17, 99999999999999984.0, 1e21, 1e22, 1e23,
    9007199254740993.0, 123456789012345678.0, 0x1p-1022, 0x1p-1074, 0x1p1023, 9e59,
    4.35, 2.5e-320, 1.7976931348623157e308, 2.2250738585072009e-308,
};
enum { EDGE_COUNT = sizeof edge_values / sizeof edge_values[0], RANDOM_COUNT = 200000 };

static double value(size_t i)
{
    return i < EDGE_COUNT ? edge_values[i] : random_double(i);
}

/* Significant digits in text: the digits of the mantissa without leading
 * zeros and, for a plain number, without trailing zeros before no point. */
static int significant_digits(const char *text)
{
    const char *end = text + strcspn(text, "e");
    int digits = 0, pending_zeros = 0, started = 0;
    for (const char *c = text; c < end; c++) {
        if (*c < '0' || *c > '9') continue;
        if (*c == '0' && !started) continue;
        started = 1;
        if (*c == '0') {
            pending_zeros++;
        } else {
            digits += pending_zeros + 1;
            pending_zeros = 0;
        }
    }
    return digits ? digits : 1;
}

/* The fewest digits with which printf's correctly rounded "%.*e" reads back. */
static int printf_shortest_digits(double x)
{
    char text[64];
    for (int digits = 1; digits < 17; digits++) {
        snprintf(text, sizeof text, "%.*e", digits - 1, x);
        if (bits_of(strtod(text, NULL)) == bits_of(x)) return digits;
    }
    return 17;
}

static void check_format_double(void)
{
    for (size_t i = 0; i < EDGE_COUNT + RANDOM_COUNT; i++) {
        double x = value(i);
        char text[FORMAT_DOUBLE_SIZE + 8];
        memset(text, 'X', sizeof text);
        char *end = format_double(text, x);
        size_t length = (size_t)(end - text);
        CHECK(*end == '\0' && length == strlen(text) && length < FORMAT_DOUBLE_SIZE,
              "%a: length %zu, \"%.*s\"", x, length, FORMAT_DOUBLE_SIZE, text);
        char *parsed_end;
        double back = strtod(text, &parsed_end);
        CHECK(parsed_end == end, "%a: strtod stops early in \"%s\"", x, text);
        CHECK(bits_of(back) == bits_of(x), "%a (%016" PRIx64 "): \"%s\" reads back as %a", x,
              bits_of(x), text, back);
        int shortest = printf_shortest_digits(x);
        CHECK(significant_digits(text) <= shortest, "%a: \"%s\" has %d digits, %%.%de reads back",
              x, text, significant_digits(text), shortest - 1);
    }
    char text[FORMAT_DOUBLE_SIZE];
    format_double(text, 0.1);
    CHECK(strcmp(text, "0.1") == 0, "0.1 printed as \"%s\"", text);
    format_double(text, -0.0);
    CHECK(strcmp(text, "-0") == 0, "-0 printed as \"%s\"", text);
    format_double(text, 5e-324);
    CHECK(strcmp(text, "5e-324") == 0, "5e-324 printed as \"%s\"", text);
    format_double(text, 1e17);
    CHECK(strcmp(text, "1e+17") == 0, "1e17 printed as \"%s\"", text);
    format_double(text, INFINITY);
    CHECK(strcmp(text, "inf") == 0 && isinf(strtod(text, NULL)), "inf printed as \"%s\"", text);
    format_double(text, -INFINITY);
    CHECK(strcmp(text, "-inf") == 0, "-inf printed as \"%s\"", text);
    format_double(text, NAN);
    CHECK(strcmp(text, "nan") == 0 && isnan(strtod(text, NULL)), "nan printed as \"%s\"", text);
}

enum { MESH_VERTICES = 20000 };

static char *read_file(const char *path)
{
    FILE *file = fopen(path, "rb");
    if (!file) return NULL;
    fseek(file, 0, SEEK_END);
    long size = ftell(file);
    fseek(file, 0, SEEK_SET);
    char *text = malloc((size_t)size + 1);
    if (text && fread(text, 1, (size_t)size, file) != (size_t)size) {
        free(text);
        text = NULL;
    }
    if (text) text[size] = '\0';
    fclose(file);
    return text;
}

/* Skips `lines` lines of text. */
static const char *skip_lines(const char *text, int lines)
{
    while (lines-- > 0 && text) {
        text = strchr(text, '\n');
        if (text) text++;
    }
    return text;
}

/* Reads count vertex lines: optional prefix, then `per_vertex` numbers
 * checked against expected[], then the rest of the line. */
static void check_vertex_lines(const char *path, const char *text, const char *prefix,
                               const double *expected, size_t count, int per_vertex, int stride,
                               const double *zero_z)
{
    for (size_t i = 0; i < count && text; i++) {
        while (*text == ' ') text++;
        if (prefix) {
            CHECK(strncmp(text, prefix, strlen(prefix)) == 0, "%s: vertex %zu: no \"%s\"", path, i, prefix);
            text += strlen(prefix);
        }
        for (int c = 0; c < per_vertex; c++) {
            char *end;
            double back = strtod(text, &end);
            double want = c < stride ? expected[(size_t)stride * i + (size_t)c] : *zero_z;
            CHECK(end > text && bits_of(back) == bits_of(want), "%s: vertex %zu, coordinate %d: %a, not %a",
                  path, i, c, back, want);
            text = end;
        }
        CHECK(*text == '\n', "%s: vertex %zu: line goes on: \"%.20s\"", path, i, text);
        text++;
    }
}

static void check_writers(const char *dir)
{
    double *xy = malloc(2 * MESH_VERTICES * sizeof *xy);
    double *xyz = malloc(3 * MESH_VERTICES * sizeof *xyz);
    int32_t triangles[3] = {0, 1, 2};
    for (size_t i = 0; i < 2 * MESH_VERTICES; i++) xy[i] = value(i);
    for (size_t i = 0; i < 3 * MESH_VERTICES; i++) xyz[i] = value(3 * MESH_VERTICES - 1 - i);
    static const double zero = 0.0;
    static const struct { mesh_format format; const char *name, *prefix; int header_lines; } cases[] = {
        {MESH_FORMAT_OFF, "m.off", NULL, 2},
        {MESH_FORMAT_OBJ, "m.obj", "v ", 1},
        {MESH_FORMAT_PLY, "m.ply", NULL, 10},
    };
    char path[4096];
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        snprintf(path, sizeof path, "%s/%s", dir, cases[c].name);
        cli_error error;
        CHECK(write_triangle_mesh(path, xy, NULL, MESH_VERTICES, triangles, 1, cases[c].format, &error) == CLI_EXIT_OK,
              "%s: %s", path, error.message);
        char *text = read_file(path);
        CHECK(text != NULL, "%s: not written", path);
        if (!text) continue;
        const char *body = skip_lines(text, cases[c].header_lines);
        check_vertex_lines(path, body, cases[c].prefix, xy, MESH_VERTICES, 3, 2, &zero);
        free(text);
    }
    snprintf(path, sizeof path, "%s/m.vtu", dir);
    int32_t tet[4] = {0, 1, 2, 3};
    volume_mesh mesh = {xyz, MESH_VERTICES, tet, 1, 1, NULL, 0, 0, NULL, NULL, NULL};
    cli_error error;
    CHECK(write_vtu(path, path, &mesh, &error) == CLI_EXIT_OK, "%s: %s", path, error.message);
    char *text = read_file(path);
    CHECK(text != NULL, "%s: not written", path);
    if (text) check_vertex_lines(path, skip_lines(text, 6), NULL, xyz, MESH_VERTICES, 3, 3, &zero);
    free(text);
    free(xy);
    free(xyz);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fputs("usage: test_format_double WORK_DIR\n", stderr);
        return 2;
    }
    mkdir(argv[1], 0777);
    check_format_double();
    check_writers(argv[1]);
    if (failures) return 1;
    printf("format_double: %d doubles and the OFF/OBJ/PLY/VTU writers read back bit for bit\n",
           EDGE_COUNT + RANDOM_COUNT);
    return 0;
}
