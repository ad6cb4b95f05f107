/* compatmesh triangulate: the compatible triangulation of the inputs,
 * written as meshes, a report and pictures. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <compatmesh/compatmesh.h>

#include "cli_common.h"
#include "commands.h"
#include "options.h"
#include "triangulate_job.h"

static const option_spec triangulate_options[] = {
    {"out-dir", 'o', "DIR",
     "where the outputs go (required); DIR is created if\n"
     "missing (its parent must exist); files in DIR named\n"
     "like an output are replaced, other files are kept"},
    TRIANGULATE_FORMAT_SPEC,
    TRIANGULATE_PREVIEW_SPEC,
    TRIANGULATION_OPTION_SPECS,
    {"help", 'h', NULL, "show this help and exit"},
};
static const size_t triangulate_option_count =
    sizeof triangulate_options / sizeof triangulate_options[0];

typedef struct triangulate_args {
    triangulate_job job;
    int help;
} triangulate_args;

static int handle_triangulate_option(void *context, int key, const char *value,
                                     cli_error *error)
{
    triangulate_args *args = context;
    int code = triangulate_job_option(&args->job, "triangulate", key, value, error);
    if (code >= 0) return code;
    switch (key) {
    case 'o':
        args->job.out_dir = value;
        return CLI_EXIT_OK;
    case 'h':
        args->help = 1;
        return CLI_EXIT_OK;
    default:
        cli_error_set(error, "triangulate: unhandled option %d", key);
        return CLI_EXIT_INTERNAL;
    }
}

static void print_triangulate_help(FILE *out)
{
    fputs("Usage: compatmesh triangulate IN1 IN2 [IN3 ...] --out-dir DIR [OPTIONS]\n"
          "\n"
          "Compatibly triangulates k >= 2 simple polygons, with or without holes.\n"
          "With the index correspondence (the default for equal counts) vertex i of\n"
          "each input corresponds to vertex i of the others; arclength and auto (the\n"
          "default when the counts differ) add the other inputs' points on each\n"
          "input's edges (see --correspondence). All meshes share one triangle list;\n"
          "the boundary vertices come first (each input's own vertices in input\n"
          "order and bit-identical, with arclength and auto the added points among\n"
          "them, on its edges), then the Steiner vertices. An input in a plane\n"
          "other than z = constant is meshed in its plane and written in space.\n"
          "\n"
          "Inputs (chosen by file name extension):\n"
          "  .obj        an OBJ polyline: 'v x y [z]' lines and 'l' lines whose\n"
          "              edges form closed loops (one closed 'l' line per loop, or\n"
          "              one 'l a b' line per edge in any order, as MeshLab writes),\n"
          "              each loop in the order of its first edge; z, if given,\n"
          "              must be the same for all vertices (up to the rounding\n"
          "              of single precision, as MeshLab writes sections)\n"
          "  .ply        a PLY edge mesh (ASCII or binary): element vertex (x, y,\n"
          "              optional z) and element edge (vertex1, vertex2), the edges\n"
          "              forming closed loops, each followed from its first edge\n"
          "  .geojson,   a GeoJSON Polygon (RFC 7946), alone, in a Feature or in a\n"
          "  .json       FeatureCollection of one Feature: the exterior ring, then\n"
          "              the holes, each ring without its closing repeat;\n"
          "              positions [x, y] or [x, y, z], z as for .obj\n"
          "  .obj, .ply  several loops give a polygon with holes: the loop of\n"
          "              largest area is the outer one, the holes follow in file\n"
          "              order\n"
          "  any other   one vertex 'x y' or 'x y z' per line (z the same for all\n"
          "              vertices, as for .obj), the numbers separated by blanks\n"
          "              and/or one comma (\"1.5 2\", \"1.5, 2\", \"1.5,2\"); '#' starts\n"
          "              a comment; blank lines are ignored; a line beginning\n"
          "              with '>' ends a loop (the outer loop first, then the holes);\n"
          "              a loop's last vertex repeating its first, closing the\n"
          "              ring, is dropped; a first line of words only (a CSV\n"
          "              header such as 'x,y') is skipped\n"
          "  The polygons may run clockwise or counter-clockwise, all the same way.\n"
          "  With holes every input has the same number of loops, loop j of each\n"
          "  of the same size (vertices correspond by index within each loop),\n"
          "  every loop may run either way (the same way in every input).\n"
          "\n"
          "Options:\n", out);
    print_options(out, triangulate_options, triangulate_option_count);
    fputs("\n"
          "Outputs, written to a temporary directory beside DIR and moved into DIR\n"
          "only when everything succeeded (on failure DIR is left as it was):\n"
          "  DIR/STEM.FMT     one mesh per input, STEM being the input's file name\n"
          "                   without its extension (two inputs with the same stem\n"
          "                   are an error), in its input's plane (its z, its\n"
          "                   plane in space, or z = 0 where the input has no\n"
          "                   z); coordinates with 17 significant digits, so\n"
          "                   input vertices read back bit-identical\n"
          "  DIR/report.json  version, n, k, vertices, steiner, triangles, holes\n"
          "                   (per input), bridges (paths cutting them open: two\n"
          "                   per hole, one where the overlay took over),\n"
          "                   holes_moved (auto: holes paired with a hole at\n"
          "                   another place in the first input's list),\n"
          "                   pairings_built and pairings_remeshed (auto: the\n"
          "                   correspondences tried, and those remeshed: one\n"
          "                   whose corner-fan cap cannot beat the best so far\n"
          "                   is set aside), time_limit_reached (the remesher\n"
          "                   stopped at --time-limit, keeping the result\n"
          "                   reached), valid,\n"
          "                   method, remesh, correspondence (as asked),\n"
          "                   correspondence_choice (what was made: index,\n"
          "                   arclength, conformal, similarity, affine,\n"
          "                   corners or annulus; with holes the outer\n"
          "                   loop's), max_edge and time_limit (where given),\n"
          "                   reversed_input,\n"
          "                   fallback_count,\n"
          "                   steiner_before_remesh, remesh_iterations,\n"
          "                   remesh_aim_deg (the target lowered where the\n"
          "                   input allows less), ceiling (null with\n"
          "                   --no-ceiling: ceiling_deg, no compatible\n"
          "                   triangulation can have a larger smallest angle;\n"
          "                   corner_fan_cap_deg, correspondence_bound_deg,\n"
          "                   modulus_distortion, distortion_quad and, for\n"
          "                   auto, correspondence_bound_before_deg: arc length\n"
          "                   from the first vertices), seconds (validate,\n"
          "                   build, remesh, check, ceiling, and total: the\n"
          "                   whole computation)\n"
          "                   and per mesh the input, output, min/max angle and\n"
          "                   the share of triangles whose smallest angle is\n"
          "                   below 10, 15 and 20 degrees, after and\n"
          "                   (before_remesh) before remeshing\n"
          "  DIR/preview.svg  the meshes side by side: boundary thick, Steiner\n"
          "                   vertices as dots, triangles whose smallest angle is\n"
          "                   below 20 degrees orange, each mesh's worst one red\n"
          "  DIR/preview.png  the same picture as PNG (cairo draws both)\n"
          "\n", out);
    fputs(cli_exit_status_help, out);
}

static int parse_triangulate_args(int argc, char **argv, triangulate_args *args,
                                  cli_error *error)
{
    memset(args, 0, sizeof *args);
    int code = triangulate_job_init(&args->job, argc, error);
    if (code != CLI_EXIT_OK) return code;
    code = parse_options(argc, argv, "triangulate", triangulate_options,
                             triangulate_option_count, handle_triangulate_option,
                             args, error);
    if (code != CLI_EXIT_OK || args->help) return code;
    code = triangulation_args_check(&args->job.tri, "triangulate", error);
    if (code != CLI_EXIT_OK) return code;
    if (!args->job.out_dir) {
        cli_error_set(error, "triangulate: --out-dir DIR is required "
                      "(see 'compatmesh triangulate --help')");
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

int run_triangulate(int argc, char **argv)
{
    triangulate_args args;
    cli_error error = {{0}};
    int code = parse_triangulate_args(argc, argv, &args, &error);
    if (code == CLI_EXIT_OK && args.help) print_triangulate_help(stdout);
    else if (code == CLI_EXIT_OK) code = triangulate_job_run(&args.job, NULL, &error);
    if (code != CLI_EXIT_OK) cli_print_error(&error);
    triangulation_args_free(&args.job.tri);
    return code;
}
