#include "text_file.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "pierre/io/input_error.hpp"

namespace pierre::io::detail {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file, std::string_view what) {
  const std::string expected = fmt::format("a readable {}", what);
  // A folder opens as an empty stream: said as what it is, not as an empty file.
  if (std::error_code ec; fs::is_directory(file, ec))
    throw InputError(file, 0, "file", "a folder, not a file", expected);
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::error_code ec;
    const bool exists = fs::is_regular_file(file, ec);
    throw InputError(file, 0, "file", exists ? "a file that cannot be read" : "no such file",
                     expected);
  }
  std::stringstream buf;
  buf << in.rdbuf();
  return buf.str();
}

fs::path relative_to(const fs::path& base_file, const std::string& p) {
  const fs::path q(p);
  return q.is_absolute() ? q : base_file.parent_path() / q;
}

}  // namespace pierre::io::detail
