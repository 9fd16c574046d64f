// The name a misspelt one was most likely meant to be: a key typed [[observation_line]] for
// [[observation_lines]], a material "asphalt" for the [materials.asfalt] table. Said after the
// list of valid names in an input error, so that the fix is read, not searched for.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pierre::io::detail {

// The one name of `names` within a few edits of `found` (insertions, deletions, substitutions
// and swaps of neighbours, letter case ignored): at most 1 for a name of up to 4 characters, 2
// up to 8, 3 beyond. Empty when none is that close, when two are equally close, or when `found`
// is itself a name.
std::string nearest_name(std::string_view found, const std::vector<std::string>& names);

// "; the nearest is observation_lines", or "" when there is no nearest name.
std::string nearest_name_hint(std::string_view found, const std::vector<std::string>& names);

}  // namespace pierre::io::detail
