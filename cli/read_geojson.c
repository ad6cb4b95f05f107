#include "read_geojson.h"

#include <jansson.h>
#include <stdlib.h>
#include <string.h>

#include "edge_loop.h"

/* The Polygon the root stands for: itself, a Feature's geometry, or the
 * geometry of a FeatureCollection's one Feature. NULL with the message
 * set where it stands for none. */
static json_t *the_polygon(json_t *root, const char *path, cli_error *error)
{
    json_t *object = root;
    const char *type = json_string_value(json_object_get(object, "type"));
    if (type && strcmp(type, "FeatureCollection") == 0) {
        json_t *features = json_object_get(object, "features");
        if (!json_is_array(features) || json_array_size(features) != 1) {
            cli_error_set(error, "%s: a FeatureCollection of %zu features; expected exactly one (a Polygon)", path,
                          json_array_size(features));
            return NULL;
        }
        object = json_array_get(features, 0);
        type = json_string_value(json_object_get(object, "type"));
    }
    if (type && strcmp(type, "Feature") == 0) {
        object = json_object_get(object, "geometry");
        type = json_string_value(json_object_get(object, "type"));
        if (!type) {
            cli_error_set(error, "%s: a Feature without a geometry; expected a Polygon", path);
            return NULL;
        }
    }
    if (!type) {
        cli_error_set(error, "%s: not GeoJSON (no \"type\" member); expected a Polygon", path);
        return NULL;
    }
    if (strcmp(type, "Polygon") != 0) {
        char shown[64];
        cli_error_set(error, "%s: a GeoJSON %s; expected a Polygon%s", path, quote_token(type, 40, shown, sizeof shown),
                      strcmp(type, "MultiPolygon") == 0 ? " (write each of its polygons to a file of its own)" : "");
        return NULL;
    }
    return object;
}

/* Position p of ring r as x, y and z (*given: it had z). 0, or -1 with
 * the message set. */
static int read_position(json_t *position, size_t r, size_t p, double *x, double *y, double *z, int *given,
                         const char *path, cli_error *error)
{
    size_t size = json_array_size(position);
    int ok = json_is_array(position) && (size == 2 || size == 3);
    for (size_t c = 0; ok && c < size; c++) ok = json_is_number(json_array_get(position, c));
    if (!ok) {
        cli_error_set(error, "%s: coordinates[%zu][%zu]: expected a position [x, y] or [x, y, z]", path, r, p);
        return -1;
    }
    *x = json_number_value(json_array_get(position, 0));
    *y = json_number_value(json_array_get(position, 1));
    *z = size == 3 ? json_number_value(json_array_get(position, 2)) : 0.0;
    *given = size == 3;
    return 0;
}

/* The rings of a Polygon into polygon. */
static int read_rings(json_t *rings, const char *path, polygon_input *polygon, cli_error *error)
{
    size_t loops = json_array_size(rings), total = 0;
    if (!json_is_array(rings) || loops == 0) {
        cli_error_set(error, "%s: a Polygon without coordinates; expected an array of rings", path);
        return CLI_EXIT_USAGE;
    }
    for (size_t r = 0; r < loops; r++) {
        if (!json_is_array(json_array_get(rings, r))) {
            cli_error_set(error, "%s: coordinates[%zu]: expected a ring (an array of positions)", path, r);
            return CLI_EXIT_USAGE;
        }
        total += json_array_size(json_array_get(rings, r));
    }
    polygon->xy = malloc((2 * total + 1) * sizeof *polygon->xy);
    polygon->source_line = malloc((total + 1) * sizeof *polygon->source_line);
    polygon->loop_sizes = malloc(loops * sizeof *polygon->loop_sizes);
    if (!polygon->xy || !polygon->source_line || !polygon->loop_sizes) {
        cli_error_set(error, "%s: out of memory", path);
        return CLI_EXIT_INTERNAL;
    }
    plane_z plane = {.by_index = 1};
    size_t count = 0;
    for (size_t r = 0; r < loops; r++) {
        json_t *ring = json_array_get(rings, r);
        size_t first = count, size = json_array_size(ring);
        if (size < 4) {
            cli_error_set(error, "%s: coordinates[%zu]: a ring of %zu positions; GeoJSON rings have at least 4 "
                          "(3 vertices, the first repeated last)", path, r, size);
            return CLI_EXIT_USAGE;
        }
        for (size_t p = 0; p < size; p++, count++) {
            double x, y, z;
            int given, code;
            if (read_position(json_array_get(ring, p), r, p, &x, &y, &z, &given, path, error)) return CLI_EXIT_USAGE;
            if ((code = plane_z_take(&plane, x, y, z, given, path, (long)count, error)) != CLI_EXIT_OK) return code;
            polygon->xy[2 * count] = x, polygon->xy[2 * count + 1] = y;
            polygon->source_line[count] = (long)count;
        }
        size_t kept = ring_size_without_repeat(polygon->xy + 2 * first, 2, size);
        count = first + kept;
        polygon->loop_sizes[r] = kept;
    }
    polygon->count = count, polygon->loops = loops, polygon->by_index = 1;
    polygon->has_z = plane.given, polygon->z = plane.z;
    return CLI_EXIT_OK;
}

int parse_geojson(const char *path, const char *text, size_t length, polygon_input *polygon, cli_error *error)
{
    json_error_t parse;
    json_t *root = json_loadb(text, length, JSON_REJECT_DUPLICATES | JSON_DECODE_INT_AS_REAL, &parse);
    if (!root) {
        if (json_error_code(&parse) == json_error_out_of_memory) {
            cli_error_set(error, "%s: out of memory", path);
            return CLI_EXIT_INTERNAL;
        }
        char shown[4 * JSON_ERROR_TEXT_LENGTH]; /* jansson quotes the text near the error as it is */
        cli_error_set(error, "%s:%d: %s", path, parse.line,
                      quote_token(parse.text, JSON_ERROR_TEXT_LENGTH, shown, sizeof shown));
        return CLI_EXIT_USAGE;
    }
    json_t *geometry = the_polygon(root, path, error);
    int code = geometry ? read_rings(json_object_get(geometry, "coordinates"), path, polygon, error) : CLI_EXIT_USAGE;
    json_decref(root);
    return code;
}
