#pragma once

#include <charconv>
#include <string>
#include <system_error>

namespace pf {

// `value` as printf's "%.<precision>g" (general) or "%.<precision>f" (fixed) writes it in
// the C locale, whatever LC_NUMERIC says. QCoreApplication sets the user's LC_NUMERIC,
// under which snprintf and std::to_string(double) write "0,12": an OBJ file no reader
// takes, and an English report with German digits in it.
// (Room for any double in fixed notation, 309 digits before the point, at the precisions
// used.)
inline std::string cLocaleNumber(double value, std::chars_format format, int precision) {
    char text[400];
    const std::to_chars_result r =
        std::to_chars(text, text + sizeof text, value, format, precision);
    if (r.ec != std::errc()) return "?"; // not at the precisions used
    return std::string(text, r.ptr);
}

} // namespace pf
