/// \file
/// rb::fromChars: std::from_chars, also for double where the standard library lacks it. The
/// WebAssembly build's libc++ (emscripten 3.1) has no floating-point from_chars; there it is
/// strtod on a copy, held to from_chars's rules: no leading space or '+', no hex, the same
/// errors. The native build calls std::from_chars itself.
#pragma once

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <string>
#include <system_error>
#include <type_traits>

namespace rb {

/// std::from_chars for integers.
template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
std::from_chars_result fromChars(const char* first, const char* last, Integer& value) {
    return std::from_chars(first, last, value);
}

/// std::from_chars for double (std::chars_format::general).
inline std::from_chars_result fromChars(const char* first, const char* last, double& value) {
#ifndef __EMSCRIPTEN__
    return std::from_chars(first, last, value);
#else
    const std::string text(first, last);
    const char* s = text.c_str();
    const char* digits = s + (s[0] == '-');
    // from_chars takes no leading space or '+', and reads "0x1p3" as 0 followed by "x1p3".
    if (text.empty() || std::isspace(static_cast<unsigned char>(s[0])) || s[0] == '+' ||
        (digits[0] == '-' || digits[0] == '+'))
        return {first, std::errc::invalid_argument};
    std::string plain = text;
    if (digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X'))
        plain = text.substr(0, static_cast<size_t>(digits - s) + 1);
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(plain.c_str(), &end);
    if (end == plain.c_str()) return {first, std::errc::invalid_argument};
    const char* ptr = first + (end - plain.c_str());
    if (errno == ERANGE) return {ptr, std::errc::result_out_of_range};
    value = v;
    return {ptr, std::errc()};
#endif
}

}  // namespace rb
