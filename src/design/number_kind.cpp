#include "pierre/design/number_kind.hpp"

#include <cmath>
#include <cstdio>

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

// printf's %.<decimals>f or %.<decimals>E (not the global locale's, as number_text), padded on
// the left to `width`.
std::string printed(double v, int decimals, bool scientific, int width) {
  char buf[64];
  std::snprintf(buf, sizeof buf, scientific ? "%.*E" : "%.*f", decimals, v);
  return right_aligned(buf, width);
}

}  // namespace

std::string right_aligned(std::string s, int width) {
  if (static_cast<int>(s.size()) < width) s.insert(0, static_cast<std::size_t>(width) - s.size(), ' ');
  return s;
}

std::string number_cell(double v, NumberKind kind, int width) {
  if (std::isnan(v)) return right_aligned("-", width);
  if (std::isinf(v)) return right_aligned(v > 0 ? "beyond" : "-inf", width);
  // The decimals of the shipped layout's formats (a test holds them together): "#,##0" count,
  // "0.00" speed and length, "#,##0.0" energy, "0.0000" parameter, "0.00E+00" scientific,
  // "0.00000" small_percent (scientific below 0.00001 %).
  switch (kind) {
    case NumberKind::count: return printed(v, 0, false, width);
    case NumberKind::speed:
    case NumberKind::length: return printed(v, 2, false, width);
    case NumberKind::energy: return printed(v, 1, false, width);
    case NumberKind::small_percent: return printed(v, v != 0 && std::abs(v) < 1e-5 ? 2 : 5, v != 0 && std::abs(v) < 1e-5, width);
    case NumberKind::scientific: return printed(v, 2, true, width);
    case NumberKind::parameter: return printed(v, 4, false, width);
  }
  return printed(v, 4, false, width);
}

std::pair<std::string, std::string> compared_texts(double value, double limit,
                                                   std::string_view unit) {
  auto trimmed = [](std::string s) { return s.substr(s.find_first_not_of(' ')); };
  const NumberKind kv = check_number_kind(unit, value), kl = check_number_kind(unit, limit);
  std::string a = trimmed(number_cell(value, kv)), b = trimmed(number_cell(limit, kl));
  // Alike in print but not in value: fixed decimals, more of them until they differ.
  if (a == b && value != limit && std::isfinite(value) && std::isfinite(limit))
    for (int decimals = 1; decimals <= 9 && a == b; ++decimals) {
      const int more = (kv == NumberKind::energy ? 1 : kv == NumberKind::count ? 0 : 2) + decimals;
      a = printed(value, more, false, 0);
      b = printed(limit, more, false, 0);
    }
  if (!unit.empty() && unit != "%") {
    a += " " + std::string(unit);
    b += " " + std::string(unit);
  } else if (unit == "%") {
    a += " %";
    b += " %";
  }
  return {a, b};
}

}  // namespace pierre::design
