#include "pierre/design/number_kind.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace pierre::design {

std::string_view format_key(NumberKind kind) {
  switch (kind) {
    case NumberKind::count: return "count";
    case NumberKind::speed: return "speed";
    case NumberKind::length: return "length";
    case NumberKind::energy: return "energy";
    case NumberKind::small_percent: return "small_percent";
    case NumberKind::scientific: return "scientific";
    case NumberKind::parameter: return "parameter";
  }
  return "parameter";
}

NumberKind check_number_kind(std::string_view unit, double v) {
  if (unit == "kJ") return NumberKind::energy;
  if (unit == "m") return NumberKind::length;
  if (unit == "m/s") return NumberKind::speed;
  if (unit == "%")  // two decimals; more for a small probability of exceedance (0.00217 %)
    return std::isfinite(v) && v != 0 && std::abs(v) < 0.1 ? NumberKind::small_percent
                                                           : NumberKind::length;
  if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e15) return NumberKind::count;
  if (std::isfinite(v) && v != 0 && std::abs(v) < 1e-3) return NumberKind::scientific;
  return NumberKind::parameter;
}

namespace {

// s with spaces before it to make `width` characters (bytes: the texts here are ASCII).
std::string right_aligned(std::string s, int width) {
  const auto n = static_cast<std::size_t>(std::max(width, 0));
  return s.size() < n ? std::string(n - s.size(), ' ') + s : s;
}

// text + " " + unit (append: GCC 12's -Wrestrict misreads " " + std::string under -Werror).
std::string with_unit(std::string text, std::string_view unit) {
  if (!unit.empty()) text.append(" ").append(unit);
  return text;
}

// printf's %.<decimals>f or %.<decimals>E (not the global locale's, as number_text), padded on
// the left to `width`.
std::string printed(double v, int decimals, bool scientific, int width) {
  char buf[64];
  std::snprintf(buf, sizeof buf, scientific ? "%.*E" : "%.*f", decimals, v);
  return right_aligned(buf, width);
}

}  // namespace

// The decimals of the shipped layout's formats (a test holds them together): "#,##0" count,
// "0.00" speed and length, "#,##0.0" energy, "0.0000" parameter, "0.00E+00" scientific (of the
// mantissa), "0.00000" small_percent (scientific below 0.001 %, where five decimals would keep
// fewer than three digits: 1.29e-05 % printed as 0.00001).
int decimals_of(NumberKind kind) {
  switch (kind) {
    case NumberKind::count: return 0;
    case NumberKind::energy: return 1;
    case NumberKind::speed:
    case NumberKind::length:
    case NumberKind::scientific: return 2;
    case NumberKind::parameter: return 4;
    case NumberKind::small_percent: return 5;
  }
  return 4;
}

std::string number_cell(double v, NumberKind kind, int width) {
  if (std::isnan(v)) return right_aligned("-", width);
  if (std::isinf(v)) return right_aligned(v > 0 ? "beyond" : "-inf", width);
  const bool scientific = kind == NumberKind::scientific ||
                          (kind == NumberKind::small_percent && v != 0 && std::abs(v) < 1e-3);
  return printed(v, scientific ? 2 : decimals_of(kind), scientific, width);
}

std::string quantity_text(double v, std::string_view unit) {
  return with_unit(number_cell(v, check_number_kind(unit, v)), unit);
}

std::pair<std::string, std::string> compared_texts(double value, double limit,
                                                   std::string_view unit) {
  const NumberKind kind = check_number_kind(unit, value);
  std::string a = number_cell(value, kind), b = number_cell(limit, check_number_kind(unit, limit));
  // Alike in print but not in value: fixed decimals, one more at a time until they differ.
  if (a == b && value != limit && std::isfinite(value) && std::isfinite(limit))
    for (int more = decimals_of(kind) + 1; more <= 12 && a == b; ++more) {
      a = printed(value, more, false, 0);
      b = printed(limit, more, false, 0);
    }
  return {with_unit(std::move(a), unit), with_unit(std::move(b), unit)};
}

}  // namespace pierre::design
