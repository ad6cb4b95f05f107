/* Morphing through valid sections (paper section 1; Floater and Gotsman). */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

struct cm_morph {
    char message[512];
};

void cm_morph_options_init(cm_morph_options *options)
{
    memset(options, 0, sizeof *options);
    options->method = CM_MORPH_CONVEX;
}

cm_status cm_morph_create(const cm_result *result, const cm_morph_options *options,
                          cm_morph **morph)
{
    (void)result, (void)options;
    if (!morph) return CM_ERR_ARGUMENT;
    *morph = calloc(1, sizeof **morph);
    if (!*morph) return CM_ERR_NO_MEMORY;
    strcpy((*morph)->message, "morph: not implemented yet");
    return CM_ERR_ARGUMENT;
}

void cm_morph_free(cm_morph *morph) { free(morph); }

const char *cm_morph_message(const cm_morph *morph) { return morph ? morph->message : "no morph"; }

cm_status cm_morph_section(cm_morph *morph, double t, double *xy, size_t *inverted,
                           double *min_angle_deg)
{
    (void)morph, (void)t, (void)xy, (void)inverted, (void)min_angle_deg;
    return CM_ERR_ARGUMENT;
}
