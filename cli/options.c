#include "options.h"

#include <errno.h>
#include <getopt.h>
#include <stdlib.h>
#include <string.h>

static const option_spec *find_option(const option_spec *specs, size_t count, int key)
{
    for (size_t i = 0; i < count; i++)
        if (specs[i].key == key) return &specs[i];
    return NULL;
}

/* getopt_long's '?': an unknown long option (optopt 0), a value given to a
 * flag (--flag=value; optopt is the flag's key), or an unknown short option
 * (optopt is the letter; the word at optind - 1 may be another argument). */
static void describe_bad_option(const char *word, const char *command,
                                const option_spec *specs, size_t count,
                                cli_error *error)
{
    const option_spec *flag = optopt ? find_option(specs, count, optopt) : NULL;
    const char *equals = strchr(word, '=');
    int length = equals ? (int)(equals - word) : (int)strlen(word);
    if (strncmp(word, "--", 2) == 0 && optopt == 0)
        cli_error_set(error, "%s: unknown option '%.*s' (see 'compatmesh %s --help')",
                      command, length, word, command);
    else if (strncmp(word, "--", 2) == 0 && flag && equals &&
             strncmp(flag->name, word + 2, (size_t)length - 2) == 0)
        cli_error_set(error, "%s: option '--%s' takes no value", command, flag->name);
    else
        cli_error_set(error, "%s: unknown option '-%c' (see 'compatmesh %s --help')",
                      command, optopt, command);
}

/* Wraps getopt_long so that every problem becomes one clear message naming
 * the command. Options and positional arguments may be mixed; "--" ends the
 * options. */
int parse_options(int argc, char **argv, const char *command,
                         const option_spec *specs, size_t count,
                         option_handler handle, void *context, cli_error *error)
{
    struct option long_options[MAX_OPTIONS + 1] = {{0}};
    char short_options[3 * MAX_OPTIONS + 3] = "-:"; /* in order; report ':' */
    size_t used = 2;
    for (size_t i = 0; i < count && i < MAX_OPTIONS; i++) {
        long_options[i] = (struct option){specs[i].name,
                                          specs[i].value ? required_argument : no_argument,
                                          NULL, specs[i].key};
        if (specs[i].key < 256) {
            short_options[used++] = (char)specs[i].key;
            if (specs[i].value) short_options[used++] = ':';
        }
    }
    short_options[used] = '\0';
    opterr = 0;
    optind = 0; /* glibc: start afresh */
    int key, code = CLI_EXIT_OK;
    while (code == CLI_EXIT_OK &&
           (key = getopt_long(argc, argv, short_options, long_options, NULL)) != -1) {
        if (key == '?') {
            describe_bad_option(argv[optind - 1], command, specs, count, error);
            code = CLI_EXIT_USAGE;
        } else if (key == ':') {
            const option_spec *spec = find_option(specs, count, optopt);
            cli_error_set(error, "%s: option '--%s' needs a value %s", command,
                          spec ? spec->name : "?", spec ? spec->value : "");
            code = CLI_EXIT_USAGE;
        } else {
            code = handle(context, key == 1 ? 0 : key, optarg, error);
        }
    }
    for (int i = optind; code == CLI_EXIT_OK && i < argc; i++)
        code = handle(context, 0, argv[i], error); /* what followed "--" */
    return code;
}

void print_options(FILE *out, const option_spec *specs, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        int width;
        if (specs[i].key < 256)
            width = fprintf(out, "  -%c, --%s", specs[i].key, specs[i].name);
        else
            width = fprintf(out, "      --%s", specs[i].name);
        if (specs[i].value) width += fprintf(out, " %s", specs[i].value);
        if (width >= OPTION_HELP_COLUMN - 1) {
            fputc('\n', out);
            width = 0;
        }
        fprintf(out, "%*s", OPTION_HELP_COLUMN - width, "");
        for (const char *c = specs[i].help; *c; c++) {
            fputc(*c, out);
            if (*c == '\n') fprintf(out, "%*s", OPTION_HELP_COLUMN, "");
        }
        fputc('\n', out);
    }
}

long parse_whole_number(const char *text, long low, long high)
{
    char *end;
    errno = 0;
    long value = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE || value < low || value > high)
        return -1;
    return value;
}
