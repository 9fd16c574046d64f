// How a number of the results is rounded, the same on the console, in report.xlsx and in the
// reasons of the check lines: each kind is a key of the report layout's [formats]
// (templates/report.toml), and text is written with the decimals of the shipped layout's format
// ("0.00" m/s: 22.66 m/s in all three places). Pure text arithmetic, no I/O.
#pragma once

#include <string>
#include <string_view>
#include <utility>

namespace pierre::design {

enum class NumberKind {
  count,          // a whole number (trajectories, an energy class)
  speed,          // m/s
  length,         // m, and percentages of two decimals
  energy,         // kJ
  small_percent,  // a value in % below 0.1 (a P(E > MEL_req) of 0.00217 %)
  scientific,     // a tiny dimensionless value (a KS p-value of 1e-9)
  parameter,      // fitted parameters, KS statistics, other dimensionless values
};

// The key of the report layout's [formats] table.
std::string_view format_key(NumberKind kind);

// The kind of a check line's value or limit, by its unit and, where the unit leaves it open,
// its size (a dimensionless 12 is a count, 1e-9 is scientific).
NumberKind check_number_kind(std::string_view unit, double v);

// v as the console prints it: the shipped layout's decimals of `kind`, right-aligned in
// `width` ("-" for NaN, "beyond" for +inf: a zone that reaches past the profile's end).
std::string number_cell(double v, NumberKind kind, int width = 0);
// The decimals `kind` is printed with (of the mantissa for scientific).
int decimals_of(NumberKind kind);

// v with its unit ("5.29 m", "1309.9 kJ"), in the decimals of the unit's kind.
std::string quantity_text(double v, std::string_view unit);

// A value and a limit compared in a check line's reason, each with its unit ("5.30 m", "1309.9
// kJ"), in the decimals of the unit's kind, or more where those would print two different
// numbers alike ("1000.00 kJ < 1000.04 kJ", not "1000.0 kJ < 1000.0 kJ").
std::pair<std::string, std::string> compared_texts(double value, double limit, std::string_view unit);

}  // namespace pierre::design
