#define _POSIX_C_SOURCE 200809L /* strtok_r, strcasecmp */

#include "read_polygon.h"

#include "edge_loop.h"
#include "read_geojson.h"
#include "read_ply.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

enum { MAX_FIELDS = 8 };

/* Growable list of vertices (x y z) with the line each came from. */
typedef struct vertex_list {
    double *xyz;
    long *line;
    size_t count, capacity;
} vertex_list;

static int vertex_list_push(vertex_list *list, double x, double y, double z, long line)
{
    if (list->count == list->capacity) {
        size_t capacity = list->capacity ? 2 * list->capacity : 64;
        double *xyz = realloc(list->xyz, 3 * capacity * sizeof *xyz);
        if (!xyz) return -1;
        list->xyz = xyz;
        long *lines = realloc(list->line, capacity * sizeof *lines);
        if (!lines) return -1;
        list->line = lines;
        list->capacity = capacity;
    }
    double *p = list->xyz + 3 * list->count;
    p[0] = x, p[1] = y, p[2] = z;
    list->line[list->count] = line;
    list->count++;
    return 0;
}

static void vertex_list_free(vertex_list *list)
{
    free(list->xyz);
    free(list->line);
    memset(list, 0, sizeof *list);
}

/* A section's plane fitted in doubles must leave its coordinates finite. */
#define FIT_BEYOND "the polygon's plane does not fit in doubles (coordinates too large for it)"

int place_section(const char *path, polygon_input *polygon, double *xyz, const plane_z *plane, cli_error *error)
{
    size_t n = polygon->count;
    polygon->xy = malloc((2 * n + 1) * sizeof *polygon->xy);
    if (!polygon->xy) {
        free(xyz);
        cli_error_set(error, "%s: out of memory", path);
        return CLI_EXIT_INTERNAL;
    }
    if (!plane->off) {
        for (size_t i = 0; i < n; i++) polygon->xy[2 * i] = xyz[3 * i], polygon->xy[2 * i + 1] = xyz[3 * i + 1];
        polygon->has_z = plane->given, polygon->z = plane->z;
        free(xyz);
        return CLI_EXIT_OK;
    }
    size_t worst = 0;
    char message[256];
    int fit = section_fit(xyz, n, polygon->loops ? polygon->loop_sizes[0] : n, &polygon->frame, &worst, message,
                          sizeof message);
    if (fit) {
        free(xyz);
        if (fit == -2) {
            cli_error_set(error, "%s: out of memory", path);
            return CLI_EXIT_INTERNAL;
        }
        if (polygon->by_index) cli_error_set(error, "%s: vertex %ld: %s", path, polygon->source_line[worst], message);
        else cli_error_set(error, "%s:%ld: %s", path, polygon->source_line[worst], message);
        return CLI_EXIT_USAGE;
    }
    section_to_plane(&polygon->frame, xyz, n, polygon->xy);
    polygon->spatial = 1, polygon->xyz = xyz;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(polygon->xy[2 * i]) || !isfinite(polygon->xy[2 * i + 1])) {
            if (polygon->by_index) cli_error_set(error, "%s: vertex %ld: %s", path, polygon->source_line[i], FIT_BEYOND);
            else cli_error_set(error, "%s:%ld: %s", path, polygon->source_line[i], FIT_BEYOND);
            return CLI_EXIT_USAGE;
        }
    return CLI_EXIT_OK;
}

/* Reads the whole file into a NUL-terminated buffer. Files of any kind
 * (pipes included) work because it reads until end of file. */
static int read_whole_file(const char *path, size_t max_bytes, char **text, size_t *length,
                           cli_error *error)
{
    FILE *file = fopen(path, "rb");
    if (!file) {
        int resources = errno == ENOMEM || errno == EMFILE || errno == ENFILE;
        cli_error_set(error, "%s: cannot open: %s", path, strerror(errno));
        return resources ? CLI_EXIT_INTERNAL : CLI_EXIT_USAGE;
    }
    size_t used = 0, capacity = 1 << 16;
    char *buffer = malloc(capacity);
    int code = buffer ? CLI_EXIT_OK : CLI_EXIT_INTERNAL;
    while (code == CLI_EXIT_OK) {
        if (capacity - used < 2) {
            /* Room for max_bytes + 1 bytes and the NUL at most. */
            size_t grown = capacity > max_bytes / 2 ? max_bytes + 2 : 2 * capacity;
            char *bigger = realloc(buffer, grown);
            if (!bigger) { code = CLI_EXIT_INTERNAL; break; }
            buffer = bigger;
            capacity = grown;
        }
        size_t got = fread(buffer + used, 1, capacity - used - 1, file);
        used += got;
        if (got == 0) break;
        if (used > max_bytes) {
            code = CLI_EXIT_USAGE;
            break;
        }
    }
    if (code == CLI_EXIT_USAGE) {
        cli_error_set(error, "%s: larger than %zu bytes (--max-input-bytes); raise the limit to read it",
                      path, max_bytes);
    } else if (code == CLI_EXIT_INTERNAL) {
        cli_error_set(error, "%s: out of memory reading the file", path);
    } else if (ferror(file)) {
        cli_error_set(error, "%s: cannot read: %s", path, strerror(errno));
        code = CLI_EXIT_USAGE;
    }
    fclose(file);
    if (code != CLI_EXIT_OK) {
        free(buffer);
        return code;
    }
    buffer[used] = '\0';
    *text = buffer;
    *length = used;
    return CLI_EXIT_OK;
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* Cuts a '#' comment off the end of a line. */
static void strip_comment(char *line)
{
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
}

/* Splits a line in place into fields. Blanks separate fields; when
 * allow_comma is set, one comma (with optional blanks around it) does too.
 * Returns the number of fields found (at most MAX_FIELDS are stored, more
 * are counted), or -1 for a leading, trailing or doubled comma. */
static int split_fields(char *line, int allow_comma, char **fields)
{
    int count = 0;
    int comma_pending = 0; /* a comma since the last field */
    char *p = line;
    for (;;) {
        while (is_blank(*p)) p++;
        if (*p == '\0') break;
        if (allow_comma && *p == ',') {
            if (count == 0 || comma_pending) return -1;
            comma_pending = 1;
            p++;
            continue;
        }
        comma_pending = 0;
        if (count < MAX_FIELDS) fields[count] = p;
        count++;
        while (*p && !is_blank(*p) && !(allow_comma && *p == ',')) p++;
        char separator = *p;
        *p = '\0';
        if (separator == '\0') break;
        p++;
        if (separator == ',') comma_pending = 1;
    }
    return comma_pending ? -1 : count;
}

/* Parses one coordinate; the whole field must be a finite number. */
static int parse_coordinate(const char *field, double *value, const char *path,
                            long line, cli_error *error)
{
    char shown[64];
    char *end;
    errno = 0;
    double parsed = strtod(field, &end);
    if (end == field || *end != '\0' || cli_is_hexadecimal(field)) {
        cli_error_set(error, "%s:%ld: '%s' is not a number", path, line,
                      quote_token(field, 40, shown, sizeof shown));
        return -1;
    }
    if (!isfinite(parsed)) {
        cli_error_set(error, "%s:%ld: '%s' is %s", path, line,
                      quote_token(field, 40, shown, sizeof shown),
                      errno == ERANGE ? "too large for a double"
                                      : "not a finite number");
        return -1;
    }
    *value = parsed;
    return 0;
}

/* Calls visit(line_text, line_number, state) for every line of text, which
 * it modifies in place. Stops at the first non-zero return and returns it. */
static int for_each_line(char *text, int (*visit)(char *, long, void *),
                         void *state)
{
    long number = 0;
    char *line = text;
    while (*line) {
        char *end = strchr(line, '\n');
        if (end) *end = '\0';
        int code = visit(line, ++number, state);
        if (code != CLI_EXIT_OK) return code;
        if (!end) break;
        line = end + 1;
    }
    return CLI_EXIT_OK;
}

/* ---- .xy text ---------------------------------------------------------- */

/* Loop sizes as a file lists its loops. */
typedef struct loop_list {
    size_t *size;
    size_t count, capacity;
} loop_list;

static int loop_list_push(loop_list *list, size_t size)
{
    if (list->count == list->capacity) {
        size_t capacity = list->capacity ? 2 * list->capacity : 4;
        size_t *bigger = realloc(list->size, capacity * sizeof *bigger);
        if (!bigger) return -1;
        list->size = bigger, list->capacity = capacity;
    }
    list->size[list->count++] = size;
    return 0;
}

typedef struct xy_state {
    const char *path;
    vertex_list vertices;
    loop_list loops;
    size_t loop_first; /* first vertex of the loop being read */
    long loop_line;    /* the line of its first vertex */
    plane_z plane;
    int seen_line; /* a line with fields was read (a header comes first) */
    cli_error *error;
} xy_state;

/* Drops the last vertex of the loop being read where it repeats the
 * loop's first exactly: a closed ring, as GMT, WKT and shapefiles write
 * polygons (a loop of three or fewer keeps them all, for the messages on
 * too few vertices). Returns the loop's vertex count. */
static size_t xy_drop_ring_repeat(xy_state *state)
{
    size_t size = state->vertices.count - state->loop_first;
    if (size == 0) return 0; /* no vertices yet: xy may be NULL */
    size_t kept = ring_size_without_repeat(state->vertices.xyz + 3 * state->loop_first, 3, size);
    state->vertices.count -= size - kept;
    return kept;
}

/* Ends the loop being read (none yet: nothing to do). */
static int xy_close_loop(xy_state *state)
{
    size_t size = xy_drop_ring_repeat(state);
    if (size == 0) return CLI_EXIT_OK;
    if (size < 3) {
        cli_error_set(state->error, "%s:%ld: loop %zu has %zu vertices, needs at least 3",
                      state->path, state->loop_line, state->loops.count, size);
        return CLI_EXIT_USAGE;
    }
    if (loop_list_push(&state->loops, size)) {
        cli_error_set(state->error, "%s: out of memory", state->path);
        return CLI_EXIT_INTERNAL;
    }
    state->loop_first = state->vertices.count;
    return CLI_EXIT_OK;
}

/* A field strtod reads nothing of: a word, as a column name. */
static int is_word(const char *field)
{
    char *end;
    (void)strtod(field, &end);
    return end == field;
}

static int visit_xy_line(char *line, long number, void *opaque)
{
    xy_state *state = opaque;
    if (line[0] == '>') return xy_close_loop(state);
    strip_comment(line);
    char *fields[MAX_FIELDS];
    int count = split_fields(line, 1, fields);
    if (count == 0) return CLI_EXIT_OK;
    /* The first line of words only is a header, as spreadsheets and CSV
     * exports write ('x,y'): skipped. A number among them is an error. */
    int header = !state->seen_line && count > 0 && count <= MAX_FIELDS;
    for (int f = 0; header && f < count; f++) header = is_word(fields[f]);
    state->seen_line = 1;
    if (header) return CLI_EXIT_OK;
    if (count < 0) {
        cli_error_set(state->error, "%s:%ld: misplaced ','; expected 'x y' or 'x, y'",
                      state->path, number);
        return CLI_EXIT_USAGE;
    }
    if (count != 2 && count != 3) {
        cli_error_set(state->error, "%s:%ld: expected 2 or 3 numbers 'x y [z]', found %d field%s",
                      state->path, number, count, count == 1 ? "" : "s");
        return CLI_EXIT_USAGE;
    }
    double x, y, z = 0.0;
    if (parse_coordinate(fields[0], &x, state->path, number, state->error) ||
        parse_coordinate(fields[1], &y, state->path, number, state->error) ||
        (count == 3 && parse_coordinate(fields[2], &z, state->path, number, state->error)))
        return CLI_EXIT_USAGE;
    if (plane_z_same_columns(&state->plane, count == 3, state->path, number, state->error)) return CLI_EXIT_USAGE;
    plane_z_note(&state->plane, x, y, z, count == 3, number);
    if (state->vertices.count == state->loop_first) state->loop_line = number;
    if (vertex_list_push(&state->vertices, x, y, z, number)) {
        cli_error_set(state->error, "%s: out of memory", state->path);
        return CLI_EXIT_INTERNAL;
    }
    return CLI_EXIT_OK;
}

static int parse_xy(const char *path, char *text, polygon_input *polygon,
                    cli_error *error)
{
    xy_state state = {.path = path, .error = error};
    int code = for_each_line(text, visit_xy_line, &state);
    if (code == CLI_EXIT_OK && state.vertices.count == 0) {
        cli_error_set(error, "%s: no vertices found (expected one 'x y' or 'x y z' per line)", path);
        code = CLI_EXIT_USAGE;
    }
    /* A single loop keeps the hole-free rules (the core counts its
     * vertices); several must each have 3. */
    if (code == CLI_EXIT_OK && state.loops.count > 0) code = xy_close_loop(&state);
    else if (code == CLI_EXIT_OK && loop_list_push(&state.loops, xy_drop_ring_repeat(&state))) code = CLI_EXIT_INTERNAL;
    if (code == CLI_EXIT_INTERNAL && !error->message[0]) cli_error_set(error, "%s: out of memory", path);
    if (code != CLI_EXIT_OK) {
        vertex_list_free(&state.vertices);
        free(state.loops.size);
        return code;
    }
    polygon->count = state.vertices.count;
    polygon->source_line = state.vertices.line;
    polygon->loops = state.loops.count;
    polygon->loop_sizes = state.loops.size;
    return place_section(path, polygon, state.vertices.xyz, &state.plane, error);
}

/* ---- OBJ polyline ------------------------------------------------------ */

typedef struct obj_state {
    const char *path;
    vertex_list vertices;
    plane_z plane;
    loop_edge *edges;  /* of every 'l' line, 0-based (range checked at the end) */
    size_t edge_count, edge_capacity;
    long l_line;       /* 0 until the first 'l' line */
    cli_error *error;
} obj_state;

static int obj_vertex(obj_state *state, char **fields, int count, long number)
{
    if (count < 3 || count > 4) {
        cli_error_set(state->error, "%s:%ld: expected 'v x y [z]'", state->path, number);
        return CLI_EXIT_USAGE;
    }
    double x, y, z = 0.0;
    if (parse_coordinate(fields[1], &x, state->path, number, state->error) ||
        parse_coordinate(fields[2], &y, state->path, number, state->error) ||
        (count == 4 && parse_coordinate(fields[3], &z, state->path, number, state->error)))
        return CLI_EXIT_USAGE;
    if (plane_z_same_columns(&state->plane, count == 4, state->path, number, state->error)) return CLI_EXIT_USAGE;
    plane_z_note(&state->plane, x, y, z, count == 4, number);
    if (vertex_list_push(&state->vertices, x, y, z, number)) {
        cli_error_set(state->error, "%s: out of memory", state->path);
        return CLI_EXIT_INTERNAL;
    }
    return CLI_EXIT_OK;
}

/* Parses an 'l' entry ("i" or "i/t") into a 0-based index. Negative OBJ
 * indices count back from the vertices read so far. Positive ones may refer
 * forward; their range is checked once the whole file is read. */
static int obj_loop_index(obj_state *state, const char *field, long number, long *index)
{
    char shown[64];
    char *end;
    errno = 0;
    long value = strtol(field, &end, 10);
    if (end == field || (*end != '\0' && *end != '/') || errno == ERANGE) {
        cli_error_set(state->error, "%s:%ld: '%s' is not a vertex index", state->path,
                      number, quote_token(field, 40, shown, sizeof shown));
        return -1;
    }
    if (value < 0) value += (long)state->vertices.count + 1;
    if (value <= 0) {
        cli_error_set(state->error, "%s:%ld: vertex index %s does not name a vertex "
                      "(indices start at 1)", state->path, number,
                      quote_token(field, 40, shown, sizeof shown));
        return -1;
    }
    *index = value - 1;
    return 0;
}

/* Reads an 'l' line: a polyline of at least two vertices, one edge per
 * consecutive pair (MeshLab writes one 'l a b' line per edge). Tokens past
 * MAX_FIELDS are re-split here because a polyline may list every vertex on
 * one line. */
static int obj_polyline(obj_state *state, char *rest, long number)
{
    if (!state->l_line) state->l_line = number;
    long previous = -1, index;
    size_t indices = 0;
    char *save = NULL;
    for (char *field = strtok_r(rest, " \t\r\v\f", &save); field;
         field = strtok_r(NULL, " \t\r\v\f", &save), indices++) {
        if (obj_loop_index(state, field, number, &index)) return CLI_EXIT_USAGE;
        if (indices > 0) {
            if (state->edge_count == state->edge_capacity) {
                size_t capacity = state->edge_capacity ? 2 * state->edge_capacity : 64;
                loop_edge *bigger = realloc(state->edges, capacity * sizeof *bigger);
                if (!bigger) {
                    cli_error_set(state->error, "%s: out of memory", state->path);
                    return CLI_EXIT_INTERNAL;
                }
                state->edges = bigger, state->edge_capacity = capacity;
            }
            state->edges[state->edge_count++] = (loop_edge){previous, index, number};
        }
        previous = index;
    }
    if (indices < 2) {
        cli_error_set(state->error, "%s:%ld: an 'l' line needs at least 2 vertices", state->path, number);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

static int visit_obj_line(char *line, long number, void *opaque)
{
    obj_state *state = opaque;
    strip_comment(line);
    while (is_blank(*line)) line++;
    if (line[0] == 'l' && (line[1] == ' ' || line[1] == '\t'))
        return obj_polyline(state, line + 2, number);
    char *fields[MAX_FIELDS];
    int count = split_fields(line, 0, fields);
    if (count == 0) return CLI_EXIT_OK;
    if (strcmp(fields[0], "v") == 0)
        return obj_vertex(state, fields, count, number);
    if (strcmp(fields[0], "f") == 0) {
        cli_error_set(state->error, "%s:%ld: faces are not supported; expected one "
                      "closed 'l' polyline", state->path, number);
        return CLI_EXIT_USAGE;
    }
    if (strcmp(fields[0], "l") == 0) {
        cli_error_set(state->error, "%s:%ld: empty 'l' line", state->path, number);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK; /* other statements (o, g, vn, ...) do not matter */
}

/* Chains the 'l' edges into the polygon's loops. */
static int obj_make_polygon(obj_state *state, polygon_input *polygon)
{
    const char *path = state->path;
    if (!state->l_line) {
        cli_error_set(state->error, "%s: no 'l' line; expected closed polylines", path);
        return CLI_EXIT_USAGE;
    }
    long *loop;
    size_t count = 0, *sizes, loops;
    int code = edge_loops(path, state->edges, state->edge_count, state->vertices.xyz, 3, state->vertices.count, 1, 0,
                          &loop, &sizes, &loops, state->error);
    if (code != CLI_EXIT_OK) return code;
    for (size_t l = 0; l < loops; l++) count += sizes[l];
    double *xyz = malloc((3 * count + 1) * sizeof *xyz);
    polygon->source_line = malloc((count + 1) * sizeof *polygon->source_line);
    if (!xyz || !polygon->source_line) {
        free(loop), free(sizes), free(xyz);
        cli_error_set(state->error, "%s: out of memory", path);
        return CLI_EXIT_INTERNAL;
    }
    for (size_t i = 0; i < count; i++) {
        size_t v = (size_t)loop[i];
        memcpy(xyz + 3 * i, state->vertices.xyz + 3 * v, 3 * sizeof *xyz);
        polygon->source_line[i] = state->vertices.line[v];
    }
    free(loop);
    polygon->count = count;
    polygon->loops = loops;
    polygon->loop_sizes = sizes;
    return place_section(path, polygon, xyz, &state->plane, state->error);
}

static int parse_obj(const char *path, char *text, polygon_input *polygon,
                     cli_error *error)
{
    obj_state state = {0};
    state.path = path;
    state.error = error;
    int code = for_each_line(text, visit_obj_line, &state);
    if (code == CLI_EXIT_OK) code = obj_make_polygon(&state, polygon);
    vertex_list_free(&state.vertices);
    free(state.edges);
    return code;
}

/* ---- entry point ------------------------------------------------------- */

static int has_extension(const char *path, const char *extension)
{
    size_t length = strlen(path), n = strlen(extension);
    return length >= n && strcasecmp(path + length - n, extension) == 0;
}

int parse_polygon_text(const char *path, char *text, size_t length,
                       polygon_input *polygon, cli_error *error)
{
    memset(polygon, 0, sizeof *polygon);
    int code;
    /* A UTF-8 byte order mark, as Notepad and spreadsheets' "CSV UTF-8"
     * write text, is not part of the first line (read as such, it hid an
     * OBJ file's first vertex and shifted every index after it). */
    if (!has_extension(path, ".ply") && length >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) text += 3, length -= 3;
    const char *nul = memchr(text, '\0', length);
    if (has_extension(path, ".ply")) {
        code = parse_ply(path, text, length, polygon, error);
    } else if (nul) {
        long line = 1;
        for (const char *p = text; p < nul; p++) line += *p == '\n';
        cli_error_set(error, "%s:%ld: binary data (a NUL byte); expected a text file",
                      path, line);
        code = CLI_EXIT_USAGE;
    } else if (has_extension(path, ".obj")) {
        code = parse_obj(path, text, polygon, error);
    } else if (has_extension(path, ".geojson") || has_extension(path, ".json")) {
        code = parse_geojson(path, text, length, polygon, error);
    } else {
        code = parse_xy(path, text, polygon, error);
    }
    if (code != CLI_EXIT_OK) {
        polygon_input_free(polygon);
        return code;
    }
    polygon->path = path;
    return CLI_EXIT_OK;
}

int read_polygon(const char *path, size_t max_bytes, polygon_input *polygon, cli_error *error)
{
    memset(polygon, 0, sizeof *polygon);
    char *text;
    size_t length;
    int code = read_whole_file(path, max_bytes, &text, &length, error);
    if (code != CLI_EXIT_OK) return code;
    code = parse_polygon_text(path, text, length, polygon, error);
    free(text);
    return code;
}

void polygon_frames(const polygon_input *polygons, size_t k, double *frames)
{
    for (size_t g = 0; g < k; g++) {
        if (!polygons[g].spatial) { /* the plane z = its z (0 where none was given) */
            static const double plane[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
            memcpy(frames + 9 * g, plane, sizeof plane);
            frames[9 * g + 2] = polygons[g].z;
            continue;
        }
        const section_frame *f = &polygons[g].frame;
        memcpy(frames + 9 * g, f->origin, sizeof f->origin);
        memcpy(frames + 9 * g + 3, f->u, sizeof f->u);
        memcpy(frames + 9 * g + 6, f->v, sizeof f->v);
    }
}

void polygon_input_free(polygon_input *polygon)
{
    free(polygon->xy);
    free(polygon->xyz);
    free(polygon->source_line);
    free(polygon->loop_sizes);
    memset(polygon, 0, sizeof *polygon);
}
