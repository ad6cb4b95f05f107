/* The swept volume: sections stacked into prisms valid along their blends. */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

struct cm_sweep {
    char message[512];
};

void cm_sweep_options_init(cm_sweep_options *options)
{
    memset(options, 0, sizeof *options);
    options->sections = 11;
    options->height = 1.0;
    options->max_refine = 1000;
}

cm_status cm_sweep_create(cm_morph *morph, const cm_sweep_options *options, cm_sweep **sweep)
{
    (void)morph, (void)options;
    if (!sweep) return CM_ERR_ARGUMENT;
    *sweep = calloc(1, sizeof **sweep);
    if (!*sweep) return CM_ERR_NO_MEMORY;
    strcpy((*sweep)->message, "sweep: not implemented yet");
    return CM_ERR_ARGUMENT;
}

void cm_sweep_free(cm_sweep *sweep) { free(sweep); }
const char *cm_sweep_message(const cm_sweep *sweep) { return sweep ? sweep->message : "no sweep"; }
size_t cm_sweep_num_sections(const cm_sweep *sweep) { (void)sweep; return 0; }
const double *cm_sweep_section_z(const cm_sweep *sweep) { (void)sweep; return NULL; }
size_t cm_sweep_num_nodes(const cm_sweep *sweep) { (void)sweep; return 0; }
const double *cm_sweep_nodes(const cm_sweep *sweep) { (void)sweep; return NULL; }
size_t cm_sweep_num_prisms(const cm_sweep *sweep) { (void)sweep; return 0; }
const int32_t *cm_sweep_prisms(const cm_sweep *sweep) { (void)sweep; return NULL; }
size_t cm_sweep_num_tets(const cm_sweep *sweep) { (void)sweep; return 0; }
const int32_t *cm_sweep_tets(const cm_sweep *sweep) { (void)sweep; return NULL; }
double cm_sweep_volume(const cm_sweep *sweep) { (void)sweep; return 0.0; }
