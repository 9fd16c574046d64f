#include "xlsx_parts_check.hpp"

#include <unzip.h>

#include <cstddef>
#include <vector>

namespace pierre::io::detail {

namespace {

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

bool ends_with(const std::string& s, std::size_t end, const std::string& tail) {
  return end >= tail.size() && s.compare(end - tail.size(), tail.size(), tail) == 0;
}

// The whole of the current member of `zip`; nothing when it cannot be read to its end.
std::optional<std::string> read_member(unzFile zip) {
  if (unzOpenCurrentFile(zip) != UNZ_OK) return std::nullopt;
  std::string text;
  std::vector<char> buf(1 << 16);
  int n;
  while ((n = unzReadCurrentFile(zip, buf.data(), static_cast<unsigned>(buf.size()))) > 0)
    text.append(buf.data(), static_cast<std::size_t>(n));
  // unzCloseCurrentFile checks the CRC of what was read against the archive's.
  if (unzCloseCurrentFile(zip) != UNZ_OK || n < 0) return std::nullopt;
  return text;
}

}  // namespace

bool xml_part_is_whole(const std::string& xml) {
  // The root element: the first '<' that opens neither a declaration (<?) nor a comment (<!).
  std::size_t at = 0;
  while ((at = xml.find('<', at)) != std::string::npos && at + 1 < xml.size() &&
         (xml[at + 1] == '?' || xml[at + 1] == '!'))
    ++at;
  if (at == std::string::npos || at + 1 >= xml.size()) return false;
  std::size_t name_end = at + 1;
  while (name_end < xml.size() && !is_space(xml[name_end]) && xml[name_end] != '>' &&
         xml[name_end] != '/')
    ++name_end;
  const std::string root = xml.substr(at + 1, name_end - at - 1);
  std::size_t end = xml.size();
  while (end > 0 && is_space(xml[end - 1])) --end;
  if (ends_with(xml, end, "</" + root + ">")) return true;
  // <root .../> and nothing after it.
  const std::size_t close = xml.find('>', name_end);
  return close != std::string::npos && close + 1 == end && xml[close - 1] == '/';
}

std::optional<std::string> first_incomplete_part(const std::filesystem::path& xlsx) {
  unzFile zip = unzOpen64(xlsx.c_str());
  if (!zip) return std::string("the archive");
  std::optional<std::string> bad;
  int r = unzGoToFirstFile(zip);
  for (; r == UNZ_OK && !bad; r = unzGoToNextFile(zip)) {
    char name[512];
    unz_file_info64 info;
    if (unzGetCurrentFileInfo64(zip, &info, name, sizeof name, nullptr, 0, nullptr, 0) != UNZ_OK) {
      bad = "the archive";
      break;
    }
    const std::string part(name);
    const std::optional<std::string> text = read_member(zip);
    const bool xml = ends_with(part, part.size(), ".xml") || ends_with(part, part.size(), ".rels");
    if (!text || (xml && !xml_part_is_whole(*text))) bad = part;
  }
  if (!bad && r != UNZ_END_OF_LIST_OF_FILE) bad = "the archive";
  unzClose(zip);
  return bad;
}

}  // namespace pierre::io::detail
