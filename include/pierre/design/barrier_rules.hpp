// A barrier design rule set (design-checks.md §1, "Rule sets to ship"): plain data read by io
// from rules/<name>.toml. The code knows the procedure; every number lives in the file, with
// its source, so an engineer can add a code (e.g. ONR 24810) without recompiling.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pierre::design {

enum class Governing { weibull, empirical, larger };  // which characteristic value is used
enum class DesignOn { mel, sel, both };               // which capacity the barrier must meet

// A partial factor: a number, or the product of parts each chosen by a data-quality answer
// (e.g. γF = γTr · γDp with γTr = 1.02 for back-analysed trajectories, 1.10 from literature).
struct FactorPart {
  std::string symbol;  // "γTr"
  std::string choice;  // the data-quality question it depends on: "trajectory"
  std::map<std::string, double> options;  // answer -> value: {"back-analysed": 1.02, ...}
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
};
struct EnergyClassTable {
  std::string name, source;
  std::vector<EnergyClass> classes;  // ascending; the last is open-ended ("> 4500 kJ")
};

struct BarrierRuleSet {
  std::string name;    // file stem, e.g. "thesis-2015"
  std::string title;   // human title
  std::string source;  // citation
  double percentile = 95;  // p of the characteristic values
  Governing governing = Governing::weibull;
  DesignOn design_on = DesignOn::both;
  FactorDefinition gamma_F, gamma_M, gamma_h;  // velocity, mass, height factors
  double gamma_E_MEL = 1, gamma_E_SEL = 1;     // required capacity = γE · E_d
  double free_board_abs = 0;  // m
  double free_board_rel = 0;  // × D_f
  std::optional<double> gamma_d_MEL, gamma_d_SEL;  // elongation factors (absent: not applicable)
  double sample_tolerance = 0.05;  // CI half-width / value above which sample.size WARNs
  std::string classes = "etag027-classes";  // energy class table (rules/<name>.toml)
  std::map<std::string, std::string> clauses;  // check id -> clause text for the `rule` column
};

}  // namespace pierre::design
