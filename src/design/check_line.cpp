#include "pierre/design/check_line.hpp"

#include <algorithm>

namespace pierre::design {

std::string_view to_string(CheckStatus s) {
  switch (s) {
    case CheckStatus::pass: return "PASS";
    case CheckStatus::fail: return "FAIL";
    case CheckStatus::warn: return "WARN";
    case CheckStatus::not_applicable: return "N/A";
  }
  return "N/A";
}

bool any_failure(const std::vector<CheckLine>& lines) {
  return std::any_of(lines.begin(), lines.end(),
                     [](const CheckLine& l) { return l.status == CheckStatus::fail; });
}

}  // namespace pierre::design
