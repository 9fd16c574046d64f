// One rounding per quantity on the console and in report.xlsx: the console's decimals of each
// number kind are those of the shipped layout's [formats] (templates/report.toml), so that the
// barrier table's E_d reads 1280.2 kJ in both places. A change to either alone fails here.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "pierre/design/number_kind.hpp"
#include "pierre/io/report_template.hpp"

namespace {

using pierre::design::NumberKind;
using pierre::design::number_cell;

const std::filesystem::path kTemplate = PIERRE_SOURCE_DIR "/templates/report.toml";

// The decimals an Excel number format shows for a positive value in its last section ("0.00"
// → 2, "#,##0.0" → 1, "[=0]0;[<0.001]0.00E+00;0.00000" → 5; a mantissa's before "E").
int format_decimals(const std::string& code) {
  const std::string last = code.substr(code.rfind(';') == std::string::npos ? 0 : code.rfind(';') + 1);
  const auto dot = last.find('.');
  if (dot == std::string::npos) return 0;
  const auto end = last.find('E', dot);
  return static_cast<int>((end == std::string::npos ? last.size() : end) - dot - 1);
}

// The decimals of a printed number ("1280.2" → 1, "5.42E-19" → 2, "445" → 0).
int text_decimals(const std::string& text) {
  const auto dot = text.find('.');
  if (dot == std::string::npos) return 0;
  const auto end = text.find('E', dot);
  return static_cast<int>((end == std::string::npos ? text.size() : end) - dot - 1);
}

TEST(NumberKind, TheConsoleRoundsAsTheShippedReportLayout) {
  const auto t = pierre::io::load_report_template(kTemplate);
  // A value of each kind, in the range its format's last section is for.
  const std::pair<NumberKind, double> kinds[] = {
      {NumberKind::count, 445},           {NumberKind::speed, 22.6612},
      {NumberKind::length, 4.28571},      {NumberKind::energy, 1280.2391},
      {NumberKind::small_percent, 0.00217}, {NumberKind::scientific, 5.4e-19},
      {NumberKind::parameter, 0.511432}};
  for (const auto& [kind, v] : kinds) {
    const std::string key(pierre::design::format_key(kind));
    const std::string code = t.get("formats", key);
    EXPECT_EQ(text_decimals(number_cell(v, kind)), format_decimals(code))
        << key << ": the console prints " << number_cell(v, kind) << ", the report's format is "
        << code;
  }
  // Scientific where the layout switches to it (0.00E+00), in both.
  EXPECT_EQ(number_cell(5.4e-19, NumberKind::scientific), "5.40E-19");
  EXPECT_EQ(number_cell(3e-6, NumberKind::small_percent), "3.00E-06");
  EXPECT_EQ(number_cell(0.00217, NumberKind::small_percent), "0.00217");
  // Three digits at least (a new user read 1.29e-05 % as "0.00001"), switching where the
  // report's format does: its "[<t]" section.
  EXPECT_EQ(number_cell(1.29e-5, NumberKind::small_percent), "1.29E-05");
  EXPECT_EQ(number_cell(0.000999, NumberKind::small_percent), "9.99E-04");
  const std::string code = t.get("formats", "small_percent");
  const auto lt = code.find("[<");
  ASSERT_NE(lt, std::string::npos) << code;
  const double switch_at = std::stod(code.substr(lt + 2, code.find(']', lt) - lt - 2));
  EXPECT_NE(number_cell(std::nextafter(switch_at, 0.0), NumberKind::small_percent).find('E'),
            std::string::npos);
  EXPECT_EQ(number_cell(switch_at, NumberKind::small_percent).find('E'), std::string::npos);
}

TEST(NumberKind, ACheckLineIsRoundedByItsUnit) {
  using pierre::design::check_number_kind;
  EXPECT_EQ(check_number_kind("kJ", 1571.9), NumberKind::energy);
  EXPECT_EQ(check_number_kind("m", 5.29), NumberKind::length);
  EXPECT_EQ(check_number_kind("m/s", 26.3), NumberKind::speed);
  EXPECT_EQ(check_number_kind("%", 5.71), NumberKind::length);  // two decimals
  EXPECT_EQ(check_number_kind("%", 0.00217), NumberKind::small_percent);
  EXPECT_EQ(check_number_kind("%", 0.0), NumberKind::length);
  EXPECT_EQ(check_number_kind("", 445), NumberKind::count);  // crossings reached
  EXPECT_EQ(check_number_kind("", 0.05), NumberKind::parameter);  // a significance level
  EXPECT_EQ(check_number_kind("", 2.7e-9), NumberKind::scientific);  // a KS p-value
  // A p-value just under the switch keeps four decimals in the console: 0.0010, not 0.00.
  EXPECT_EQ(number_cell(0.001, check_number_kind("", 0.001)), "0.0010");
}

TEST(NumberKind, NotANumberAndAnOpenEndAreWordsAlignedInTheirColumn) {
  EXPECT_EQ(number_cell(std::numeric_limits<double>::quiet_NaN(), NumberKind::energy, 6), "     -");
  EXPECT_EQ(number_cell(std::numeric_limits<double>::infinity(), NumberKind::length, 7), " beyond");
  EXPECT_EQ(number_cell(1280.2391, NumberKind::energy, 9), "   1280.2");
}

}  // namespace
