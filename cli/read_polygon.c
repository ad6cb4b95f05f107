#define _POSIX_C_SOURCE 200809L /* strtok_r, strcasecmp */

#include "read_polygon.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

enum { MAX_FIELDS = 8 };

/* Growable list of vertices with the line each came from. */
typedef struct vertex_list {
    double *xy;
    long *line;
    size_t count, capacity;
} vertex_list;

static int vertex_list_push(vertex_list *list, double x, double y, long line)
{
    if (list->count == list->capacity) {
        size_t capacity = list->capacity ? 2 * list->capacity : 64;
        double *xy = realloc(list->xy, 2 * capacity * sizeof *xy);
        if (!xy) return -1;
        list->xy = xy;
        long *lines = realloc(list->line, capacity * sizeof *lines);
        if (!lines) return -1;
        list->line = lines;
        list->capacity = capacity;
    }
    list->xy[2 * list->count] = x;
    list->xy[2 * list->count + 1] = y;
    list->line[list->count] = line;
    list->count++;
    return 0;
}

static void vertex_list_free(vertex_list *list)
{
    free(list->xy);
    free(list->line);
    memset(list, 0, sizeof *list);
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

/* Copies token into out for an error message: at most ~40 characters, bytes
 * that are not printable ASCII shown as \xNN so the message stays one line. */
static const char *quote_token(const char *token, char *out, size_t size)
{
    size_t used = 0;
    for (const unsigned char *p = (const unsigned char *)token; *p; p++) {
        if (used + 8 >= size || p - (const unsigned char *)token >= 40) {
            strcpy(out + used, "...");
            return out;
        }
        if (isprint(*p)) out[used++] = (char)*p;
        else used += (size_t)snprintf(out + used, size - used, "\\x%02X", *p);
    }
    out[used] = '\0';
    return out;
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
    if (end == field || *end != '\0') {
        cli_error_set(error, "%s:%ld: '%s' is not a number", path, line,
                      quote_token(field, shown, sizeof shown));
        return -1;
    }
    if (!isfinite(parsed)) {
        cli_error_set(error, "%s:%ld: '%s' is %s", path, line,
                      quote_token(field, shown, sizeof shown),
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
    cli_error *error;
} xy_state;

/* Ends the loop being read (none yet: nothing to do). */
static int xy_close_loop(xy_state *state)
{
    size_t size = state->vertices.count - state->loop_first;
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

static int visit_xy_line(char *line, long number, void *opaque)
{
    xy_state *state = opaque;
    if (line[0] == '>') return xy_close_loop(state);
    strip_comment(line);
    char *fields[MAX_FIELDS];
    int count = split_fields(line, 1, fields);
    if (count == 0) return CLI_EXIT_OK;
    if (count < 0) {
        cli_error_set(state->error, "%s:%ld: misplaced ','; expected 'x y' or 'x, y'",
                      state->path, number);
        return CLI_EXIT_USAGE;
    }
    if (count != 2) {
        cli_error_set(state->error, "%s:%ld: expected 2 numbers 'x y', found %d field%s",
                      state->path, number, count, count == 1 ? "" : "s");
        return CLI_EXIT_USAGE;
    }
    double x, y;
    if (parse_coordinate(fields[0], &x, state->path, number, state->error) ||
        parse_coordinate(fields[1], &y, state->path, number, state->error))
        return CLI_EXIT_USAGE;
    if (state->vertices.count == state->loop_first) state->loop_line = number;
    if (vertex_list_push(&state->vertices, x, y, number)) {
        cli_error_set(state->error, "%s: out of memory", state->path);
        return CLI_EXIT_INTERNAL;
    }
    return CLI_EXIT_OK;
}

static int parse_xy(const char *path, char *text, polygon_input *polygon,
                    cli_error *error)
{
    xy_state state = {path, {0}, {0}, 0, 0, error};
    int code = for_each_line(text, visit_xy_line, &state);
    if (code == CLI_EXIT_OK && state.vertices.count == 0) {
        cli_error_set(error, "%s: no vertices found (expected one 'x y' per line)", path);
        code = CLI_EXIT_USAGE;
    }
    /* A single loop keeps the hole-free rules (the core counts its
     * vertices); several must each have 3. */
    if (code == CLI_EXIT_OK && state.loops.count > 0) code = xy_close_loop(&state);
    else if (code == CLI_EXIT_OK) code = loop_list_push(&state.loops, state.vertices.count) ? CLI_EXIT_INTERNAL : CLI_EXIT_OK;
    if (code == CLI_EXIT_INTERNAL && !error->message[0]) cli_error_set(error, "%s: out of memory", path);
    if (code != CLI_EXIT_OK) {
        vertex_list_free(&state.vertices);
        free(state.loops.size);
        return code;
    }
    polygon->count = state.vertices.count;
    polygon->xy = state.vertices.xy;
    polygon->source_line = state.vertices.line;
    polygon->loops = state.loops.count;
    polygon->loop_sizes = state.loops.size;
    return CLI_EXIT_OK;
}

/* ---- OBJ polyline ------------------------------------------------------ */

typedef struct obj_state {
    const char *path;
    vertex_list vertices;
    double first_z;
    long first_z_line; /* 0 until the first 'v' line */
    int has_z;         /* some 'v' line gave z */
    long *index;       /* 0-based vertex indices of every 'l' line, one after another */
    size_t index_count, index_capacity;
    loop_list lines;   /* how many indices each 'l' line has */
    long *line_number; /* the file line of each 'l' line */
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
    if (count == 4) state->has_z = 1;
    if (state->first_z_line == 0) {
        state->first_z = z;
        state->first_z_line = number;
    } else if (z != state->first_z) {
        cli_error_set(state->error,
                      "%s:%ld: z = %.17g differs from z = %.17g on line %ld; "
                      "the polygon must lie in a plane z = constant",
                      state->path, number, z, state->first_z, state->first_z_line);
        return CLI_EXIT_USAGE;
    }
    if (vertex_list_push(&state->vertices, x, y, number)) {
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
                      number, quote_token(field, shown, sizeof shown));
        return -1;
    }
    if (value < 0) value += (long)state->vertices.count + 1;
    if (value <= 0) {
        cli_error_set(state->error, "%s:%ld: vertex index %s does not name a vertex "
                      "(indices start at 1)", state->path, number,
                      quote_token(field, shown, sizeof shown));
        return -1;
    }
    *index = value - 1;
    return 0;
}

/* Reads an 'l' line. Tokens past MAX_FIELDS are re-split here because a
 * polyline lists every vertex on one line. */
static int obj_polyline(obj_state *state, char *rest, long number)
{
    long *numbers = realloc(state->line_number, (state->lines.count + 1) * sizeof *numbers);
    if (!numbers) {
        cli_error_set(state->error, "%s: out of memory", state->path);
        return CLI_EXIT_INTERNAL;
    }
    state->line_number = numbers;
    numbers[state->lines.count] = number;
    size_t first = state->index_count;
    char *save = NULL;
    for (char *field = strtok_r(rest, " \t\r\v\f", &save); field;
         field = strtok_r(NULL, " \t\r\v\f", &save)) {
        if (state->index_count == state->index_capacity) {
            size_t capacity = state->index_capacity ? 2 * state->index_capacity : 64;
            long *bigger = realloc(state->index, capacity * sizeof *bigger);
            if (!bigger) {
                cli_error_set(state->error, "%s: out of memory", state->path);
                return CLI_EXIT_INTERNAL;
            }
            state->index = bigger, state->index_capacity = capacity;
        }
        if (obj_loop_index(state, field, number, &state->index[state->index_count]))
            return CLI_EXIT_USAGE;
        state->index_count++;
    }
    if (loop_list_push(&state->lines, state->index_count - first)) {
        cli_error_set(state->error, "%s: out of memory", state->path);
        return CLI_EXIT_INTERNAL;
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

/* The loops of an OBJ file: vertex indices, one loop after another. */
typedef struct obj_loops {
    long *vertex;
    size_t count;
    loop_list sizes;
    long *line; /* an 'l' line of each loop, for messages */
} obj_loops;

static int obj_add_loop(obj_loops *loops, const long *vertex, size_t size, long line)
{
    long *lines = realloc(loops->line, (loops->sizes.count + 1) * sizeof *lines);
    if (!lines) return -1;
    loops->line = lines;
    lines[loops->sizes.count] = line;
    if (loop_list_push(&loops->sizes, size)) return -1;
    memcpy(loops->vertex + loops->count, vertex, size * sizeof *vertex);
    loops->count += size;
    return 0;
}

/* Open 'l' lines (MeshLab writes a section as one 'l a b' line per edge)
 * joined into closed loops at shared vertices: every vertex they use must
 * end exactly two of their edges. Each loop runs the way its first edge
 * is written. */
static int obj_join_edges(obj_state *state, obj_loops *loops, const unsigned char *open)
{
    size_t nv = state->vertices.count;
    long *link = malloc((2 * nv + 1) * sizeof *link), *walk = malloc((state->index_count + 1) * sizeof *walk);
    long *first_line = malloc((nv + 1) * sizeof *first_line);
    int code = CLI_EXIT_OK;
    if (!link || !walk || !first_line) {
        cli_error_set(state->error, "%s: out of memory", state->path);
        code = CLI_EXIT_INTERNAL;
        goto end;
    }
    for (size_t v = 0; v < 2 * nv; v++) link[v] = -1;
    size_t at = 0;
    for (size_t l = 0; l < state->lines.count && code == CLI_EXIT_OK; at += state->lines.size[l++]) {
        if (!open[l]) continue;
        for (size_t i = 0; i + 1 < state->lines.size[l]; i++) {
            long ends[2] = {state->index[at + i], state->index[at + i + 1]};
            for (int e = 0; e < 2; e++) {
                long v = ends[e], w = ends[1 - e];
                if (link[2 * v] < 0) link[2 * v] = w, first_line[v] = state->line_number[l];
                else if (link[2 * v + 1] < 0 && v != w) link[2 * v + 1] = w;
                else {
                    cli_error_set(state->error, "%s:%ld: vertex %ld ends more than two edges (the 'l' lines "
                                  "must form closed loops)", state->path, state->line_number[l], v + 1);
                    code = CLI_EXIT_USAGE;
                    break;
                }
            }
            if (code != CLI_EXIT_OK) break;
        }
    }
    at = 0;
    for (size_t l = 0; l < state->lines.count && code == CLI_EXIT_OK; at += state->lines.size[l++]) {
        if (!open[l]) continue;
        for (size_t i = 0; i + 1 < state->lines.size[l] && code == CLI_EXIT_OK; i++) {
            long start = state->index[at + i], prev = start, v = state->index[at + i + 1];
            if (link[2 * start] == -2) continue; /* on a loop already walked */
            size_t m = 0;
            walk[m++] = start;
            while (v != start && m <= nv) {
                if (link[2 * v + 1] < 0) break;
                walk[m++] = v;
                long next = link[2 * v] == prev ? link[2 * v + 1] : link[2 * v];
                prev = v, v = next;
            }
            if (v != start || link[2 * start + 1] < 0) {
                long end = link[2 * v + 1] < 0 ? v : start;
                cli_error_set(state->error, "%s:%ld: the 'l' lines do not close: vertex %ld ends only one edge",
                              state->path, first_line[end], end + 1);
                code = CLI_EXIT_USAGE;
                break;
            }
            for (size_t j = 0; j < m; j++) link[2 * walk[j]] = -2;
            if (obj_add_loop(loops, walk, m, first_line[start])) {
                cli_error_set(state->error, "%s: out of memory", state->path);
                code = CLI_EXIT_INTERNAL;
            }
        }
    }
end:
    free(link), free(walk), free(first_line);
    return code;
}

static double loop_area(const vertex_list *v, const long *loop, size_t m)
{
    double sum = 0;
    for (size_t i = 0; i < m; i++) {
        const double *a = v->xy + 2 * loop[i], *b = v->xy + 2 * loop[(i + 1) % m];
        sum += a[0] * b[1] - a[1] * b[0];
    }
    return 0.5 * sum;
}

/* Checks the polylines and turns them into the polygon: each closed 'l'
 * line a loop in its order without the closing repetition, open ones
 * joined; the outer loop (largest area: it must contain the others, which
 * the core checks exactly) first, the holes in file order. */
static int obj_make_polygon(obj_state *state, polygon_input *polygon)
{
    const char *path = state->path;
    if (!state->lines.count) {
        cli_error_set(state->error, "%s: no 'l' line; expected one closed polyline", path);
        return CLI_EXIT_USAGE;
    }
    size_t at = 0, opened = 0;
    unsigned char *open = calloc(state->lines.count, 1);
    obj_loops loops = {malloc((state->index_count + 1) * sizeof(long)), 0, {0}, NULL};
    int code = open && loops.vertex ? CLI_EXIT_OK : CLI_EXIT_INTERNAL;
    if (code != CLI_EXIT_OK) cli_error_set(state->error, "%s: out of memory", path);
    for (size_t l = 0; l < state->lines.count && code == CLI_EXIT_OK; at += state->lines.size[l++]) {
        const long *index = state->index ? state->index + at : NULL; /* no indices yet: NULL */
        size_t size = state->lines.size[l];
        for (size_t i = 0; i < size; i++)
            if ((size_t)index[i] >= state->vertices.count) {
                cli_error_set(state->error, "%s:%ld: vertex index %ld is out of range "
                              "(the file has %zu vertices)", path, state->line_number[l],
                              index[i] + 1, state->vertices.count);
                code = CLI_EXIT_USAGE;
                break;
            }
        if (code != CLI_EXIT_OK) break;
        if (size >= 2 && index[0] == index[size - 1]) {
            if (obj_add_loop(&loops, index, size - 1, state->line_number[l])) code = CLI_EXIT_INTERNAL;
        } else if (state->lines.count == 1 || size < 2) {
            cli_error_set(state->error, "%s:%ld: the 'l' polyline is not closed: its last "
                          "index must repeat the first", path, state->line_number[l]);
            code = CLI_EXIT_USAGE;
        } else {
            open[l] = 1, opened++;
        }
    }
    if (code == CLI_EXIT_OK && opened) code = obj_join_edges(state, &loops, open);
    if (code == CLI_EXIT_INTERNAL && !state->error->message[0]) cli_error_set(state->error, "%s: out of memory", path);
    size_t outer = 0, count = loops.count;
    double largest = -1;
    for (size_t l = 0, first = 0; code == CLI_EXIT_OK && l < loops.sizes.count; first += loops.sizes.size[l++]) {
        if (loops.sizes.count > 1 && loops.sizes.size[l] < 3) {
            cli_error_set(state->error, "%s:%ld: a loop of %zu vertices, needs at least 3", path,
                          loops.line[l], loops.sizes.size[l]);
            code = CLI_EXIT_USAGE;
        }
        double area = fabs(loop_area(&state->vertices, loops.vertex + first, loops.sizes.size[l]));
        if (area > largest) largest = area, outer = l;
    }
    if (code == CLI_EXIT_OK) {
        polygon->xy = malloc(2 * (count + 1) * sizeof *polygon->xy);
        polygon->source_line = malloc((count + 1) * sizeof *polygon->source_line);
        polygon->loop_sizes = malloc(loops.sizes.count * sizeof *polygon->loop_sizes);
        if (!polygon->xy || !polygon->source_line || !polygon->loop_sizes) {
            cli_error_set(state->error, "%s: out of memory", path);
            code = CLI_EXIT_INTERNAL;
        }
    }
    if (code == CLI_EXIT_OK) {
        size_t out = 0, next_loop = 0;
        for (size_t pass = 0; pass < 2; pass++) /* the outer loop, then the others */
            for (size_t l = 0, first = 0; l < loops.sizes.count; first += loops.sizes.size[l++]) {
                if ((pass == 0) != (l == outer)) continue;
                polygon->loop_sizes[next_loop++] = loops.sizes.size[l];
                for (size_t i = 0; i < loops.sizes.size[l]; i++, out++) {
                    size_t v = (size_t)loops.vertex[first + i];
                    polygon->xy[2 * out] = state->vertices.xy[2 * v];
                    polygon->xy[2 * out + 1] = state->vertices.xy[2 * v + 1];
                    polygon->source_line[out] = state->vertices.line[v];
                }
            }
        polygon->count = count;
        polygon->loops = loops.sizes.count;
        polygon->has_z = state->has_z;
        polygon->z = state->first_z;
    }
    free(open), free(loops.vertex), free(loops.sizes.size), free(loops.line);
    return code;
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
    free(state.index), free(state.lines.size), free(state.line_number);
    return code;
}

/* ---- entry point ------------------------------------------------------- */

static int has_obj_extension(const char *path)
{
    size_t length = strlen(path);
    return length >= 4 && strcasecmp(path + length - 4, ".obj") == 0;
}

int parse_polygon_text(const char *path, char *text, size_t length,
                       polygon_input *polygon, cli_error *error)
{
    memset(polygon, 0, sizeof *polygon);
    int code;
    const char *nul = memchr(text, '\0', length);
    if (nul) {
        long line = 1;
        for (const char *p = text; p < nul; p++) line += *p == '\n';
        cli_error_set(error, "%s:%ld: binary data (a NUL byte); expected a text file",
                      path, line);
        code = CLI_EXIT_USAGE;
    } else if (has_obj_extension(path)) {
        code = parse_obj(path, text, polygon, error);
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

void polygon_input_free(polygon_input *polygon)
{
    free(polygon->xy);
    free(polygon->source_line);
    free(polygon->loop_sizes);
    memset(polygon, 0, sizeof *polygon);
}
