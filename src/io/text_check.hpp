// Text from an input file ends up in the report (an XML document inside the xlsx) and in the CSV
// and JSON outputs: XML 1.0 cannot hold control characters other than tab, line feed and
// carriage return, so a name with one (a bell, an escape) would make a workbook Excel refuses.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace pierre::io::detail {

// What is wrong with `s` for a found-value of an InputError, or nothing when it may be written.
inline std::optional<std::string> control_character_in(std::string_view s) {
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\t' && c != '\n' && c != '\r') || u == 0x7F)
      return fmt::format("a text with the control character U+{:04X}", u);
  }
  return std::nullopt;
}

inline constexpr std::string_view kNoControlCharacters =
    "text without control characters (other than tab and line breaks)";

}  // namespace pierre::io::detail
