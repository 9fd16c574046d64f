#include "pierre/io/number_kind.hpp"

#include <cmath>

#include <fmt/format.h>

namespace pierre::io {

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

std::string number_cell(double v, NumberKind kind, int width) {
  if (std::isnan(v)) return fmt::format("{:>{}}", "-", width);
  if (std::isinf(v)) return fmt::format("{:>{}}", v > 0 ? "beyond" : "-inf", width);
  // The decimals of the shipped layout's formats (a test holds them together): "#,##0" count,
  // "0.00" speed and length, "#,##0.0" energy, "0.0000" parameter, "0.00E+00" scientific,
  // "0.00000" small_percent (scientific below 0.00001 %).
  switch (kind) {
    case NumberKind::count: return fmt::format("{:>{}.0f}", v, width);
    case NumberKind::speed:
    case NumberKind::length: return fmt::format("{:>{}.2f}", v, width);
    case NumberKind::energy: return fmt::format("{:>{}.1f}", v, width);
    case NumberKind::small_percent:
      if (v != 0 && std::abs(v) < 1e-5) return fmt::format("{:>{}.2E}", v, width);
      return fmt::format("{:>{}.5f}", v, width);
    case NumberKind::scientific: return fmt::format("{:>{}.2E}", v, width);
    case NumberKind::parameter: return fmt::format("{:>{}.4f}", v, width);
  }
  return fmt::format("{:>{}}", v, width);
}

}  // namespace pierre::io
