// A written workbook read back before it replaces an earlier one. libxlsxwriter (1.1.4) makes
// each sheet and chart in a temporary file and does not check those writes: on a full disk or
// under a file size limit, a part is cut short and the workbook still closes without an error,
// a report that Excel calls corrupt. Each XML part must end with its root element's end tag.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace pierre::io::detail {

// The name of the first part of `xlsx` that is cut short or cannot be read ("the archive" when
// the zip itself cannot be opened); nothing when every part is whole.
std::optional<std::string> first_incomplete_part(const std::filesystem::path& xlsx);

// Whether `xml` (a whole part's text) ends with the end tag of its root element, or is a root
// element closed in itself. Exposed for the tests.
bool xml_part_is_whole(const std::string& xml);

}  // namespace pierre::io::detail
