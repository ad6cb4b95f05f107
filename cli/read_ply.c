/* PLY: the header says which elements follow, in order, each a list of
 * typed properties; every element is read (others are skipped) and the
 * vertices and edges kept. Debian 12 packages no C or C++ library that
 * reads PLY edge elements short of VTK or PCL (see the README). */
#define _POSIX_C_SOURCE 200809L

#include "read_ply.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "edge_loop.h"

enum { MAX_ELEMENTS = 16, MAX_PROPERTIES = 32 };

typedef enum ply_type { T_NONE, T_I8, T_U8, T_I16, T_U16, T_I32, T_U32, T_F32, T_F64 } ply_type;

typedef struct ply_property {
    char name[64];
    ply_type type;       /* of the value, or of the list's items */
    ply_type count_type; /* T_NONE: not a list */
} ply_property;

typedef struct ply_element {
    char name[64];
    long count;
    ply_property property[MAX_PROPERTIES];
    int num_properties;
} ply_element;

typedef struct ply_reader {
    const char *path;
    const char *data, *end, *at;
    int format; /* 0 ascii, 1 little endian, 2 big endian */
    long line;  /* ASCII: the current line */
    cli_error *error;
} ply_reader;

static ply_type type_named(const char *name)
{
    static const struct { const char *name; ply_type type; } names[] = {
        {"char", T_I8}, {"int8", T_I8}, {"uchar", T_U8}, {"uint8", T_U8},
        {"short", T_I16}, {"int16", T_I16}, {"ushort", T_U16}, {"uint16", T_U16},
        {"int", T_I32}, {"int32", T_I32}, {"uint", T_U32}, {"uint32", T_U32},
        {"float", T_F32}, {"float32", T_F32}, {"double", T_F64}, {"float64", T_F64}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strcmp(name, names[i].name) == 0) return names[i].type;
    return T_NONE;
}

static size_t type_size(ply_type t)
{
    static const size_t size[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};
    return size[t];
}

/* ---- header -------------------------------------------------------------- */

/* The next header line, NUL-terminated in line[]; 0 at the end of the data. */
static int header_line(ply_reader *r, char *line, size_t size)
{
    if (r->at >= r->end) return 0;
    const char *nl = memchr(r->at, '\n', (size_t)(r->end - r->at));
    size_t n = (size_t)((nl ? nl : r->end) - r->at);
    if (n >= size) n = size - 1;
    memcpy(line, r->at, n);
    line[n] = '\0';
    if (n && line[n - 1] == '\r') line[n - 1] = '\0';
    r->at = nl ? nl + 1 : r->end;
    r->line++;
    return 1;
}

static int header_error(ply_reader *r, const char *what)
{
    cli_error_set(r->error, "%s:%ld: %s", r->path, r->line, what);
    return CLI_EXIT_USAGE;
}

static int read_header(ply_reader *r, ply_element *elements, int *num_elements)
{
    char line[1024];
    if (!header_line(r, line, sizeof line) || strcmp(line, "ply") != 0)
        return header_error(r, "not a PLY file (the first line must be 'ply')");
    int have_format = 0;
    *num_elements = 0;
    while (header_line(r, line, sizeof line)) {
        char *save = NULL, *word = strtok_r(line, " \t", &save);
        if (!word || strcmp(word, "comment") == 0 || strcmp(word, "obj_info") == 0) continue;
        if (strcmp(word, "end_header") == 0) {
            if (!have_format) return header_error(r, "no 'format' line before 'end_header'");
            return CLI_EXIT_OK;
        }
        if (strcmp(word, "format") == 0) {
            const char *kind = strtok_r(NULL, " \t", &save), *version = strtok_r(NULL, " \t", &save);
            if (!kind || !version || strcmp(version, "1.0") != 0)
                return header_error(r, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
            if (strcmp(kind, "ascii") == 0) r->format = 0;
            else if (strcmp(kind, "binary_little_endian") == 0) r->format = 1;
            else if (strcmp(kind, "binary_big_endian") == 0) r->format = 2;
            else return header_error(r, "unknown PLY format (known: ascii, binary_little_endian, binary_big_endian)");
            have_format = 1;
        } else if (strcmp(word, "element") == 0) {
            const char *name = strtok_r(NULL, " \t", &save), *count = strtok_r(NULL, " \t", &save);
            char *end = NULL;
            errno = 0;
            long n = count ? strtol(count, &end, 10) : -1;
            if (!name || !count || *end || n < 0 || errno == ERANGE || strtok_r(NULL, " \t", &save))
                return header_error(r, "expected 'element NAME COUNT'");
            if (*num_elements == MAX_ELEMENTS) return header_error(r, "too many elements");
            ply_element *e = &elements[(*num_elements)++];
            memset(e, 0, sizeof *e);
            snprintf(e->name, sizeof e->name, "%s", name);
            e->count = n;
        } else if (strcmp(word, "property") == 0) {
            if (*num_elements == 0) return header_error(r, "a 'property' line before any 'element' line");
            ply_element *e = &elements[*num_elements - 1];
            if (e->num_properties == MAX_PROPERTIES) return header_error(r, "too many properties");
            ply_property *p = &e->property[e->num_properties++];
            const char *type = strtok_r(NULL, " \t", &save);
            if (type && strcmp(type, "list") == 0) {
                const char *count_type = strtok_r(NULL, " \t", &save);
                type = strtok_r(NULL, " \t", &save);
                p->count_type = count_type ? type_named(count_type) : T_NONE;
                if (p->count_type == T_NONE || p->count_type == T_F32 || p->count_type == T_F64)
                    return header_error(r, "expected 'property list COUNT_TYPE TYPE NAME' with an integer count type");
            }
            const char *name = strtok_r(NULL, " \t", &save);
            p->type = type ? type_named(type) : T_NONE;
            if (p->type == T_NONE || !name || strtok_r(NULL, " \t", &save))
                return header_error(r, "expected 'property TYPE NAME' (TYPE: char, uchar, short, ushort, int, "
                                       "uint, float, double or their sized names)");
            snprintf(p->name, sizeof p->name, "%s", name);
        } else {
            return header_error(r, "unknown header line (expected format, element, property, comment or end_header)");
        }
    }
    return header_error(r, "no 'end_header' line");
}

/* ---- values -------------------------------------------------------------- */

/* Reads one value of type t into *value. 0 on success, -1 at the end of
 * the data, -2 for a bad ASCII token (the message set). */
static int read_value(ply_reader *r, ply_type t, double *value)
{
    if (r->format == 0) {
        while (r->at < r->end && (*r->at == ' ' || *r->at == '\t' || *r->at == '\r' || *r->at == '\n')) {
            if (*r->at == '\n') r->line++;
            r->at++;
        }
        if (r->at >= r->end) return -1;
        const char *start = r->at;
        while (r->at < r->end && !(*r->at == ' ' || *r->at == '\t' || *r->at == '\r' || *r->at == '\n')) r->at++;
        char token[128];
        size_t n = (size_t)(r->at - start);
        if (n >= sizeof token) n = sizeof token - 1;
        memcpy(token, start, n);
        token[n] = '\0';
        char *end;
        errno = 0;
        double v = strtod(token, &end);
        if (end == token || *end || cli_is_hexadecimal(token) || !isfinite(v) ||
            (t != T_F32 && t != T_F64 && v != floor(v))) {
            cli_error_set(r->error, "%s:%ld: '%s' is not %s", r->path, r->line, token,
                          t == T_F32 || t == T_F64 ? "a finite number" : "an integer");
            return -2;
        }
        *value = v;
        return 0;
    }
    size_t size = type_size(t);
    if ((size_t)(r->end - r->at) < size) return -1;
    unsigned char b[8];
    for (size_t i = 0; i < size; i++) b[i] = (unsigned char)r->at[r->format == 1 ? i : size - 1 - i];
    r->at += size;
    uint64_t u = 0;
    for (size_t i = size; i-- > 0;) u = (u << 8) | b[i]; /* little endian now */
    switch (t) {
    case T_I8: *value = (int8_t)u; break;
    case T_U8: *value = (uint8_t)u; break;
    case T_I16: *value = (int16_t)u; break;
    case T_U16: *value = (uint16_t)u; break;
    case T_I32: *value = (int32_t)u; break;
    case T_U32: *value = (uint32_t)u; break;
    case T_F32: { uint32_t w = (uint32_t)u; float f; memcpy(&f, &w, 4); *value = f; break; }
    default: { double d; memcpy(&d, &u, 8); *value = d; break; }
    }
    return 0;
}

/* ---- the polyline ---------------------------------------------------------- */

static int property_index(const ply_element *e, const char *name)
{
    for (int i = 0; i < e->num_properties; i++)
        if (strcmp(e->property[i].name, name) == 0) return i;
    return -1;
}

int parse_ply(const char *path, const char *data, size_t length, polygon_input *polygon, cli_error *error)
{
    ply_reader r = {path, data, data + length, data, 0, 0, error};
    ply_element elements[MAX_ELEMENTS];
    int num_elements;
    int code = read_header(&r, elements, &num_elements);
    if (code != CLI_EXIT_OK) return code;
    r.line++; /* the data starts on the line after end_header */
    const ply_element *vertex = NULL, *edge = NULL;
    int ix = -1, iy = -1, iz = -1, ia = -1, ib = -1;
    for (int k = 0; k < num_elements; k++) {
        const ply_element *e = &elements[k];
        if (strcmp(e->name, "vertex") == 0) {
            vertex = e, ix = property_index(e, "x"), iy = property_index(e, "y"), iz = property_index(e, "z");
            if (ix < 0 || iy < 0) {
                cli_error_set(error, "%s: element vertex has no property x or y", path);
                return CLI_EXIT_USAGE;
            }
        } else if (strcmp(e->name, "edge") == 0) {
            edge = e, ia = property_index(e, "vertex1"), ib = property_index(e, "vertex2");
            if (ia < 0 || ib < 0 || e->property[ia].count_type || e->property[ib].count_type ||
                e->property[ia].type >= T_F32 || e->property[ib].type >= T_F32) {
                cli_error_set(error, "%s: element edge needs the integer properties vertex1 and vertex2", path);
                return CLI_EXIT_USAGE;
            }
        } else if (strcmp(e->name, "face") == 0 && e->count > 0) {
            cli_error_set(error, "%s: %ld faces; expected an edge mesh (element edge) forming one closed polyline",
                          path, e->count);
            return CLI_EXIT_USAGE;
        }
    }
    if (!vertex || !edge) {
        cli_error_set(error, "%s: no element %s; expected an edge mesh (elements vertex and edge)", path,
                      vertex ? "edge" : "vertex");
        return CLI_EXIT_USAGE;
    }
    /* No more entries than the data could hold (a byte per value at least),
     * for every element: each is read through. An element without
     * properties holds no data. */
    for (int k = 0; k < num_elements; k++)
        if (elements[k].num_properties > 0 && elements[k].count > (long)length) {
            cli_error_set(error, "%s: the header promises more %s elements than the file holds", path,
                          elements[k].name);
            return CLI_EXIT_USAGE;
        }
    double *xyz = malloc(3 * (size_t)(vertex->count + 1) * sizeof *xyz);
    long *line = malloc((size_t)(vertex->count + 1) * sizeof *line);
    loop_edge *edges = malloc((size_t)(edge->count + 1) * sizeof *edges);
    if (!xyz || !line || !edges) {
        free(xyz), free(line), free(edges);
        cli_error_set(error, "%s: out of memory", path);
        return CLI_EXIT_INTERNAL;
    }
    const int binary = r.format != 0;
    plane_z plane = {.by_index = binary};
    for (int k = 0; k < num_elements && code == CLI_EXIT_OK; k++) {
        const ply_element *e = &elements[k];
        for (long i = 0; i < e->count && e->num_properties > 0 && code == CLI_EXIT_OK; i++) {
            long where = r.line + 1;
            double value[MAX_PROPERTIES] = {0};
            for (int p = 0; p < e->num_properties && code == CLI_EXIT_OK; p++) {
                const ply_property *prop = &e->property[p];
                double count = 1;
                int status = 0;
                if (prop->count_type) {
                    status = read_value(&r, prop->count_type, &count);
                    if (status == 0 && count < 0) {
                        cli_error_set(error, "%s: %s %ld: a negative list length", path, e->name, i);
                        status = -2;
                    }
                }
                for (double j = 0; j < count && status == 0; j++) status = read_value(&r, prop->type, &value[p]);
                if (p == 0 && !binary) where = r.line; /* the element's first token */
                if (status == -1)
                    cli_error_set(error, "%s: the file ends in %s %ld of %ld", path, e->name, i, e->count);
                if (status) code = CLI_EXIT_USAGE;
            }
            if (code != CLI_EXIT_OK) break;
            if (e == vertex) {
                if (!isfinite(value[ix]) || !isfinite(value[iy]) || (iz >= 0 && !isfinite(value[iz]))) {
                    if (binary) cli_error_set(error, "%s: vertex %ld: a coordinate is not finite", path, i);
                    else cli_error_set(error, "%s:%ld: a coordinate is not finite", path, where);
                    code = CLI_EXIT_USAGE;
                    break;
                }
                xyz[3 * i] = value[ix], xyz[3 * i + 1] = value[iy], xyz[3 * i + 2] = iz >= 0 ? value[iz] : 0;
                line[i] = binary ? i : where;
                plane_z_note(&plane, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], iz >= 0, line[i]);
            } else if (e == edge) {
                for (int end = 0; end < 2 && code == CLI_EXIT_OK; end++) {
                    double v = value[end ? ib : ia];
                    if (v >= 0 && v < (double)vertex->count && v == floor(v)) continue;
                    if (binary)
                        cli_error_set(error, "%s: edge %ld: vertex index %g is out of range (the file has %ld vertices)",
                                      path, i, v, vertex->count);
                    else
                        cli_error_set(error, "%s:%ld: vertex index %g is out of range (the file has %ld vertices)",
                                      path, where, v, vertex->count);
                    code = CLI_EXIT_USAGE;
                }
                if (code != CLI_EXIT_OK) break;
                edges[i] = (loop_edge){(long)value[ia], (long)value[ib], binary ? i : where};
            }
        }
    }
    long *loop = NULL;
    size_t count = 0, *sizes = NULL, loops = 0;
    if (code == CLI_EXIT_OK)
        code = edge_loops(path, edges, (size_t)edge->count, xyz, 3, (size_t)vertex->count, 0, binary, &loop, &sizes,
                          &loops, error);
    for (size_t l = 0; l < loops; l++) count += sizes[l];
    double *ordered = NULL;
    if (code == CLI_EXIT_OK) {
        ordered = malloc((3 * count + 1) * sizeof *ordered);
        polygon->source_line = malloc((count + 1) * sizeof *polygon->source_line);
        if (!ordered || !polygon->source_line) {
            cli_error_set(error, "%s: out of memory", path);
            code = CLI_EXIT_INTERNAL;
        } else {
            for (size_t i = 0; i < count; i++) {
                memcpy(ordered + 3 * i, xyz + 3 * loop[i], 3 * sizeof *ordered);
                polygon->source_line[i] = line[loop[i]];
            }
            polygon->count = count;
            polygon->loops = loops;
            polygon->loop_sizes = sizes;
            sizes = NULL;
            polygon->by_index = binary;
            code = place_section(path, polygon, ordered, &plane, error);
            ordered = NULL; /* taken */
        }
    }
    free(ordered), free(xyz), free(line), free(edges), free(loop), free(sizes);
    return code;
}
