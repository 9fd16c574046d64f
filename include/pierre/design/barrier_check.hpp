// The barrier procedure at an observation line (design-checks.md §1, thesis §4.7 and
// appendix D): characteristic values from Weibull fits and empirically, design values with
// partial factors, required MEL/SEL, energy class, interception height, exceedance, bootstrap
// confidence, and the check lines. Pure: samples and rules in, a BarrierDesign out.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pierre/design/barrier_rules.hpp"
#include "pierre/design/check_line.hpp"
#include "pierre/design/design_block.hpp"
#include "pierre/stats/bootstrap.hpp"
#include "pierre/stats/kolmogorov_smirnov.hpp"
#include "pierre/stats/lognormal_fit.hpp"
#include "pierre/stats/sample_summary.hpp"
#include "pierre/stats/weibull_fit.hpp"

namespace pierre::design {

struct CandidateBarrier {
  std::optional<int> energy_class;
  std::optional<double> mel_kJ, sel_kJ;   // declared capacities (override the class's)
  std::optional<double> height;           // vertical interception height at the line, m
  std::optional<double> elongation_mel, elongation_sel;  // declared maximum elongations, m
  std::optional<double> distance_to_object;              // m
  std::optional<double> residual_height;                 // m, for the residual height category
};

// Everything a scenario says about one barrier (io parses it from [[barriers]]).
struct BarrierSpec {
  std::string name;
  std::string line;          // observation line name
  std::string rules;         // rule set name
  DesignBlock design_block;
  std::optional<double> free_board_diameter;  // D_f, m; default: mean equivalent diameter thrown
  std::map<std::string, std::string> data_quality;  // e.g. trajectory = "back-analysed"
  std::optional<CandidateBarrier> candidate;        // absent: a design, not a check
  std::optional<double> acceptable_energy_exceedance;  // probability (0..1)
  std::optional<double> acceptable_height_exceedance;
  std::string observed_file;  // optional CSV of observed speeds, heights, energies (echo only)
};

// The sample at the line (design-checks.md §1 step 1): first crossings in the main direction.
struct BarrierSample {
  std::vector<double> speed;               // m/s
  std::vector<double> height;              // m, vertical passing height
  std::vector<double> energy;              // J, translational, each block's own mass
  std::vector<double> rotational_energy;   // J
  std::uint64_t not_reached = 0;           // trajectories that never crossed
  BlocksThrown blocks;                     // every block thrown (design block rule, default D_f)
  std::uint32_t throws = 0;                // per block and source (0: unknown), for sample.size
};

// Observed data at the line (optional; as at Vaujany): any column may be empty.
struct ObservedSample {
  std::vector<double> speed, height, energy;  // m/s, m, J
  std::string file;  // where they came from (echo)
};

struct QuantityFit {  // one quantity's sample statistics and fits
  stats::SampleSummary summary;
  std::optional<stats::WeibullFit> weibull;
  std::optional<stats::KolmogorovSmirnovTest> weibull_ks;
  std::optional<stats::LognormalFit> lognormal;
  std::optional<stats::KolmogorovSmirnovTest> lognormal_ks;
  std::string error;  // why a fit is missing
  // When no Weibull fits because the positive values are all one value, or there are none
  // (every block sliding across the line: all heights 0): the sample is a point mass there,
  // the limit of a Weibull whose shape grows without bound. Its quantiles are that value and
  // P(X > x) is 1 below it, 0 from it on.
  std::optional<double> point_mass;
};

struct Characteristic {  // v_k or h_k
  double weibull = 0, empirical = 0, value = 0;  // value: the governing one
  std::optional<stats::BootstrapInterval> interval;
};

struct ExceedanceRow {  // one column of Table 4.2
  std::string what;        // "P(E > SEL_req)"
  double threshold = 0;    // in the quantity's unit (kJ or m)
  std::string unit;
  double simulated_weibull = 0, simulated_empirical = 0;
  std::optional<double> observed_weibull;
};

struct BarrierDesign {
  BarrierSpec spec;
  std::string rules_title, rules_source;
  // How each design quantity was obtained, in words, for the report (keys as the factors
  // table: v_k, h_k, gamma_E_MEL, gamma_E_SEL, density, volume, free_board_diameter,
  // free_board, h_d, h_i, energy_class); the partial factors carry their own (ResolvedFactor).
  std::map<std::string, std::string> how;
  double chainage = 0;  // m
  std::uint64_t crossings = 0, not_reached = 0;
  QuantityFit speed, height, energy;  // energy in kJ
  stats::SampleSummary rotational_energy;  // kJ
  Characteristic v_k, h_k;
  ResolvedFactor gamma_F, gamma_M, gamma_h;
  double gamma_E_MEL = 1, gamma_E_SEL = 1;
  // The elongation factors the elongation check uses (the rule set's, for the tests it designs
  // on); absent: that check is not applicable.
  std::optional<double> gamma_d_MEL, gamma_d_SEL;
  double design_volume = 0, design_density = 0;  // m³, kg/m³
  double v_d = 0, m_d = 0, E_d_kJ = 0;            // m/s, kg, kJ
  double MEL_req_kJ = 0, SEL_req_kJ = 0;
  std::optional<EnergyClass> energy_class;  // smallest meeting design_on; none: above the table
  double free_board_diameter = 0, free_board = 0, h_d = 0, h_i = 0;  // m
  std::optional<stats::BootstrapInterval> E_d_interval, h_i_interval;
  std::vector<ExceedanceRow> exceedance;
  std::vector<CheckLine> checks;

  // Added with the procedure (design-checks.md §1):
  std::string rules_name;                    // the rule set's name (file stem)
  DesignOn design_on = DesignOn::both;       // the rule set's: the other capacity is information
  std::string rules_file;                    // where the rule set was read from
  std::string classes_name, classes_title, classes_file;  // the energy class table used
  std::optional<QuantityFit> observed_speed, observed_height, observed_energy;  // energy kJ
  double h_max_sim = 0;                      // m, largest simulated passing height
  double candidate_mel_kJ = 0, candidate_sel_kJ = 0;  // NaN when not declared / no candidate
  std::string residual_height_category;      // "A", "B", "C"; empty when not declared
  std::uint64_t bootstrap_seed = 0;          // the bootstrap's own stream
  std::uint32_t throws = 0;                  // per block and source of the run (0: unknown)
  std::vector<std::string> notes;            // what an engineer should know (fits missing, ...)
};

// ---- the procedure's parts, each usable (and tested) on its own ----

// Steps 3–6: the design arithmetic from the characteristic values, separate from the fitting.
struct DesignInputs {
  double v_k = 0;      // m/s
  double h_k = 0;      // m
  double volume = 0;   // m³, design block
  double density = 0;  // kg/m³
  double free_board_diameter = 0;  // D_f, m
  std::map<std::string, std::string> data_quality;
};
struct DesignValues {
  ResolvedFactor gamma_F, gamma_M, gamma_h;
  double gamma_E_MEL = 1, gamma_E_SEL = 1;
  double v_d = 0, m_d = 0, E_d_kJ = 0;  // m/s, kg, kJ
  double MEL_req_kJ = 0, SEL_req_kJ = 0;
  std::optional<EnergyClass> energy_class;
  double free_board = 0, h_d = 0, h_i = 0;  // m
};
// Steps 5 and 6 from a characteristic value: E_d = ½ m_d (v_k γF)² in kJ, h_i = h_k γh + f. The
// design values and every bootstrap replicate of v_k and h_k go through these, so that the
// intervals bracket the values they are reported with.
double design_energy_kJ(double v_k, double gamma_F, double m_d);
double interception_height(double h_k, double gamma_h, double free_board);
// Fails only when a factor cannot be resolved (a data-quality answer missing or unknown).
stats::Outcome<DesignValues> design_values(const BarrierRuleSet& rules,
                                           const EnergyClassTable& classes,
                                           const DesignInputs& in);

// Step 2: one quantity's Weibull and log-normal ML fits with their KS tests (the Stephens
// p-value is the one checked), and its summary.
QuantityFit fit_quantity(std::span<const double> sample);
// v_k or h_k at percentile p (0..100): Weibull quantile and type-7 empirical percentile;
// `value` per `governing` (NaN when the governing fit is missing).
Characteristic characteristic_value(const QuantityFit& fit, std::span<const double> sample,
                                    double p, Governing governing);

// Step 7: P(E > SEL_req), P(E > MEL_req), P(h > h_i), P(h > h_max,sim) from the simulated
// Weibull fits (NaN without a fit), the empirical fractions of the simulated sample, and the
// observed Weibull fits when given. S(x) = exp(-(x/λ)^k).
struct ExceedanceInputs {
  double SEL_req_kJ = 0, MEL_req_kJ = 0, h_i = 0, h_max_sim = 0;
  std::optional<stats::WeibullFit> simulated_energy, simulated_height;  // kJ, m
  std::optional<double> simulated_energy_point, simulated_height_point;  // QuantityFit::point_mass
  std::span<const double> simulated_energy_kJ, simulated_height_m;
  std::optional<stats::WeibullFit> observed_energy, observed_height;    // kJ, m
};
std::vector<ExceedanceRow> exceedance_rows(const ExceedanceInputs& in);
// P(X > x) from q's Weibull fit, or its point mass (QuantityFit::point_mass); NaN without
// either. x in q's unit (kJ, m).
double weibull_exceedance(const QuantityFit& q, double x);

// The check lines of a computed design (the table of design-checks.md §1). With a candidate:
// energy.mel, energy.sel, height.interception, elongation, exceedance.energy,
// exceedance.height and the advisory lines; without one (a design) only the advisory lines
// fit.v, fit.h, fit.E, sample.size, reach.
std::vector<CheckLine> barrier_check_lines(const BarrierDesign& d, const BarrierRuleSet& rules);

// The bootstrap's own stream for barrier `index` (0-based, scenario order) of a run with
// `scenario_seed`: scenario_seed ^ 0x4241525249455253 ("BARRIERS") ^ index. Inside
// design_barrier the speed and the height resamples use splitmix64 of that seed ^ 1 and ^ 2.
std::uint64_t barrier_bootstrap_seed(std::uint64_t scenario_seed, std::size_t index);

// Runs the procedure (steps 1–8). `seed` keys the bootstrap's own stream
// (barrier_bootstrap_seed). Fails (with the reason) only
// when the data cannot give a design at all, e.g. no crossing at the line.
struct BarrierOutcome {
  std::optional<BarrierDesign> design;
  std::string error;
  // Without a design, the check line that says so in its place: "reach" (a WARN) when fewer
  // than two blocks crossed the line, "design" (a FAIL) when the crossings gave no design (e.g.
  // no fit of identical values, a design value out of the rule set's tables).
  std::string check_line = "design";
};
// threads: the bootstraps of step 8 (most of the time) share their resamples out over this
// many threads; the results are the same for any count (each resample has its own stream).
BarrierOutcome design_barrier(const BarrierSpec& spec, const BarrierRuleSet& rules,
                              const EnergyClassTable& classes, const BarrierSample& sample,
                              const std::optional<ObservedSample>& observed, double chainage,
                              std::uint64_t seed, unsigned threads = 1);

}  // namespace pierre::design
