#include "pierre/io/nearest_name.hpp"

#include <algorithm>
#include <cctype>

namespace pierre::io::detail {
namespace {

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

// Optimal string alignment distance (Damerau–Levenshtein without repeated edits of a substring),
// case-insensitive: a swap of two neighbours ("lenght") is one edit, as a typist makes it.
std::size_t edits(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

// Lower case without '_', '-' and spaces: "free board" and "free_board" alike.
std::string folded(std::string_view s) {
  std::string out;
  for (char c : s)
    if (c != '_' && c != '-' && c != ' ') out.push_back(lower(c));
  return out;
}

}  // namespace

std::vector<std::string> names_beginning_with(std::string_view found,
                                              const std::vector<std::string>& names) {
  const std::string f = folded(found);
  std::vector<std::string> out;
  if (f.size() < 4) return out;  // "x", "tan": the start of too many names to mean one
  for (const std::string& name : names) {
    const std::string n = folded(name);
    if (n != f && n.starts_with(f) &&
        std::find(out.begin(), out.end(), name) == out.end())
      out.push_back(name);
  }
  return out;
}

std::string nearest_name(std::string_view found, const std::vector<std::string>& names) {
  if (found.empty() || found.size() > 200) return {};  // a pasted paragraph is no typo
  const std::size_t allowed = found.size() <= 4 ? 1 : found.size() <= 8 ? 2 : 3;
  std::string best;
  std::size_t best_edits = allowed + 1;
  bool tie = false;
  for (const std::string& name : names) {
    if (name == found) return {};
    const std::size_t e = edits(found, name);
    if (e < best_edits) {
      best = name;
      best_edits = e;
      tie = false;
    } else if (e == best_edits && name != best) {
      tie = true;
    }
  }
  return best_edits <= allowed && !tie ? best : std::string();
}

std::string nearest_name_hint(std::string_view found, const std::vector<std::string>& names) {
  if (const std::string n = nearest_name(found, names); !n.empty()) return "; the nearest is " + n;
  const std::vector<std::string> longer = names_beginning_with(found, names);
  if (longer.empty() || longer.size() > 3) return {};
  std::string list = longer.front();
  for (std::size_t i = 1; i < longer.size(); ++i)
    list += (i + 1 == longer.size() ? " or " : ", ") + longer[i];
  return (longer.size() > 1 ? "; the nearest are " : "; the nearest is ") + list;
}

}  // namespace pierre::io::detail
