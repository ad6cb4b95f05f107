/* A polygon from GeoJSON (RFC 7946), as QGIS, GDAL (ogr2ogr), shapely
 * (json.dumps(mapping(p))) and geopandas write it: a Polygon geometry, a
 * Feature holding one, or a FeatureCollection of exactly one such Feature.
 * jansson parses the JSON. */
#ifndef CM_CLI_READ_GEOJSON_H
#define CM_CLI_READ_GEOJSON_H

#include <stddef.h>

#include "read_polygon.h"

/* text[0..length) is the whole file. Fills polygon: the exterior ring,
 * then the holes, each ring without its closing repeat; positions
 * [x, y] or [x, y, z] (z the same for all, checked as for OBJ; a ring has
 * at least 4 positions, as RFC 7946 says, and may be left open);
 * source_line[i] is vertex i's index (polygon->by_index set). Returns
 * CLI_EXIT_OK, or CLI_EXIT_USAGE with "PATH:LINE: ..." for JSON that does
 * not parse and "PATH: coordinates[R][P]: ..." (ring R, position P) or
 * "PATH: ..." for GeoJSON that is not one Polygon, or CLI_EXIT_INTERNAL
 * when out of memory. */
int parse_geojson(const char *path, const char *text, size_t length, polygon_input *polygon, cli_error *error);

#endif
