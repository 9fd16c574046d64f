#include "pierre/stats/resample_index_stream.hpp"

namespace pierre::stats {
namespace {

// High and low 64 bits of the 128-bit product a · b, from 32-bit halves (portable: no
// __int128, no _umul128).
void multiply_128(std::uint64_t a, std::uint64_t b, std::uint64_t& hi, std::uint64_t& lo) {
  const std::uint64_t a_lo = a & 0xffffffffu, a_hi = a >> 32;
  const std::uint64_t b_lo = b & 0xffffffffu, b_hi = b >> 32;
  const std::uint64_t p0 = a_lo * b_lo, p1 = a_lo * b_hi, p2 = a_hi * b_lo, p3 = a_hi * b_hi;
  const std::uint64_t mid = (p0 >> 32) + (p1 & 0xffffffffu) + (p2 & 0xffffffffu);
  hi = p3 + (p1 >> 32) + (p2 >> 32) + (mid >> 32);
  lo = (mid << 32) | (p0 & 0xffffffffu);
}

}  // namespace

ResampleIndexStream::ResampleIndexStream(std::uint64_t seed, std::uint64_t resample)
    : key_{{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)}},
      resample_lo_(static_cast<std::uint32_t>(resample)),
      resample_hi_(static_cast<std::uint32_t>(resample >> 32)) {}

r123::Philox4x32::ctr_type ResampleIndexStream::block(std::uint32_t pair,
                                                      std::uint32_t attempt) const {
  const r123::Philox4x32::ctr_type ctr{{pair, attempt, resample_lo_, resample_hi_}};
  return r123::Philox4x32()(ctr, key_);
}

std::uint64_t ResampleIndexStream::next(std::uint64_t n) {
  if (lane_ == 2) {
    current_ = block(pair_++, 0);
    lane_ = 0;
  }
  const int lane = lane_++;
  std::uint64_t hi = 0, lo = 0;
  multiply_128(word(current_, lane), n, hi, lo);
  if (lo < n) {                                   // maybe in the biased sliver: Lemire's exact test
    const std::uint64_t threshold = (0 - n) % n;  // 2^64 mod n
    for (std::uint32_t attempt = 1; lo < threshold; ++attempt) {
      multiply_128(word(block(pair_ - 1, attempt), lane), n, hi, lo);
    }
  }
  return hi;
}

}  // namespace pierre::stats
