/* Reading one input polygon from a text file. */
#ifndef CM_CLI_READ_POLYGON_H
#define CM_CLI_READ_POLYGON_H

#include <stddef.h>

#include "cli_common.h"
#include "edge_loop.h"
#include "section_plane.h"

/* One polygon as read from disk. Vertex i is (xy[2i], xy[2i+1]); it was read
 * from line source_line[i] (1-based) of the file, so errors the core reports
 * by vertex index can point the user at the line to fix. */
typedef struct polygon_input {
    const char *path; /* borrowed from the command line */
    size_t count;
    double *xy;
    long *source_line;
    int by_index;     /* binary files: source_line[i] is the vertex's index in the file */
    /* Loops: the outer loop, then the holes, one after another in xy;
     * loops >= 1 entries of loop_sizes (summing to count). */
    size_t loops;
    size_t *loop_sizes;
    int has_z;        /* the file gave z (the same for every vertex) */
    double z;         /* that z, else 0 */
    /* A section in a plane other than z = constant (or, once any input of
     * a call is, every input: triangulation.c): xyz holds its vertices as
     * read (3 per vertex, in the order of xy), frame its plane, and xy the
     * vertices' coordinates in that plane. */
    int spatial;
    double *xyz;
    section_frame frame;
} polygon_input;

/* Reads `path` into *polygon. Files ending in ".obj" (any case) are read as
 * an OBJ polyline ("v x y [z]" lines and "l" lines whose edges form
 * closed loops, in a plane: z constant, or any plane, place_section); ".ply" as a PLY edge mesh (read_ply.h); with
 * several loops the outer one is the one of largest area, the holes follow
 * in file order, each loop in the order of its first edge; ".geojson" and
 * ".json" as one GeoJSON Polygon (read_geojson.h). Anything else
 * as ".xy" text (one "x y" or "x y z" vertex per line, in a plane as for
 * OBJ, blanks and/or one comma between
 * the numbers, '#' to end of line is a comment, blank lines ignored; a
 * line beginning with '>' ends a loop, GMT's multi-segment convention: the
 * outer loop first, then the holes; a loop's last vertex that repeats its
 * first exactly, closing the ring, is dropped; a first line of words only
 * is a header, skipped).
 * A file longer than max_bytes is refused after reading max_bytes + 1
 * bytes (so /dev/zero is refused too), with a message naming the limit.
 * Returns CLI_EXIT_OK on success. Otherwise leaves *polygon empty, sets
 * error->message to "PATH:LINE: what is wrong" (or "PATH: ..." when no line
 * applies) and returns CLI_EXIT_USAGE for an unreadable or malformed file,
 * CLI_EXIT_INTERNAL when out of memory (also when opening the file runs
 * out of memory or file descriptors: errno is reported as it is). */
int read_polygon(const char *path, size_t max_bytes, polygon_input *polygon, cli_error *error);

/* The same for a file's contents already in memory: text[0..length) followed
 * by a NUL at text[length]; `path` names the file in messages and chooses
 * the format. Modifies text. Used by read_polygon and the parser fuzzer. */
int parse_polygon_text(const char *path, char *text, size_t length,
                       polygon_input *polygon, cli_error *error);

/* The plane of the polygon's count vertices read as xyz (3 each, in the
 * polygon's order; taken: kept or freed), plane as plane_z_note left it:
 * where every vertex lies in the plane z = constant, xy gets their x and
 * y and has_z, z say the plane; else the polygon is spatial, its plane
 * fitted (section_fit: within 1e-5 of its size, the normal following the
 * outer loop) and xy its coordinates there. Errors "PATH:LINE: the polygon
 * is not planar: ..." (by_index: "PATH: vertex I: ...") return
 * CLI_EXIT_USAGE; out of memory CLI_EXIT_INTERNAL. */
int place_section(const char *path, polygon_input *polygon, double *xyz, const plane_z *plane, cli_error *error);

/* The planes of k inputs as the core's loft takes them
 * (cm_sweep_options.frames, cm_loft_section): 9 doubles each, the origin,
 * u and v; an input that is not spatial lies in the plane z = its z. */
void polygon_frames(const polygon_input *polygons, size_t k, double *frames);

void polygon_input_free(polygon_input *polygon);

#endif
