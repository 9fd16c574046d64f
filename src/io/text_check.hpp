// Text from an input file ends up in the report (XML documents inside the xlsx) and in the CSV
// and JSON outputs. XML 1.0 holds only well-formed UTF-8 without control characters (other than
// tab, line feed and carriage return) and without U+FFFE and U+FFFF; anything else makes a
// workbook Excel refuses. TOML text is UTF-8 already (its parser checks); CSV cells are bytes,
// and a Latin-1 or Windows-1252 export is common.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace pierre::io::detail {

// What is wrong with `s` for the found-value of an InputError, or nothing when it may be written.
// `place` names a byte's place in `s`: "position" in a cell, "column" in a line.
inline std::optional<std::string> unwritable_text(std::string_view s,
                                                  std::string_view place = "position") {
  for (std::size_t i = 0; i < s.size();) {
    const auto b = static_cast<unsigned char>(s[i]);
    if (b < 0x80) {
      if ((b < 0x20 && b != '\t' && b != '\n' && b != '\r') || b == 0x7F)
        return fmt::format("a text with the control character U+{:04X} at {} {}", b, place, i + 1);
      ++i;
      continue;
    }
    // A multi-byte sequence: its length from the lead byte, continuation bytes 10xxxxxx, the
    // shortest form, no surrogates, at most U+10FFFF (RFC 3629).
    const std::size_t len = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC0 ? 2 : 0;
    char32_t cp = len == 4 ? b & 0x07u : len == 3 ? b & 0x0Fu : b & 0x1Fu;
    bool ok = len != 0 && i + len <= s.size();
    for (std::size_t k = 1; ok && k < len; ++k) {
      const auto c = static_cast<unsigned char>(s[i + k]);
      ok = (c & 0xC0) == 0x80;
      cp = (cp << 6) | (c & 0x3Fu);
    }
    const char32_t lowest = len == 4 ? 0x10000 : len == 3 ? 0x800 : 0x80;
    ok = ok && cp >= lowest && cp <= 0x10FFFF && !(cp >= 0xD800 && cp <= 0xDFFF);
    if (!ok)
      return fmt::format("a text that is not UTF-8 (byte 0x{:02X} at {} {}; save the file "
                         "as UTF-8)", b, place, i + 1);
    if (cp == 0xFFFE || cp == 0xFFFF)
      return fmt::format("a text with the non-character U+{:04X}", static_cast<unsigned>(cp));
    i += len;
  }
  return std::nullopt;
}

inline constexpr std::string_view kWritableText =
    "UTF-8 text without control characters (other than tab and line breaks)";

}  // namespace pierre::io::detail
