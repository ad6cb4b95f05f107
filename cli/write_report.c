#include "write_report.h"

#include <math.h>
#include <string.h>

#include "outdir.h"

/* A JSON string. Invalid UTF-8 (file names can hold any bytes) becomes
 * U+FFFD so the file stays valid JSON. */
static void json_string(FILE *file, const char *text)
{
    const unsigned char *p = (const unsigned char *)text;
    size_t remaining = strlen(text);
    fputc('"', file);
    while (remaining > 0) {
        size_t length = utf8_sequence_length(p, remaining);
        if (length == 0) {
            fputs("\\ufffd", file);
            length = 1;
        } else if (*p == '"' || *p == '\\') {
            fprintf(file, "\\%c", *p);
        } else if (*p < 0x20) {
            fprintf(file, "\\u%04x", *p);
        } else {
            fwrite(p, 1, length, file);
        }
        p += length;
        remaining -= length;
    }
    fputc('"', file);
}

/* JSON has no NaN or infinity; null marks a value that could not be had. */
static void json_number(FILE *file, double value)
{
    if (isfinite(value)) fprintf(file, "%.10g", value);
    else fputs("null", file);
}

static void json_field(FILE *file, const char *separator, const char *key,
                       double value)
{
    fprintf(file, "%s\"%s\": ", separator, key);
    json_number(file, value);
}

static void write_seconds(FILE *file, const cm_stats *stats, double total)
{
    fputs("  \"seconds\": {", file);
    json_field(file, "", "validate", stats->seconds_validate);
    json_field(file, ", ", "build", stats->seconds_build);
    json_field(file, ", ", "remesh", stats->seconds_remesh);
    json_field(file, ", ", "check", stats->seconds_check);
    json_field(file, ", ", "ceiling", stats->seconds_ceiling);
    json_field(file, ", ", "total", total);
    fputs("},\n", file);
}

/* The certified caps on the smallest angle (null when not computed). */
static void write_ceiling(FILE *file, const cm_stats *stats, int computed)
{
    if (!computed) {
        fputs("  \"ceiling\": null,\n", file);
        return;
    }
    fputs("  \"ceiling\": {", file);
    json_field(file, "", "ceiling_deg", stats->ceiling_deg);
    json_field(file, ", ", "corner_fan_cap_deg", stats->corner_fan_cap_deg);
    json_field(file, ",\n              ", "correspondence_bound_deg", stats->correspondence_bound_deg);
    json_field(file, ", ", "modulus_distortion", stats->modulus_distortion);
    fprintf(file, ",\n              \"distortion_quad\": [%ld, %ld, %ld, %ld]", stats->distortion_quad[0],
            stats->distortion_quad[1], stats->distortion_quad[2], stats->distortion_quad[3]);
    if (stats->correspondence_bound_before_deg > 0)
        json_field(file, ",\n              ", "correspondence_bound_before_deg",
                   stats->correspondence_bound_before_deg);
    fputs("},\n", file);
}

/* The quality fields of one mesh; NaN (null) when it could not be had. */
static void write_quality(FILE *file, const char *first, const char *line,
                          cm_status status, cm_quality quality)
{
    if (status != CM_OK) quality = (cm_quality){NAN, NAN, NAN, NAN, NAN};
    json_field(file, first, "min_angle_deg", quality.min_angle_deg);
    json_field(file, ", ", "max_angle_deg", quality.max_angle_deg);
    json_field(file, line, "pct_triangles_below_10deg", quality.pct_below_10deg);
    json_field(file, ", ", "pct_triangles_below_15deg", quality.pct_below_15deg);
    json_field(file, ", ", "pct_triangles_below_20deg", quality.pct_below_20deg);
}

static void write_mesh_entry(FILE *file, const report_info *info, size_t g)
{
    cm_quality quality;
    fputs("    {\"input\": ", file);
    json_string(file, info->inputs[g]);
    fputs(", \"output\": ", file);
    json_string(file, info->outputs[g]);
    write_quality(file, ",\n     ", ",\n     ", cm_result_quality(info->result, g, &quality),
                  quality);
    fputs(",\n     \"before_remesh\": {", file);
    write_quality(file, "", ",\n      ", cm_result_quality_before(info->result, g, &quality),
                  quality);
    fputs("}", file);
    if (info->correspondence != CM_CORRESPOND_INDEX || info->max_edge > 0) {
        /* Per boundary vertex: [e, t], the point at t of input edge e -> e + 1. */
        fputs(",\n     \"boundary_source\": [", file);
        for (size_t i = 0; i < cm_result_stats(info->result)->n; i++) {
            double t;
            long e = cm_result_boundary_source(info->result, g, i, &t);
            fprintf(file, "%s[%ld, %.17g]", i ? ", " : "", e, t);
        }
        fputs("]", file);
    }
    fputs("}", file);
}

/* The opening brace and the counts every report starts with. */
/* ["a", "b", ...]: count > 0 strings. */
static void json_string_list(FILE *file, const char *const *strings, size_t count)
{
    fputc('[', file);
    for (size_t i = 0; i < count; i++) {
        json_string(file, strings[i]);
        fputs(i + 1 < count ? ", " : "]", file);
    }
}

static void write_head(FILE *file, const cm_stats *stats)
{
    fprintf(file, "{\n");
    fprintf(file, "  \"version\": \"%d.%d.%d\",\n", CM_VERSION_MAJOR, CM_VERSION_MINOR,
            CM_VERSION_PATCH);
    fprintf(file, "  \"n\": %zu,\n  \"k\": %zu,\n", stats->n, stats->k);
    fprintf(file, "  \"vertices\": %zu,\n  \"steiner\": %zu,\n  \"triangles\": %zu,\n",
            stats->vertices, stats->steiner, stats->triangles);
    fprintf(file, "  \"holes\": %zu,\n  \"bridges\": %zu,\n", stats->holes, stats->bridges);
}

int write_report(const char *path, const report_info *info, cli_error *error)
{
    FILE *file = output_open(path, error);
    if (!file) return CLI_EXIT_INTERNAL;
    const cm_stats *stats = cm_result_stats(info->result);
    write_head(file, stats);
    fprintf(file, "  \"valid\": true,\n");
    fputs("  \"method\": ", file);
    json_string(file, info->method);
    fprintf(file, ",\n  \"remesh\": %s,\n", info->remesh ? "true" : "false");
    static const char *const correspondence[] = {"index", "arclength", "auto"};
    fprintf(file, "  \"correspondence\": \"%s\",\n", correspondence[info->correspondence]);
    if (info->max_edge > 0) fprintf(file, "  \"max_edge\": %.17g,\n", info->max_edge);
    fprintf(file, "  \"reversed_input\": %s,\n", stats->reversed_input ? "true" : "false");
    fprintf(file, "  \"fallback_count\": %zu,\n", stats->fallback_count);
    fprintf(file, "  \"steiner_before_remesh\": %zu,\n", stats->steiner_before_remesh);
    fprintf(file, "  \"remesh_iterations\": %zu,\n", stats->remesh_iterations);
    json_field(file, "  ", "remesh_aim_deg", stats->remesh_aim_deg);
    fputs(",\n", file);
    write_ceiling(file, stats, info->ceiling);
    write_seconds(file, stats, info->seconds_total);
    fputs("  \"meshes\": [\n", file);
    for (size_t g = 0; g < stats->k; g++) {
        write_mesh_entry(file, info, g);
        fputs(g + 1 < stats->k ? ",\n" : "\n", file);
    }
    fputs("  ]\n}\n", file);
    return output_close(file, path, error);
}

int write_morph_report(const char *path, const morph_report_info *info, cli_error *error)
{
    FILE *file = output_open(path, error);
    if (!file) return CLI_EXIT_INTERNAL;
    const cm_stats *stats = cm_result_stats(info->result);
    write_head(file, stats);
    fputs("  \"method\": ", file);
    json_string(file, info->method);
    fputs(",\n  \"morph\": ", file);
    json_string(file, info->morph);
    fputs(",\n  \"inputs\": ", file);
    json_string_list(file, info->inputs, stats->k);
    fputs(",\n", file);
    size_t total = 0;
    for (size_t f = 0; f < info->frame_count; f++) total += info->inverted[f];
    fprintf(file, "  \"inverted_total\": %zu,\n", total);
    fputs("  \"frames\": [\n", file);
    for (size_t f = 0; f < info->frame_count; f++) {
        fputs("    {\"file\": ", file);
        json_string(file, info->outputs[f]);
        json_field(file, ", ", "t", info->t[f]);
        json_field(file, ", ", "min_angle_deg", info->min_angle_deg[f]);
        fprintf(file, ", \"inverted\": %zu}%s\n", info->inverted[f],
                f + 1 < info->frame_count ? "," : "");
    }
    fputs("  ]\n}\n", file);
    return output_close(file, path, error);
}

int write_sweep_report(const char *path, const sweep_report_info *info, cli_error *error)
{
    FILE *file = output_open(path, error);
    if (!file) return CLI_EXIT_INTERNAL;
    const cm_stats *stats = cm_result_stats(info->result);
    const cm_sweep *sweep = info->sweep;
    write_head(file, stats);
    fputs("  \"method\": ", file);
    json_string(file, info->method);
    fputs(",\n  \"inputs\": ", file);
    json_string_list(file, info->inputs, stats->k);
    fputs(",\n", file);
    fputs("  \"output\": ", file);
    json_string(file, info->output);
    fprintf(file, ",\n  \"sections\": %zu,\n  \"nodes\": %zu,\n  \"cells\": %zu,\n  \"cell_type\": \"%s\",\n",
            cm_sweep_num_sections(sweep), cm_sweep_num_nodes(sweep),
            info->tets ? cm_sweep_num_tets(sweep) : cm_sweep_num_prisms(sweep), info->tets ? "tetrahedron" : "prism");
    json_field(file, "  ", "volume", cm_sweep_volume(sweep));
    fputs(",\n  \"height\": {", file);
    json_field(file, "", "value", cm_sweep_height(sweep));
    fputs(", \"rule\": ", file);
    json_string(file, info->height_rule);
    fputs("},\n", file);
    cm_sweep_quality q;
    cm_sweep_get_quality(sweep, &q);
    fputs("  \"quality\": {", file);
    json_field(file, "", "min_dihedral_deg", q.min_dihedral_deg);
    json_field(file, ", ", "max_dihedral_deg", q.max_dihedral_deg);
    json_field(file, ", ", "min_scaled_jacobian", q.min_scaled_jacobian);
    json_field(file, ", ", "max_aspect_ratio", q.max_aspect_ratio);
    fputs(", \"aspect_ratio_measure\": ", file);
    json_string(file, info->tets ? "longest edge / (2 sqrt(6) inradius), 1 for the regular tetrahedron"
                                 : "longest edge / shortest edge");
    fputs(",\n              ", file);
    json_field(file, "", "max_prism_flatness", q.max_flatness);
    json_field(file, ", ", "flat_ratio", CM_SWEEP_FLAT_RATIO);
    fprintf(file, ", \"flat_prisms\": %zu},\n", q.flat_prisms);
    fputs("  \"warnings\": [", file);
    if (info->warning) json_string(file, info->warning);
    fputs("]\n}\n", file);
    return output_close(file, path, error);
}
