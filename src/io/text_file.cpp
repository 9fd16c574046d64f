#include "text_file.hpp"

#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "pierre/io/input_error.hpp"
#include "pierre/io/input_files.hpp"

namespace pierre::io::detail {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file, std::string_view what) {
  const std::string expected = fmt::format("a readable {}", what);
  // A folder opens as an empty stream: said as what it is, not as an empty file.
  if (std::error_code ec; fs::is_directory(file, ec))
    throw InputError(file, 0, "file", "a folder, not a file", expected);
  // No input is anywhere near this size (a profile of a million vertices is ~30 MB): a larger
  // one is the wrong file, or an endless stream such as /dev/zero, which would fill the memory.
  const auto too_large = [&](const std::string& size) {
    return InputError(file, 0, "file",
                      fmt::format("{} (no input is that large: the wrong file, or an endless "
                                  "stream)",
                                  size),
                      fmt::format("a {} of at most {} MiB", what, kMaxInputBytes >> 20));
  };
  if (std::error_code ec; fs::is_regular_file(file, ec)) {
    if (const auto size = fs::file_size(file, ec); !ec && size > kMaxInputBytes)
      throw too_large(fmt::format("{} bytes", size));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::error_code ec;
    const bool exists = fs::is_regular_file(file, ec);
    throw InputError(file, 0, "file", exists ? "a file that cannot be read" : "no such file",
                     expected);
  }
  // In pieces, so that a pipe or a device is read no further than the limit.
  std::string text;
  char piece[1 << 16];
  while (in.read(piece, sizeof piece) || in.gcount() > 0) {
    text.append(piece, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxInputBytes)
      throw too_large(fmt::format("more than {} MiB", kMaxInputBytes >> 20));
  }
  InputFilesRecord::note(file, text);
  return text;
}

fs::path relative_to(const fs::path& base_file, const std::string& p) {
  const fs::path q(p);
  return q.is_absolute() ? q : base_file.parent_path() / q;
}

}  // namespace pierre::io::detail
