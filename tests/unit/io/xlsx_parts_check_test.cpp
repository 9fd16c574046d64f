// The read-back of a written workbook (xlsx_parts_check.hpp): a part cut short anywhere is
// found, a whole one passes. A whole report and files that are not one: xlsx_report_test.cpp;
// the end-to-end case (libxlsxwriter under a file size limit) is in
// tests/unit/app/cli_test.cpp.
#include <gtest/gtest.h>

#include <string>

#include "xlsx_parts_check.hpp"

namespace {

using pierre::io::detail::xml_part_is_whole;

// Every text cut before its root's end tag is complete is found incomplete; the whole text,
// with or without trailing white space, is not.
void expect_only_whole_passes(const std::string& xml, std::size_t whole_from) {
  for (std::size_t n = 0; n < xml.size(); ++n)
    EXPECT_EQ(xml_part_is_whole(xml.substr(0, n)), n >= whole_from) << "first " << n << " chars";
  EXPECT_TRUE(xml_part_is_whole(xml));
}

TEST(XlsxPartsCheck, APartCutAnywhereIsFound) {
  const std::string sheet =
      "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n"
      "<worksheet xmlns=\"http://schemas.openxmlformats.org/spreadsheetml/2006/main\">"
      "<sheetData><row r=\"1\"><c r=\"A1\"><v>1</v></c></row></sheetData></worksheet>\n";
  expect_only_whole_passes(sheet, sheet.size() - 1);  // the newline after the end tag may go
  // A chart's root has a prefix; a root closed in itself (an empty part) is whole too.
  const std::string chart = "<?xml version=\"1.0\"?>\n<c:chartSpace a=\"1\"><c:chart/></c:chartSpace>";
  expect_only_whole_passes(chart, chart.size());
  const std::string empty = "<?xml version=\"1.0\"?>\n<!-- none --><Relationships x=\"y\"/>";
  expect_only_whole_passes(empty, empty.size());
  // An end tag of another element at the end is not the root's.
  EXPECT_FALSE(xml_part_is_whole("<worksheet><sheetData></sheetData>"));
  EXPECT_FALSE(xml_part_is_whole("<worksheet><worksheetx/>"));
}

}  // namespace
