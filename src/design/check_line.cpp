#include "pierre/design/check_line.hpp"

#include <algorithm>

#include "pierre/design/number_text.hpp"

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

bool any_failure(const std::vector<CheckLine>& lines, bool warn_fails) {
  return std::any_of(lines.begin(), lines.end(), [warn_fails](const CheckLine& l) {
    return l.status == CheckStatus::fail || (warn_fails && l.status == CheckStatus::warn);
  });
}

std::size_t count_status(const std::vector<CheckLine>& lines, CheckStatus status) {
  return static_cast<std::size_t>(std::count_if(
      lines.begin(), lines.end(), [&](const CheckLine& l) { return l.status == status; }));
}

void doubt_passes(std::vector<CheckLine>& lines, const std::vector<DoubtedInput>& doubts) {
  auto bears_on = [](const DoubtedInput& d, const CheckLine& l) {
    if (!d.subject.empty() && d.subject != l.subject) return false;
    if (d.ids.empty()) return l.id != "elongation";
    return std::any_of(d.ids.begin(), d.ids.end(), [&](const std::string& id) {
      return id == l.id || (id.ends_with('.') && l.id.starts_with(id));
    });
  };
  for (CheckLine& l : lines) {
    if (l.status != CheckStatus::pass) continue;
    std::vector<std::string> fields;  // each once, in the notes' order
    for (const DoubtedInput& d : doubts)
      if (bears_on(d, l) && std::find(fields.begin(), fields.end(), d.field) == fields.end())
        fields.push_back(d.field);
    if (fields.empty()) continue;
    std::string said;
    for (const std::string& f : fields) said += (said.empty() ? "" : ", ") + f;
    l.status = CheckStatus::warn;
    l.reason += ", but it rests on " + said +
                ", noted as a likely slip (see the input notes): correct it, or confirm it under "
                "[confirmed], before relying on this line";
  }
}

SampleNeeded sample_needed(double trajectories, std::uint32_t throws, double relative,
                           double tolerance) {
  const double factor = (relative / tolerance) * (relative / tolerance);
  SampleNeeded n;
  n.trajectories = std::ceil(trajectories * factor);
  if (throws > 0) n.throws = std::ceil(static_cast<double>(throws) * factor);
  return n;
}

std::string throws_needed_text(const SampleNeeded& needed) {
  if (!(needed.throws > 0)) return {};
  return ", i.e. throws = " + number_text(needed.throws, 9) +
         " per block and source (an estimate that moves with this run's interval; throws = " +
         number_text(std::ceil(kSampleMargin * needed.throws), 9) + " leaves a margin)";
}

std::string within_interval_text(std::string_view whose, double confidence, const std::string& bound) {
  return "within " + std::string(whose) + " " + number_text(100 * confidence) +
         " % bootstrap interval (" + bound + ")";
}

}  // namespace pierre::design
