#include "write_svg.h"

#include <stdio.h>
#include <string.h>

#include "outdir.h"

/* One CSS rule per style, from the table the PNG writer uses too. */
static void write_style(FILE *file)
{
    fputs("<style>\n", file);
    for (int s = 0; s < STYLE_COUNT; s++) {
        const style_paint *paint = &picture_styles[s];
        if (paint->filled)
            fprintf(file, ".%s{fill:#%06x;stroke:none}\n", paint->name, (unsigned)paint->rgb);
        else
            fprintf(file, ".%s{fill:none;stroke:#%06x;stroke-width:%g%s}\n", paint->name,
                    (unsigned)paint->rgb, paint->width,
                    paint->round ? ";stroke-linecap:round;stroke-linejoin:round" : "");
    }
    fprintf(file, "text{font-family:sans-serif;font-size:%dpx;fill:#000}\n</style>\n",
            PICTURE_FONT_PIXELS);
}

/* Dots are zero-length round-capped segments: one element for all. */
static void write_layer(FILE *file, const picture *pic, const picture_layer *layer)
{
    fprintf(file, "<path class=\"%s\" d=\"", picture_styles[layer->style].name);
    for (size_t i = layer->first; i < layer->first + layer->count; i++) {
        const path_step *step = &pic->steps[i];
        switch (step->kind) {
        case STEP_MOVE: fprintf(file, "M%.1f %.1f", step->x, step->y); break;
        case STEP_LINE: fprintf(file, "L%.1f %.1f", step->x, step->y); break;
        case STEP_CLOSE: fputc('Z', file); break;
        case STEP_DOT: fprintf(file, "M%.1f %.1fh0", step->x, step->y); break;
        }
    }
    fputs("\"/>\n", file);
}

/* Text content for XML (the picture's texts are valid UTF-8 already). */
static void xml_text(FILE *file, const char *text)
{
    for (const char *c = text; *c; c++) {
        if (*c == '&') fputs("&amp;", file);
        else if (*c == '<') fputs("&lt;", file);
        else if (*c == '>') fputs("&gt;", file);
        else fputc(*c, file);
    }
}

int write_svg(const char *path, const picture *pic, cli_error *error)
{
    FILE *file = output_open(path, error);
    if (!file) return CLI_EXIT_INTERNAL;
    fprintf(file, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" "
                  "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n",
            pic->width, pic->height, pic->width, pic->height);
    write_style(file);
    fputs("<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n", file);
    for (size_t g = 0; g < pic->panel_count; g++) {
        fputs("<g>\n", file);
        for (size_t l = 0; l < pic->layer_count; l++)
            if (pic->layers[l].panel == g) write_layer(file, pic, &pic->layers[l]);
        for (size_t t = 0; t < pic->text_count; t++) {
            if (pic->texts[t].panel != g) continue;
            fprintf(file, "<text x=\"%.2f\" y=\"%.2f\">", pic->texts[t].x, pic->texts[t].y);
            xml_text(file, pic->texts[t].text);
            fputs("</text>\n", file);
        }
        fputs("</g>\n", file);
    }
    fputs("</svg>\n", file);
    return output_close(file, path, error);
}
