#define _POSIX_C_SOURCE 200809L /* getline, strdup */

#include "batch_list.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "triangulation.h"

#define BLANKS " \t\r\v\f"

void batch_list_free(batch_list *list)
{
    for (size_t i = 0; i < list->count; i++) {
        batch_entry *e = &list->entries[i];
        free(e->name);
        for (size_t j = 0; j < e->input_count; j++) free(e->inputs[j]);
        free(e->inputs);
    }
    free(list->entries);
    memset(list, 0, sizeof *list);
}

/* The folder of the list ("" for a bare file name), to resolve against. */
static char *list_folder(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t length = slash ? (size_t)(slash - path) + 1 : 0;
    char *folder = malloc(length + 1);
    if (folder) {
        memcpy(folder, path, length);
        folder[length] = '\0';
    }
    return folder;
}

static char *resolve(const char *folder, const char *path)
{
    size_t a = path[0] == '/' ? 0 : strlen(folder), b = strlen(path);
    char *resolved = malloc(a + b + 1);
    if (resolved) {
        memcpy(resolved, folder, a);
        memcpy(resolved + a, path, b + 1);
    }
    return resolved;
}

/* A folder name inside the output directory: one path component, not
 * hidden (staging directories are), not the batch's report. */
static int valid_name(const char *name)
{
    return name[0] != '\0' && name[0] != '.' && !strchr(name, '/') &&
           strcmp(name, "batch.json") != 0;
}

/* "LINE-STEM": the line number and the first input's stem. */
static char *default_name(long line, const char *first_input)
{
    char *stem = file_stem(first_input);
    if (!stem) return NULL;
    size_t size = strlen(stem) + 24;
    char *name = malloc(size);
    if (name) snprintf(name, size, "%ld-%s", line, stem);
    free(stem);
    return name;
}

/* Splits one line (comment already cut) into fields, in place. */
static size_t split_fields(char *text, char ***fields, size_t *capacity)
{
    size_t count = 0;
    char *save = NULL;
    for (char *field = strtok_r(text, BLANKS, &save); field; field = strtok_r(NULL, BLANKS, &save)) {
        if (count == *capacity) {
            size_t grown = *capacity ? 2 * *capacity : 16;
            char **more = realloc(*fields, grown * sizeof *more);
            if (!more) return (size_t)-1;
            *fields = more, *capacity = grown;
        }
        (*fields)[count++] = field;
    }
    return count;
}

#define OUT_OF_MEMORY(error) (cli_error_set(error, "out of memory"), CLI_EXIT_INTERNAL)

/* One job from its fields; entry is zeroed and owned by the list already. */
static int parse_entry(const char *list_path, const char *folder, long line, char **fields,
                       size_t count, batch_entry *entry, cli_error *error)
{
    entry->line = line;
    size_t first = 0;
    size_t length = strlen(fields[0]);
    if (fields[0][length - 1] == ':') {
        fields[0][length - 1] = '\0';
        if (!valid_name(fields[0])) {
            cli_error_set(error, "%s:%ld: '%s:' is not a job name (one folder name, not "
                          "starting with '.', not batch.json)", list_path, line, fields[0]);
            return CLI_EXIT_USAGE;
        }
        if (!(entry->name = strdup(fields[0]))) return OUT_OF_MEMORY(error);
        first = 1;
    }
    if (count - first < 2) {
        cli_error_set(error, "%s:%ld: a job needs at least two input files, got %zu", list_path,
                      line, count - first);
        return CLI_EXIT_USAGE;
    }
    entry->inputs = calloc(count - first, sizeof *entry->inputs);
    if (!entry->inputs) return OUT_OF_MEMORY(error);
    for (size_t i = first; i < count; i++) {
        char *path = resolve(folder, fields[i]);
        if (!path) return OUT_OF_MEMORY(error);
        entry->inputs[entry->input_count++] = path;
        struct stat info;
        if (stat(path, &info) != 0) {
            cli_error_set(error, "%s:%ld: %s: %s", list_path, line, path, strerror(errno));
            return CLI_EXIT_USAGE;
        }
        if (S_ISDIR(info.st_mode)) {
            cli_error_set(error, "%s:%ld: %s is a directory, not a polygon file", list_path, line,
                          path);
            return CLI_EXIT_USAGE;
        }
    }
    if (!entry->name && !(entry->name = default_name(line, entry->inputs[0])))
        return OUT_OF_MEMORY(error);
    return CLI_EXIT_OK;
}

static int by_name_then_line(const void *a, const void *b)
{
    const batch_entry *x = *(const batch_entry *const *)a, *y = *(const batch_entry *const *)b;
    int order = strcmp(x->name, y->name);
    return order ? order : (x->line > y->line) - (x->line < y->line);
}

/* Two jobs writing into one folder would replace each other's files; the
 * first line that reuses a name is named (sorted, so long lists stay fast). */
static int check_names(const char *list_path, const batch_list *list, cli_error *error)
{
    const batch_entry **sorted = malloc(list->count * sizeof *sorted);
    if (!sorted) return OUT_OF_MEMORY(error);
    for (size_t i = 0; i < list->count; i++) sorted[i] = &list->entries[i];
    qsort(sorted, list->count, sizeof *sorted, by_name_then_line);
    const batch_entry *again = NULL, *before = NULL;
    for (size_t i = 1; i < list->count; i++)
        if (strcmp(sorted[i]->name, sorted[i - 1]->name) == 0 &&
            (!again || sorted[i]->line < again->line))
            again = sorted[i], before = sorted[i - 1];
    free(sorted);
    if (!again) return CLI_EXIT_OK;
    cli_error_set(error, "%s:%ld: the job folder '%s' is already line %ld's; name the job with "
                  "a leading 'NAME:' field", list_path, again->line, again->name, before->line);
    return CLI_EXIT_USAGE;
}

static int read_lines(FILE *file, const char *path, const char *folder, batch_list *list,
                      cli_error *error)
{
    char *text = NULL, **fields = NULL;
    size_t text_capacity = 0, field_capacity = 0, entry_capacity = 0;
    int code = CLI_EXIT_OK;
    long line = 0;
    while (code == CLI_EXIT_OK && getline(&text, &text_capacity, file) >= 0) {
        line++;
        text[strcspn(text, "#\n")] = '\0';
        size_t count = split_fields(text, &fields, &field_capacity);
        if (count == (size_t)-1) code = OUT_OF_MEMORY(error);
        if (code != CLI_EXIT_OK || count == 0) continue;
        if (list->count == entry_capacity) {
            size_t grown = entry_capacity ? 2 * entry_capacity : 16;
            batch_entry *more = realloc(list->entries, grown * sizeof *more);
            if (!more) {
                code = OUT_OF_MEMORY(error);
                continue;
            }
            list->entries = more, entry_capacity = grown;
        }
        batch_entry *entry = &list->entries[list->count++];
        memset(entry, 0, sizeof *entry);
        code = parse_entry(path, folder, line, fields, count, entry, error);
    }
    if (code == CLI_EXIT_OK && ferror(file)) {
        cli_error_set(error, "%s: cannot read: %s", path, strerror(errno));
        code = CLI_EXIT_USAGE;
    }
    free(text);
    free(fields);
    return code;
}

int batch_list_read(const char *path, batch_list *list, cli_error *error)
{
    memset(list, 0, sizeof *list);
    FILE *file = fopen(path, "r");
    if (!file) {
        cli_error_set(error, "%s: cannot open: %s", path, strerror(errno));
        return CLI_EXIT_USAGE;
    }
    char *folder = list_folder(path);
    int code = folder ? read_lines(file, path, folder, list, error) : OUT_OF_MEMORY(error);
    fclose(file);
    free(folder);
    if (code == CLI_EXIT_OK && list->count == 0) {
        cli_error_set(error, "%s: no jobs (one line per job: its input files)", path);
        code = CLI_EXIT_USAGE;
    }
    if (code == CLI_EXIT_OK) code = check_names(path, list, error);
    if (code != CLI_EXIT_OK) batch_list_free(list);
    return code;
}
