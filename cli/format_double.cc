/* format_double (format_double.h) through Google's double-conversion, whose
 * ToShortest is the Grisu3 shortest round-trip algorithm with an exact
 * bignum fallback. */
#include "format_double.h"

#include <double-conversion/double-to-string.h>

namespace {

using double_conversion::DoubleToStringConverter;

/* -0 keeps its sign (no UNIQUE_ZERO), positive exponents have a '+' as
 * printf's do, plain decimals in [1e-6, 1e17). */
const DoubleToStringConverter converter(DoubleToStringConverter::EMIT_POSITIVE_EXPONENT_SIGN,
                                        "inf", "nan", 'e', -6, 17, 0, 0);

} // namespace

extern "C" char *format_double(char *at, double x)
{
    double_conversion::StringBuilder text(at, FORMAT_DOUBLE_SIZE);
    converter.ToShortest(x, &text);
    int length = text.position();
    text.Finalize();
    return at + length;
}
