#pragma once
#include <cstdio>
#include <string>
#include <string_view>

/// Text from a user's file shown in a message: control bytes written as escapes, so that a NUL does
/// not end the message and a CR or an escape sequence does not rewrite the terminal.
namespace dymesh {

/// Bytes of the control character at text[i]: 1 for C0 (below 0x20) and DEL, 2 for C1 (U+0080..U+009F,
/// the UTF-8 bytes C2 80..C2 9F), 0 for anything else.
inline std::size_t ControlCharacterBytes(std::string_view text, std::size_t i) {
  const auto c = static_cast<unsigned char>(text[i]);
  const auto next = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0;
  if (c < 0x20 || c == 0x7F) return 1;
  return c == 0xC2 && next >= 0x80 && next <= 0x9F ? 2 : 0;
}

/// Whether `text` holds a control character: C0, DEL or C1.
inline bool HasControlCharacter(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i)
    if (ControlCharacterBytes(text, i) > 0) return true;
  return false;
}

/// Whether a body's name can be part of its output files' names (NAME_deformed.obj, ...): not
/// empty, no / or \, no control character, not "." or "..".
inline bool UsableInFileNames(std::string_view name) {
  return !name.empty() && !HasControlCharacter(name) && name.find_first_of("/\\") == std::string_view::npos &&
         name != "." && name != "..";
}

/// What UsableInFileNames asks, for messages.
inline constexpr const char* kFileNameRule =
    "a name usable in file names (no /, \\ or control characters, DEL and U+0080..U+009F included)";

/// `text` with tab, newline and CR as \t, \n, \r, other C0 controls and DEL as \xHH, and the C1
/// controls as \u00HH; everything else as it is.
inline std::string Printable(std::string_view text) {
  std::string out;
  char escape[8];
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const std::size_t control = ControlCharacterBytes(text, i);
    if (control == 2) {
      std::snprintf(escape, sizeof escape, "\\u00%02X", static_cast<unsigned char>(text[++i]));
      out += escape;
    } else if (c == '\t' || c == '\n' || c == '\r') {
      out += c == '\t' ? "\\t" : c == '\n' ? "\\n" : "\\r";
    } else if (control == 1) {
      std::snprintf(escape, sizeof escape, "\\x%02X", c);
      out += escape;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

}  // namespace dymesh
