// A barrier design rule set (design-checks.md §1, "Rule sets to ship"): plain data read by io
// from rules/<name>.toml. The code knows the procedure; every number lives in the file, with
// its source, so an engineer can add a code (e.g. ONR 24810) without recompiling.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pierre/design/bootstrap_size.hpp"
#include "pierre/stats/outcome.hpp"

namespace pierre::design {

enum class Governing { weibull, empirical, larger };  // which characteristic value is used
enum class DesignOn { mel, sel, both };               // which capacity the barrier must meet

std::string to_string(Governing g);  // "weibull", "empirical", "larger"
std::string to_string(DesignOn d);   // "MEL", "SEL", "both"
inline bool needs_mel(DesignOn d) { return d != DesignOn::sel; }
inline bool needs_sel(DesignOn d) { return d != DesignOn::mel; }

// A partial factor: a number, or the product of parts each chosen by a data-quality answer
// (e.g. γF = γTr · γDp with γTr = 1.02 for back-analysed trajectories, 1.10 from literature).
struct FactorPart {
  std::string symbol;  // "γTr"
  std::string choice;  // the data-quality question it depends on: "trajectory"; empty: fixed
  std::map<std::string, double> options;  // answer -> value: {"back-analysed": 1.02, ...}
  std::optional<double> value;            // a part that depends on no answer (γγ = 1.0)
  std::string source;
};
struct FactorDefinition {
  std::string symbol;  // "γF"
  std::optional<double> value;   // given directly ...
  std::vector<FactorPart> parts;  // ... or the product of these
  std::string source;
};
// A factor resolved for one barrier's data-quality answers, with how it was obtained.
struct ResolvedFactor {
  double value = 1;
  std::string how;  // "γF = γTr · γDp = 1.02 × 1.02 (trajectory = back-analysed, topography = high)"
};

struct EnergyClass {
  int number = 0;
  double sel_kJ = 0;  // NaN where the table gives none (class 0)
  double mel_kJ = 0;
  // The last class of ETAG 027 ("> 4500 kJ"): its numbers are lower bounds and a barrier of
  // this class must declare its own MEL and SEL.
  bool open_ended = false;
};
// Residual height categories (ETAG 027): the residual height after the MEL test as a share of
// the nominal height; A when >= a_min, B when > b_min (and below a_min), else C (<= b_min).
struct ResidualHeightCategories {
  double a_min = 0.5, b_min = 0.3;
  std::string source;
};
struct EnergyClassTable {
  std::string name, title, source;
  std::string file;  // where it was read from (empty when made in code); for the record
  std::vector<EnergyClass> classes;  // ascending; the last is open-ended ("> 4500 kJ")
  std::optional<ResidualHeightCategories> residual_height;
};

// The rule set of a barrier that names none (rules/peila-ronco-2009.toml).
inline constexpr const char* kDefaultBarrierRules = "peila-ronco-2009";

struct BarrierRuleSet {
  std::string name;    // file stem, e.g. "thesis-2015"
  std::string title;   // human title
  std::string source;  // citation
  std::string file;    // where it was read from (empty when made in code); for the record
  double percentile = 95;  // p of the characteristic values
  Governing governing = Governing::weibull;
  DesignOn design_on = DesignOn::both;
  FactorDefinition gamma_F, gamma_M, gamma_h;  // velocity, mass, height factors
  double gamma_E_MEL = 1, gamma_E_SEL = 1;     // required capacity = γE · E_d
  double free_board_abs = 0;  // m
  double free_board_rel = 0;  // × D_f
  std::optional<double> gamma_d_MEL, gamma_d_SEL;  // elongation factors (absent: not applicable)
  double sample_tolerance = 0.05;  // CI half-width / value above which sample.size WARNs
  // The bootstrap of step 8 (design-checks.md §1): a 90 % interval from 1000 resamples at
  // least; a rule set may ask for more, not for less.
  double sample_confidence = kMinBootstrapConfidence;
  std::size_t sample_resamples = kMinBootstrapResamples;
  double fit_p_value = 0.05;       // KS p-value below which fit.* WARNs
  double min_crossings = 30;       // crossings below which reach WARNs
  std::string classes = "etag027-classes";  // energy class table (rules/<name>.toml)
  std::map<std::string, std::string> clauses;  // check id -> clause text for the `rule` column
  std::map<std::string, std::string> sources;  // factor key (gamma_E_MEL, …) -> its citation
};

// The data-quality questions a rule set asks (choice -> its answers), from every factor part
// that depends on one.
std::map<std::string, std::vector<std::string>> data_quality_questions(const BarrierRuleSet& r);

// Resolves a factor for the given answers. Fails (with the reason) when an answer is missing
// or not one of the part's options.
stats::Outcome<ResolvedFactor> resolve_factor(const FactorDefinition& f,
                                              const std::map<std::string, std::string>& answers);

// The smallest class meeting every required capacity that `on` names (>=). An open-ended
// class meets any requirement at or above its bounds. None when nothing meets them (a table
// without an open-ended class).
std::optional<EnergyClass> select_energy_class(const EnergyClassTable& t, DesignOn on,
                                               double mel_req_kJ, double sel_req_kJ);
const EnergyClass* find_energy_class(const EnergyClassTable& t, int number);

// "A", "B" or "C" for residual / nominal height.
std::string residual_height_category(const ResidualHeightCategories& c, double residual,
                                     double nominal);

// "<rule set> <clause>" for a check id (the rule set's name alone when it has no clause).
std::string rule_reference(const BarrierRuleSet& r, const std::string& check_id);

}  // namespace pierre::design
