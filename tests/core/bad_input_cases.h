/* Reader for tests/bad_input/cases.txt, the bad-input matrix every entry
 * point's test walks (format described in that file). C and C++.
 *
 *   bic_case *cases; size_t count;
 *   if (bic_load(path, &cases, &count) != 0) ...;   message on stderr
 *   ... cases[i].name, .status, .polygon, .vertex, .fragment,
 *       .k, .counts[g], .xy[g] (2 * counts[g] doubles) ...
 *   bic_free(cases, count);
 */
#ifndef CM_TEST_BAD_INPUT_CASES_H
#define CM_TEST_BAD_INPUT_CASES_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compatmesh/compatmesh.h"

enum { BIC_MAX_POLYGONS = 4, BIC_NOT_CHECKED = -2 };

typedef struct bic_case {
    char name[96];
    cm_status status;
    long polygon, vertex; /* BIC_NOT_CHECKED for '*' or '-' */
    char fragment[160];
    size_t k;
    size_t counts[BIC_MAX_POLYGONS];
    double *xy[BIC_MAX_POLYGONS];
} bic_case;

static inline char *bic_trim(char *s)
{
    while (*s == ' ' || *s == '\t') s++;
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\n' || s[n - 1] == '\r')) s[--n] = '\0';
    return s;
}

static inline int bic_status(const char *text, cm_status *status)
{
    for (int s = CM_OK; s <= CM_ERR_PRECISION; s++)
        if (strcmp(cm_status_string((cm_status)s), text) == 0) {
            *status = (cm_status)s;
            return 0;
        }
    return -1;
}

static inline long bic_location(const char *text)
{
    return text[0] == '*' || (text[0] == '-' && text[1] == '\0') ? (long)BIC_NOT_CHECKED : strtol(text, NULL, 10);
}

static inline void bic_free(bic_case *cases, size_t count)
{
    for (size_t i = 0; i < count; i++)
        for (size_t g = 0; g < cases[i].k; g++) free(cases[i].xy[g]);
    free(cases);
}

static inline int bic_load(const char *path, bic_case **out, size_t *out_count)
{
    FILE *file = fopen(path, "r");
    if (!file) {
        fprintf(stderr, "%s: cannot open\n", path);
        return -1;
    }
    bic_case *cases = NULL;
    size_t count = 0;
    char line[4096];
    long number = 0;
    int bad = 0;
    while (!bad && fgets(line, sizeof line, file)) {
        number++;
        char *text = bic_trim(line);
        if (text[0] == '#' || text[0] == '\0') continue;
        if (strncmp(text, "case ", 5) == 0) {
            bic_case *more = (bic_case *)realloc(cases, (count + 1) * sizeof *cases);
            if (!more) { bad = 1; break; }
            cases = more;
            bic_case *c = &cases[count++];
            memset(c, 0, sizeof *c);
            char *field[4] = {text + 5, NULL, NULL, NULL};
            for (int f = 1; f < 4; f++) {
                char *bar = field[f - 1] ? strchr(field[f - 1], '|') : NULL;
                if (bar) { *bar = '\0'; field[f] = bar + 1; }
            }
            char where[2][32] = {"", ""};
            bad = !field[3] || bic_status(bic_trim(field[1]), &c->status) != 0 ||
                  sscanf(field[2], "%31s %31s", where[0], where[1]) != 2;
            if (!bad) {
                snprintf(c->name, sizeof c->name, "%s", bic_trim(field[0]));
                snprintf(c->fragment, sizeof c->fragment, "%s", bic_trim(field[3]));
                c->polygon = bic_location(where[0]);
                c->vertex = bic_location(where[1]);
            }
        } else if (strncmp(text, "poly ", 5) == 0 && count && cases[count - 1].k < BIC_MAX_POLYGONS) {
            bic_case *c = &cases[count - 1];
            double *xy = (double *)malloc(sizeof(double) * strlen(text));
            size_t n = 0;
            char *p = text + 5, *end;
            for (double v = strtod(p, &end); end != p; v = strtod(p, &end)) {
                xy[n++] = v;
                p = end;
            }
            bad = n % 2 != 0 || *bic_trim(p) != '\0';
            c->xy[c->k] = xy;
            c->counts[c->k++] = n / 2;
        } else {
            bad = 1;
        }
    }
    fclose(file);
    if (bad || count == 0) {
        fprintf(stderr, "%s:%ld: malformed bad-input case\n", path, number);
        bic_free(cases, count);
        return -1;
    }
    *out = cases;
    *out_count = count;
    return 0;
}

#endif
