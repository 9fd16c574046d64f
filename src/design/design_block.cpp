#include "pierre/design/design_block.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "pierre/design/number_text.hpp"
#include "pierre/stats/percentile.hpp"

namespace pierre::design {

namespace {

std::string volume_how(const DesignBlock& b) {
  switch (b.kind) {
    case DesignBlock::Kind::given:
      return "the design block, given";
    case DesignBlock::Kind::largest:
      return "the largest block thrown, by mass";
    case DesignBlock::Kind::percentile:
      break;
  }
  // Appended to a string made here: "P" + … trips GCC 12's -Wrestrict (a false positive).
  std::string out("P");
  out.append(number_text(b.percentile)).append(" of the volumes of the blocks thrown");
  return out;
}

}  // namespace

BlocksThrown blocks_thrown(const std::vector<model::Block>& blocks) {
  BlocksThrown out;
  for (const model::Block& b : blocks) {
    out.volumes.push_back(b.volume());
    out.densities.push_back(b.density);
    out.diameters.push_back(b.diameter());
    out.masses.push_back(b.mass);
  }
  return out;
}

stats::Outcome<DesignBlockValues> resolve_design_block(
    const DesignBlock& b, std::optional<double> free_board_diameter, const BlocksThrown& thrown) {
  using Result = stats::Outcome<DesignBlockValues>;
  DesignBlockValues v;
  switch (b.kind) {
    case DesignBlock::Kind::given:
      v.volume = b.volume;
      v.density = b.density;
      break;
    case DesignBlock::Kind::largest:
    case DesignBlock::Kind::percentile: {
      if (thrown.volumes.empty() || thrown.densities.size() != thrown.volumes.size() ||
          thrown.masses.size() != thrown.volumes.size())
        return Result::failure("no block list for the design block rule");
      if (b.kind == DesignBlock::Kind::largest) {
        // By mass, as E_d = ½ m_d v_d² goes: of blocks of different densities the largest by
        // volume can be the lighter (3 m³ at 2000 kg/m³ against 2.5 m³ at 3000). With a density
        // given (the library's; the reader gives none with "largest"), mass goes with volume. Of
        // equal masses, the first.
        auto mass = [&](std::size_t i) {
          return b.density > 0 ? thrown.volumes[i] : thrown.masses[i];
        };
        std::size_t k = 0;
        for (std::size_t i = 1; i < thrown.volumes.size(); ++i)
          if (mass(i) > mass(k)) k = i;
        v.volume = thrown.volumes[k];
        v.density = thrown.densities[k];
      } else {
        v.volume = stats::percentile(thrown.volumes, b.percentile);
        v.density = std::accumulate(thrown.densities.begin(), thrown.densities.end(), 0.0) /
                    static_cast<double>(thrown.densities.size());
      }
      if (b.density > 0) v.density = b.density;
      break;
    }
  }
  v.volume_how = volume_how(b);
  v.density_how = b.density > 0 ? "given with the design block"
                  : b.kind == DesignBlock::Kind::largest ? "the heaviest block's"
                                                         : "the mean of the blocks'";
  if (free_board_diameter) {
    v.free_board_diameter = *free_board_diameter;
    v.free_board_diameter_how = "given";
  } else if (!thrown.diameters.empty()) {
    v.free_board_diameter =
        std::accumulate(thrown.diameters.begin(), thrown.diameters.end(), 0.0) /
        static_cast<double>(thrown.diameters.size());
    v.free_board_diameter_how = "the mean equivalent diameter of the blocks thrown";
  } else {
    return Result::failure(
        "no free_board_diameter and no block list to take the mean diameter from");
  }
  return Result::success(std::move(v));
}

}  // namespace pierre::design
