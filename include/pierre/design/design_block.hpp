// The block a barrier is designed for, and the free-board diameter D_f (design-checks.md §1
// steps 3 and 5): given in the scenario, or resolved from the blocks thrown. It needs no
// simulation, so `validate` can say what `run` will use.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pierre/model/block.hpp"
#include "pierre/stats/outcome.hpp"

namespace pierre::design {

// The design block: given, or a rule over the blocks thrown.
struct DesignBlock {
  enum class Kind { given, largest, percentile } kind = Kind::largest;
  double volume = 0;    // m³ (given)
  double density = 0;   // kg/m³ (given; else the block's own)
  double percentile = 95;  // of the block volumes (Kind::percentile)
};

// Every block thrown, one entry each (the same index in the four lists).
struct BlocksThrown {
  std::vector<double> volumes;    // m³
  std::vector<double> densities;  // kg/m³
  std::vector<double> diameters;  // m, equivalent sphere
  std::vector<double> masses;     // kg, as given (volume × density may differ by a rounding)
};

// The lists of a scenario's blocks (sim::Scenario::blocks): each block once, whatever the throws.
BlocksThrown blocks_thrown(const std::vector<model::Block>& blocks);

struct DesignBlockValues {
  double volume = 0;               // m³
  double density = 0;              // kg/m³
  double free_board_diameter = 0;  // D_f, m
  // Where each came from, in words (the report's "resolved: …").
  std::string volume_how, density_how, free_board_diameter_how;
  double mass() const { return volume * density; }  // kg
};

// Fails when a rule needs the blocks thrown and there are none.
stats::Outcome<DesignBlockValues> resolve_design_block(
    const DesignBlock& block, std::optional<double> free_board_diameter,
    const BlocksThrown& thrown);

}  // namespace pierre::design
