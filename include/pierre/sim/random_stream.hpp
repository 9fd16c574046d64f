// Per-trajectory random numbers: a counter-based Philox2x64-10 stream keyed by the seed, with
// the global trajectory index in the counter (model-2d.md §6). A trajectory's draws do not
// depend on the thread that runs it, on the run order, or on how the work is split.
// Philox2x64 rather than 4x32: the same 128 bits per call from 64-bit multiplies, about half
// the instructions on x86-64 (measured with callgrind).
//
// The rounds are Random123's Philox2x64-10 written out (tests/unit/sim/random_stream_test.cpp
// checks every bit against r123::Philox2x64), with the key schedule computed once per seed:
// the seed is the same for every draw of a run, so the nine key bumps of each call were
// repeated work.
#pragma once

#include <array>
#include <cstdint>

#include "pierre/model/impact_law.hpp"

namespace pierre::sim {

__extension__ typedef unsigned __int128 PhiloxProduct;  // 64 × 64 → 128-bit multiply (GCC, Clang)

// The round keys of Philox2x64-10 for one seed: key + r·W for r = 0..9 (Random123's bumpkey).
struct PhiloxKey {
  static constexpr int rounds = 10;
  static constexpr std::uint64_t multiplier = 0xD2B74407B1CE6E93ull;  // PHILOX_M2x64_0
  static constexpr std::uint64_t weyl = 0x9E3779B97F4A7C15ull;        // PHILOX_W64_0

  explicit PhiloxKey(std::uint64_t seed) {
    for (int r = 0; r < rounds; ++r) round[r] = seed + static_cast<std::uint64_t>(r) * weyl;
  }
  std::array<std::uint64_t, rounds> round;
};

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t trajectory)
      : RandomStream(PhiloxKey(seed), trajectory) {}
  RandomStream(const PhiloxKey& key, std::uint64_t trajectory)
      : key_(key), ctr0_(0), ctr1_(trajectory) {}

  // The draws of the next impact: one Philox block of 128 bits gives two 52-bit uniforms
  // in the open interval (0, 1) (Random123's u01 on 64 bits can return 1.0: library-notes.md)
  // and one spare bit for the travel sign on level ground.
  model::ImpactDraws impact_draws() {
    std::uint64_t w0, w1;
    next(w0, w1);
    model::ImpactDraws d;
    d.roughness_u = to_open_unit(w0);
    d.shape_u = to_open_unit(w1);
    d.level_sign = (w0 & 1u) != 0;  // bit 0 is below the 52 bits used by roughness_u
    return d;
  }

  std::uint64_t draws_used() const { return ctr0_; }

  // (k + 0.5) / 2^52 with k the top 52 bits: strictly inside (0, 1). (With 53 bits the top
  // value 2^53 − 0.5 is not a double and rounds to 1.0.) k < 2^52 converts exactly through a
  // signed integer, which is one instruction where the unsigned conversion is a branchy few.
  static double to_open_unit(std::uint64_t w) {
    return (static_cast<double>(static_cast<std::int64_t>(w >> 12)) + 0.5) * 0x1.0p-52;
  }

  // Philox2x64-10 of the counter {c0, c1}: out = {hi ^ key ^ c1, lo} of M·c0, ten times.
  static void philox(const PhiloxKey& key, std::uint64_t c0, std::uint64_t c1,
                     std::uint64_t& out0, std::uint64_t& out1) {
    for (int r = 0; r < PhiloxKey::rounds; ++r) {
      const PhiloxProduct prod = static_cast<PhiloxProduct>(PhiloxKey::multiplier) * c0;
      const auto hi = static_cast<std::uint64_t>(prod >> 64);
      const auto lo = static_cast<std::uint64_t>(prod);
      c0 = hi ^ key.round[r] ^ c1;
      c1 = lo;
    }
    out0 = c0;
    out1 = c1;
  }

 private:
  void next(std::uint64_t& w0, std::uint64_t& w1) {
    philox(key_, ctr0_, ctr1_, w0, w1);
    ++ctr0_;
  }
  PhiloxKey key_;
  std::uint64_t ctr0_;  // draw number within the trajectory
  std::uint64_t ctr1_;  // global trajectory index
};

}  // namespace pierre::sim
