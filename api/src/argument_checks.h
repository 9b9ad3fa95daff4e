#pragma once
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

/// Argument checks of the C ABI: a refused argument is DM_ERROR_ARGUMENT and its message
/// dm_last_error's.
namespace dymesh::api {

struct ArgumentError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

inline void Require(bool ok, const std::string& what) {
  if (!ok) throw ArgumentError(what);
}

template <typename T>
void NotNull(const T* p, const std::string& name) {
  Require(p != nullptr, name + " is null");
}

inline bool Finite(const double* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

/// A number as a message shows it: six significant digits (1e+300, not 300 digits; nan, inf).
inline std::string Number(double v) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%.6g", v);
  return digits;
}

/// Refuses a non-finite `value`, naming `field`.
inline void RequireFinite(double value, const std::string& field) {
  Require(std::isfinite(value), field + ": expected a finite number, got " + Number(value));
}

/// Whether `text` is well-formed UTF-8 (RFC 3629: no overlong forms, surrogates or code points
/// past U+10FFFF).
inline bool IsUtf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    // the sequence's length and its second byte's range, by its first byte
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF;
    if (c < 0x80) n = 1;
    else if (c >= 0xC2 && c <= 0xDF) n = 2;
    else if (c == 0xE0) n = 3, lo = 0xA0;
    else if (c >= 0xE1 && c <= 0xEC) n = 3;
    else if (c == 0xED) n = 3, hi = 0x9F;  // no surrogates
    else if (c >= 0xEE && c <= 0xEF) n = 3;
    else if (c == 0xF0) n = 4, lo = 0x90;
    else if (c >= 0xF1 && c <= 0xF3) n = 4;
    else if (c == 0xF4) n = 4, hi = 0x8F;  // at most U+10FFFF
    else return false;
    if (i + n > text.size()) return false;
    for (std::size_t k = 1; k < n; ++k) {
      const auto b = static_cast<unsigned char>(text[i + k]);
      if (b < (k == 1 ? lo : 0x80) || b > (k == 1 ? hi : 0xBF)) return false;
    }
    i += n;
  }
  return true;
}

/// `text` with every byte outside printable ASCII as \xHH: for a message about text that is not
/// UTF-8 (its bytes shown, not passed on).
inline std::string HexEscaped(std::string_view text) {
  std::string out;
  char escape[8];
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7F && c != '\\') {
      out += ch;
    } else {
      std::snprintf(escape, sizeof escape, "\\x%02X", c);
      out += escape;
    }
  }
  return out;
}

}  // namespace dymesh::api
