// The barriers of a scenario (design-checks.md §1), computed from a finished run's samples at
// their observation lines. Shared by `pierre run` and `pierre check`.
#pragma once

#include "pierre/design/run_statistics.hpp"
#include "pierre/io/result_writer.hpp"
#include "pierre/io/scenario_reader.hpp"

namespace pierre::app {

// Every barrier's design and check lines, in scenario order. A barrier that cannot be designed
// gets no design and a line that says why: `reach` (fewer than two crossings at its line; WARN,
// advisory as the spec has it) or `design` (crossings that give no design, e.g. no fit; FAIL).
// A candidate without a design also gets a FAIL `candidate` line: `pierre check` must not pass
// a barrier it could not check.
// `threads` (0: every hardware thread) as `--threads`: the barriers' bootstraps share their
// resamples out over them (the same results for any count).
io::DesignResults compute_barriers(const io::LoadedScenario& loaded, const design::RunSamples& samples,
                                   unsigned threads);

}  // namespace pierre::app
