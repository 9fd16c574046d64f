// Input files as text, and paths given relative to the file that names them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace pierre::io::detail {

// The largest input file read (bytes).
inline constexpr std::uintmax_t kMaxInputBytes = std::uintmax_t{256} << 20;

// The whole text of a file; InputError (line 0, field "file") when it is missing, a folder,
// cannot be read, or holds more than kMaxInputBytes (a pipe or device is read up to that). `what` names it in the message ("scenario file (TOML)").
std::string read_text(const std::filesystem::path& file, std::string_view what);

// `p` relative to the folder of `base_file` (absolute paths as they are).
std::filesystem::path relative_to(const std::filesystem::path& base_file, const std::string& p);

}  // namespace pierre::io::detail
