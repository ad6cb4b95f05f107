/* Small pieces every part of the command-line tool shares: exit codes, the
 * error message buffer the modules fill and main prints, and the UTF-8 check
 * behind utf8_text.h (jansson and cairo take only valid UTF-8). */
#ifndef CM_CLI_COMMON_H
#define CM_CLI_COMMON_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

enum cli_exit_code {
    CLI_EXIT_OK = 0,
    CLI_EXIT_INTERNAL = 1,   /* library failure, out of memory, output I/O */
    CLI_EXIT_USAGE = 2,      /* bad input file or command line */
    CLI_EXIT_INTERRUPTED = 130
};

/* One line, without the "compatmesh: " prefix and without a newline. */
typedef struct cli_error {
    char message[1024];
} cli_error;

/* Prints the message as the tool's one line on stderr. */
static inline void cli_print_error(const cli_error *error)
{
    fprintf(stderr, "compatmesh: %s\n", error->message);
}

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static inline void cli_error_set(cli_error *error, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vsnprintf(error->message, sizeof error->message, format, args);
    va_end(args);
}

/* Does strtod read text as a hexadecimal number ("0x10", "-0X1p3")? Input
 * files write decimals: there a hexadecimal is a typo, not a number. */
static inline int cli_is_hexadecimal(const char *text)
{
    while (*text == ' ' || *text == '\t') text++;
    if (*text == '+' || *text == '-') text++;
    return text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
}

/* Length of the well-formed UTF-8 sequence starting at text (at most
 * `available` bytes), or 0 if the bytes there are not valid UTF-8. File names
 * can hold any bytes; JSON and XML readers reject malformed UTF-8. */
static inline size_t utf8_sequence_length(const unsigned char *text,
                                          size_t available)
{
    size_t length;
    unsigned long code;
    if (text[0] < 0x80) return 1;
    if (text[0] >= 0xC2 && text[0] <= 0xDF) { length = 2; code = text[0] & 0x1Fu; }
    else if (text[0] >= 0xE0 && text[0] <= 0xEF) { length = 3; code = text[0] & 0x0Fu; }
    else if (text[0] >= 0xF0 && text[0] <= 0xF4) { length = 4; code = text[0] & 0x07u; }
    else return 0;
    if (length > available) return 0;
    for (size_t i = 1; i < length; i++) {
        if ((text[i] & 0xC0) != 0x80) return 0;
        code = (code << 6) | (text[i] & 0x3Fu);
    }
    /* Reject overlong forms, surrogates and code points past U+10FFFF. */
    if ((length == 3 && code < 0x800) || (length == 4 && code < 0x10000) ||
        (code >= 0xD800 && code <= 0xDFFF) || code > 0x10FFFF)
        return 0;
    return length;
}

#endif
