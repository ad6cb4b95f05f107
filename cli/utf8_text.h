/* Text from file names made safe for output: JSON (jansson), SVG and PNG
 * captions (cairo) all need well-formed UTF-8. */
#ifndef CM_CLI_UTF8_TEXT_H
#define CM_CLI_UTF8_TEXT_H

/* A copy of text (free it) in which bytes that are not well-formed UTF-8
 * become U+FFFD, and so do control characters other than tab when
 * replace_controls is set (a caption has no use for them; JSON escapes
 * them). NULL if out of memory. */
char *utf8_repaired_copy(const char *text, int replace_controls);

#endif
