// Uniform indices for one bootstrap resample, the same on every platform and compiler.
//
// Random bits: Random123's Philox4x32-10 (counter-based; integer arithmetic only), keyed by
// the 64-bit seed (key = {seed low 32 bits, seed high 32 bits}), with the counter
//   {draw pair, attempt, resample low 32 bits, resample high 32 bits}:
// one Philox block gives two 64-bit words, (w0 << 32 | w1) and (w2 << 32 | w3), for draws
// 2i and 2i + 1 of the resample. No std:: distribution is used (their output is
// implementation-defined: library-notes.md).
//
// Word to index in [0, n): Lemire's multiply-shift with rejection (Lemire 2019, "Fast random
// integer generation in an interval"): index = high 64 bits of word · n, rejected when the
// low 64 bits fall below 2^64 mod n; that makes every index exactly equally likely. A
// rejected draw (probability < n / 2^64) is redrawn from the block with attempt + 1, same
// lane. The 128-bit product is written out in 32-bit halves (no compiler extension).
//
// Limits: at most 2^33 draws per resample (the draw pair is 32 bits). Attempt 2^32 - 1 is
// reserved for the order-statistic bootstrap (bootstrap.hpp).
#pragma once

#include <Random123/philox.h>

#include <cstdint>

namespace pierre::stats {

class ResampleIndexStream {
 public:
  static constexpr std::uint32_t kReservedAttempt = 0xffffffffu;

  ResampleIndexStream(std::uint64_t seed, std::uint64_t resample);

  // The next index in [0, n); n >= 1.
  std::uint64_t next(std::uint64_t n);

  // The 128 bits of block `pair` at `attempt` of this resample, for other uses of the stream.
  r123::Philox4x32::ctr_type block(std::uint32_t pair, std::uint32_t attempt) const;
  // Word `lane` (0 or 1) of a block: (w0 << 32 | w1) or (w2 << 32 | w3).
  static std::uint64_t word(const r123::Philox4x32::ctr_type& b, int lane) {
    return lane == 0 ? (std::uint64_t{b[0]} << 32) | b[1] : (std::uint64_t{b[2]} << 32) | b[3];
  }
  // The most values a resample can draw from: the draw pair is 32 bits, two draws a block.
  static constexpr std::uint64_t kMaxValues = std::uint64_t{1} << 33;

 private:
  r123::Philox4x32::key_type key_;
  std::uint32_t resample_lo_;
  std::uint32_t resample_hi_;
  std::uint32_t pair_ = 0;  // next block to compute
  int lane_ = 2;            // word of the current block to use next; 2 = need a new block
  r123::Philox4x32::ctr_type current_{};
};

// 52 random bits to a double in the open interval (0, 1): ((w >> 12) + 0.5) / 2^52, so
// between 2^-53 and 1 - 2^-53, both exact. (Random123's u01 on 64 bits can return exactly
// 1.0 — library-notes.md — and so does (w >> 11) + 0.5 over 2^53: 2^53 - 0.5 is not a
// double and rounds up to 2^53.)
inline double open_unit_interval(std::uint64_t w) {
  return (static_cast<double>(w >> 12) + 0.5) * 0x1.0p-52;
}

}  // namespace pierre::stats
