// An input error: where it is (file, line), which field, what was found, what was expected.
// Thrown by the readers; the command line turns it into a message and exit code 2.
#pragma once

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "pierre/design/check_line.hpp"

namespace pierre::io {

class InputError : public std::runtime_error {
 public:
  InputError(std::filesystem::path file, long line, std::string field, std::string found,
             std::string expected);
  const std::filesystem::path& file() const { return file_; }
  long line() const { return line_; }  // 1-based; 0 when the error is about the whole file
  const std::string& field() const { return field_; }
  const std::string& found() const { return found_; }
  const std::string& expected() const { return expected_; }

 private:
  std::filesystem::path file_;
  long line_;
  std::string field_, found_, expected_;
};

// A note on the input: something that does not stop a run but is likely a mistake (an x typed
// out of order read as an overhang, a source far above the ground). Said where it is, like an
// error: "<file>:<line>: <field>: <text>". `run` and `validate` print them.
struct InputNote {
  std::filesystem::path file;
  long line = 0;  // 1-based; 0 when about the whole file
  std::string field;
  std::string text;
  // A likely slip (a unit, a height a.s.l.): the check lines it puts in doubt, whose PASS is
  // then a WARN (design::doubt_passes). None for a note on something that may well be meant.
  std::optional<design::DoubtedInput> doubt;
  std::string message() const;
};

// The notes that doubt their input (a likely slip [confirmed] does not confirm).
inline std::size_t doubted_count(const std::vector<InputNote>& notes) {
  return static_cast<std::size_t>(std::count_if(
      notes.begin(), notes.end(), [](const InputNote& n) { return n.doubt.has_value(); }));
}

// The doubt of a slip that bears on the whole simulation (the blocks, a material, gravity, a
// source's height): every check line.
inline design::DoubtedInput doubts_every_line(std::string field, double value) {
  return {std::move(field), "", {}, value};
}

}  // namespace pierre::io
