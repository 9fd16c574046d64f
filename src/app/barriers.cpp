#include "barriers.hpp"

#include "run_steps.hpp"

#include <algorithm>
#include <thread>

namespace pierre::app {

io::DesignResults compute_barriers(const io::LoadedScenario& loaded,
                                   const design::RunSamples& samples, unsigned threads) {
  if (threads == 0) threads = std::thread::hardware_concurrency();
  io::DesignResults out;
  const sim::Scenario& sc = loaded.scenario;
  const std::vector<design::DoubtedInput> doubts = doubted_inputs(loaded.notes);
  for (std::size_t i = 0; i < loaded.barriers.size(); ++i) {
    const design::BarrierSpec& spec = loaded.barriers[i];
    const auto it = std::find_if(sc.lines.begin(), sc.lines.end(),
                                 [&](const sim::ObservationLine& l) { return l.name == spec.line; });
    const auto line = static_cast<std::size_t>(it - sc.lines.begin());  // the reader checked it
    design::BarrierSample s;
    if (line < samples.lines().size()) {
      const design::LineSamples& ls = samples.lines()[line];
      s.speed = ls.speed;
      s.height = ls.height;
      s.energy = ls.translational_energy;
      s.rotational_energy = ls.rotational_energy;
    }
    const std::uint64_t n = samples.trajectories();
    s.not_reached = n >= s.speed.size() ? n - s.speed.size() : 0;
    s.blocks = design::blocks_thrown(sc.blocks);
    s.throws = sc.settings.throws;
    design::BarrierOutcome o = design::design_barrier(
        spec, loaded.barrier_rules[i], loaded.barrier_classes[i], s, loaded.barrier_observed[i],
        it == sc.lines.end() ? 0.0 : it->x,
        design::barrier_bootstrap_seed(sc.settings.seed, i), threads);
    if (o.design) {
      design::doubt_passes(o.design->checks, doubts);
      out.checks.insert(out.checks.end(), o.design->checks.begin(), o.design->checks.end());
      out.barriers.push_back(*o.design);
    } else {
      design::CheckLine l;
      l.subject = spec.name;
      l.id = o.check_line;
      l.rule = design::rule_reference(loaded.barrier_rules[i], l.id);
      if (o.check_line == "reach") {
        // Too few crossings is the advisory `reach` line (design-checks.md §1: "WARN if
        // fewer"), however few: no block to design for is not a failed design.
        l.what = "crossings of the line (first in the main direction)";
        l.value = static_cast<double>(s.speed.size());
        l.limit = loaded.barrier_rules[i].min_crossings;
        l.status = design::CheckStatus::warn;
        l.reason = "no design: " + o.error + (spec.candidate ? "; the candidate is not checked (FAIL)" : "") +
                   ": is the line where the barrier stands?";
      } else {
        l.what = "the barrier's design from the crossings of its line";
        l.status = design::CheckStatus::fail;
        l.reason = "no design: " + o.error;
      }
      const design::BarrierRuleSet& rules = loaded.barrier_rules[i];
      out.barriers_without_design.push_back({spec.name, spec.line, rules.name, rules.title,
                                             rules.source, rules.file,
                                             it == sc.lines.end() ? 0.0 : it->x,
                                             static_cast<std::uint64_t>(s.speed.size()),
                                             o.check_line, o.error});
      out.checks.push_back(std::move(l));
      // A candidate with nothing to be checked against has not passed: `pierre check` must not
      // exit 0 for it, as a pipeline gating on the exit code would take it for checked.
      if (spec.candidate) {
        design::CheckLine c;
        c.subject = spec.name;
        c.id = "candidate";
        c.rule = design::rule_reference(loaded.barrier_rules[i], c.id);
        c.what = "the candidate barrier against the design values of its line";
        c.status = design::CheckStatus::fail;
        c.reason = "not checked: the line gave no design (" + o.error +
                   "); a candidate is never passed unchecked: place the line where the blocks pass, "
                   "or see whether the profile runs from the source end";
        out.checks.push_back(std::move(c));
      }
    }
  }
  return out;
}

}  // namespace pierre::app
