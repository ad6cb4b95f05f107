#include "utf8_text.h"

#include <stdlib.h>
#include <string.h>

#include "cli_common.h"

char *utf8_repaired_copy(const char *text, int replace_controls)
{
    size_t remaining = strlen(text);
    char *copy = malloc(3 * remaining + 1), *out = copy; /* U+FFFD is 3 bytes */
    if (!copy) return NULL;
    for (const unsigned char *c = (const unsigned char *)text; remaining > 0;) {
        size_t length = utf8_sequence_length(c, remaining);
        if (length == 0 || (replace_controls && *c < 0x20 && *c != '\t')) {
            memcpy(out, "\xEF\xBF\xBD", 3), out += 3;
            length = length ? length : 1;
        } else {
            memcpy(out, c, length), out += length;
        }
        c += length, remaining -= length;
    }
    *out = '\0';
    return copy;
}
