// Rule-set helpers: data-quality questions, factor resolution, energy-class selection,
// residual height category, the `rule` column of a check line.
#include "pierre/design/barrier_rules.hpp"

#include <algorithm>
#include <cmath>

#include "pierre/design/number_text.hpp"

namespace pierre::design {
namespace {

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

}  // namespace

std::string to_string(Governing g) {
  switch (g) {
    case Governing::weibull: return "weibull";
    case Governing::empirical: return "empirical";
    case Governing::larger: return "larger";
  }
  return "weibull";
}

std::string to_string(DesignOn d) {
  switch (d) {
    case DesignOn::mel: return "MEL";
    case DesignOn::sel: return "SEL";
    case DesignOn::both: return "both";
  }
  return "both";
}

std::map<std::string, std::vector<std::string>> data_quality_questions(const BarrierRuleSet& r) {
  std::map<std::string, std::vector<std::string>> q;
  for (const FactorDefinition* f : {&r.gamma_F, &r.gamma_M, &r.gamma_h})
    for (const FactorPart& p : f->parts) {
      if (p.choice.empty()) continue;
      auto& answers = q[p.choice];
      for (const auto& [answer, value] : p.options) {
        bool seen = false;
        for (const auto& a : answers) seen = seen || a == answer;
        if (!seen) answers.push_back(answer);
      }
    }
  return q;
}

stats::Outcome<ResolvedFactor> resolve_factor(const FactorDefinition& f,
                                              const std::map<std::string, std::string>& answers) {
  using Out = stats::Outcome<ResolvedFactor>;
  ResolvedFactor r;
  if (f.value) {
    r.value = *f.value;
    r.how = f.symbol + " = " + number_text(*f.value) + " (given" +
            (f.source.empty() ? std::string() : ": " + f.source) + ")";
    return Out::success(r);
  }
  if (f.parts.empty()) return Out::failure(f.symbol + " has neither a value nor parts");
  std::vector<std::string> symbols, values, chosen;
  double product = 1;
  for (const FactorPart& p : f.parts) {
    double v = 0;
    if (p.choice.empty()) {
      if (!p.value) return Out::failure(p.symbol + " has neither a value nor a choice");
      v = *p.value;
    } else {
      const auto a = answers.find(p.choice);
      std::vector<std::string> opts;
      for (const auto& [k, x] : p.options) opts.push_back("\"" + k + "\"");
      if (a == answers.end())
        return Out::failure(p.symbol + " needs the data-quality answer " + p.choice + " (" +
                            join(opts, " or ") + ")");
      const auto o = p.options.find(a->second);
      if (o == p.options.end())
        return Out::failure(p.symbol + ": " + p.choice + " = \"" + a->second +
                            "\" is not one of " + join(opts, ", "));
      v = o->second;
      chosen.push_back(p.choice + " = " + a->second);
    }
    product *= v;
    symbols.push_back(p.symbol);
    values.push_back(number_text(v));
  }
  r.value = product;
  r.how = f.symbol + " = " + join(symbols, " · ") + " = " + join(values, " × ") + " = " +
          number_text(product);
  if (!chosen.empty()) r.how += " (" + join(chosen, ", ") + ")";
  // Where each value comes from: the factor's own citation, else its parts'.
  std::vector<std::string> cited;
  if (!f.source.empty()) cited.push_back(f.source);
  for (const FactorPart& p : f.parts)
    if (f.source.empty() && !p.source.empty() &&
        std::find(cited.begin(), cited.end(), p.source) == cited.end())
      cited.push_back(p.symbol + ": " + p.source);
  if (!cited.empty()) r.how += "; " + join(cited, "; ");
  return Out::success(r);
}

std::optional<EnergyClass> select_energy_class(const EnergyClassTable& t, DesignOn on,
                                               double mel_req_kJ, double sel_req_kJ) {
  for (const EnergyClass& c : t.classes) {
    if (c.open_ended) return c;  // every requirement above the closed classes lands here
    const bool mel_ok = !needs_mel(on) || (std::isfinite(c.mel_kJ) && c.mel_kJ >= mel_req_kJ);
    const bool sel_ok = !needs_sel(on) || (std::isfinite(c.sel_kJ) && c.sel_kJ >= sel_req_kJ);
    if (mel_ok && sel_ok) return c;
  }
  return std::nullopt;
}

const EnergyClass* find_energy_class(const EnergyClassTable& t, int number) {
  for (const EnergyClass& c : t.classes)
    if (c.number == number) return &c;
  return nullptr;
}

std::string residual_height_category(const ResidualHeightCategories& c, double residual,
                                     double nominal) {
  if (!(nominal > 0)) return "";
  const double share = residual / nominal;
  if (share >= c.a_min) return "A";
  if (share > c.b_min) return "B";
  return "C";
}

std::string rule_reference(const BarrierRuleSet& r, const std::string& check_id) {
  const auto it = r.clauses.find(check_id);
  if (it == r.clauses.end() || it->second.empty()) return r.name;
  return r.name + " " + it->second;
}

}  // namespace pierre::design
