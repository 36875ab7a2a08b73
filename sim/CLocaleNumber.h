#pragma once

#include <charconv>
#include <string>

namespace pf {

// `value` as printf's "%.<precision>g" (general) or "%.<precision>f" (fixed) writes it in
// the C locale, whatever LC_NUMERIC says. QCoreApplication sets the user's LC_NUMERIC,
// under which snprintf and std::to_string(double) write "0,12": an OBJ file no reader
// takes, and an English report with German digits in it.
inline std::string cLocaleNumber(double value, std::chars_format format, int precision) {
    char text[64];
    const std::to_chars_result r =
        std::to_chars(text, text + sizeof text, value, format, precision);
    return std::string(text, r.ptr);
}

} // namespace pf
