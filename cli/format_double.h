/* Doubles as text for every text writer of the tool: the shortest decimal
 * that reads back (strtod, Python's float, NumPy) as the same double,
 * bit for bit, -0 and subnormals included. Shortest, not "%.17g": 0.1 stays
 * "0.1" rather than "0.10000000000000001". */
#ifndef CM_CLI_FORMAT_DOUBLE_H
#define CM_CLI_FORMAT_DOUBLE_H

#ifdef __cplusplus
extern "C" {
#endif

/* The longest text plus its terminating NUL: sign, "0.", five leading
 * zeros, 17 digits ("-0.0000012345678901234567"), or an exponent form
 * ("-1.7976931348623157e+308"). */
enum { FORMAT_DOUBLE_SIZE = 32 };

/* Writes x at `at` (room for FORMAT_DOUBLE_SIZE bytes) NUL-terminated, and
 * returns the end (the NUL). Plain decimals for 1e-6 <= |x| < 1e17, else
 * "d.ddde+NN"; "inf", "-inf", "nan" for the values that have no digits. */
char *format_double(char *at, double x);

#ifdef __cplusplus
}
#endif

#endif
