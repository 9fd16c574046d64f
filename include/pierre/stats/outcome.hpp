// A value or the reason there is none. The statistics return this instead of throwing when
// the data cannot give an answer (too few values, no spread, a minimiser that did not
// converge): bad data is ordinary in a rockfall run, and the core throws nothing
// (architecture.md). C++20 has no std::expected, hence this small struct.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace pierre::stats {

template <class T>
struct Outcome {
  std::optional<T> value;
  std::string error;  // why `value` is empty; empty when there is a value

  static Outcome success(T v) { return Outcome{std::move(v), {}}; }
  static Outcome failure(std::string why) { return Outcome{std::nullopt, std::move(why)}; }

  bool ok() const { return value.has_value(); }
  explicit operator bool() const { return ok(); }
  const T& operator*() const { return *value; }
  const T* operator->() const { return &*value; }
};

}  // namespace pierre::stats
