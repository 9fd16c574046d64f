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

// The names that begin with `found` (letter case, '_', '-' and spaces ignored; `found` of 4
// characters or more): "freeboard" for free_board_diameter, "elongation" for elongation_mel and
// elongation_sel. A name the edits above do not reach, as it is much longer.
std::vector<std::string> names_beginning_with(std::string_view found,
                                              const std::vector<std::string>& names);

// "; the nearest is observation_lines", else the names beginning so ("; the nearest is
// free_board_diameter", "; the nearest are elongation_mel or elongation_sel", up to three), or
// "" when there is neither.
std::string nearest_name_hint(std::string_view found, const std::vector<std::string>& names);

}  // namespace pierre::io::detail
