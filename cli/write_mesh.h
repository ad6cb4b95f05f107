/* Writing one geometry of a result (or a morph section) as a triangle mesh
 * file. */
#ifndef CM_CLI_WRITE_MESH_H
#define CM_CLI_WRITE_MESH_H

#include <stddef.h>

#include <compatmesh/compatmesh.h>

#include "cli_common.h"
#include "read_polygon.h"

typedef enum mesh_format {
    MESH_FORMAT_OFF,
    MESH_FORMAT_OBJ,
    MESH_FORMAT_PLY
} mesh_format;

/* "off", "obj", "ply" -> *format; returns -1 for any other name. */
int mesh_format_from_name(const char *name, mesh_format *format);
/* The file extension without the dot, which is also the format's name. */
const char *mesh_format_name(mesh_format format);

/* Writes geometry g of result to path where its input lies (NULL: z = 0):
 * in its plane z = constant, or for a section in another plane (spatial)
 * in space, its input vertices as read and the points on its edges on the
 * edges in space (cm_result_boundary_source), the others mapped from the
 * plane; coordinates printed shortest (format_double.h) so they read back
 * bit-identical, then the shared triangles (counter-clockwise in the
 * plane). Returns CLI_EXIT_OK or CLI_EXIT_INTERNAL with error set. */
int write_mesh(const char *path, const cm_result *result, size_t g, const polygon_input *input,
               mesh_format format, cli_error *error);

/* Geometry g's vertices where input (with has_z, or spatial) lies, as write_mesh
 * writes them: xyz receives 3 per vertex of result. */
void mesh_in_space(const cm_result *result, size_t g, const polygon_input *input, double *xyz);

/* A morph section xy (2 per vertex of result) at time t between inputs in
 * space (triangulation.c places every input so once one is a section in
 * another plane) or in planes z = constant (frames: their planes,
 * polygon_frames): at an input's own time that input's mesh_in_space; in
 * between, cm_loft_section (between planes z = constant, x and y as in
 * xy). xyz receives 3 per vertex. */
void section_in_space(const cm_result *result, const polygon_input *inputs, const double *frames, size_t k,
                      double t, const double *xy, double *xyz);

/* The same for any geometry of the triangles: xy holds 2 * vertices
 * doubles (z = 0), or xyz 3 * vertices (xy then NULL), triangles 3 * count
 * indices. */
int write_triangle_mesh(const char *path, const double *xy, const double *xyz, size_t vertices,
                        const int32_t *triangles, size_t count, mesh_format format,
                        cli_error *error);

#endif
