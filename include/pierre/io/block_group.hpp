// A row of a block table or block CSV, as written (docs/scenario-format.md, [blocks]); shared by
// the scenario reader and the quarry reader.
#pragma once

#include <string>

namespace pierre::io {

struct BlockGroup {
  std::string id;
  double mass = 0;     // kg
  double volume = 0;   // m³
  double density = 0;  // kg/m³
  double shape_min = 1, shape_max = 1;
  unsigned count = 1;
};

}  // namespace pierre::io
