// The files a scenario's loading read, for the record of what produced a result: a pipeline
// that regenerates reports sees from summary.json which inputs changed (a block table edited,
// a rule set updated), and can check each against `sha256sum`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace pierre::io {

struct InputFile {
  std::filesystem::path file;  // as the scenario or the command line named it
  std::string sha256;          // of its bytes, 64 lower-case hex digits
  std::uintmax_t bytes = 0;
};

// While one is alive on a thread, every input file read on that thread (detail::read_text) is
// recorded in it, once per path, in reading order. One scenario's loading holds one.
class InputFilesRecord {
 public:
  InputFilesRecord();
  ~InputFilesRecord();
  InputFilesRecord(const InputFilesRecord&) = delete;
  InputFilesRecord& operator=(const InputFilesRecord&) = delete;

  std::vector<InputFile> take() { return std::move(files_); }
  // Called by detail::read_text with what it read.
  static void note(const std::filesystem::path& file, const std::string& text);

 private:
  std::vector<InputFile> files_;
  InputFilesRecord* outer_;
};

// SHA-256 of `bytes`, in hex (nettle).
std::string sha256_hex(const std::string& bytes);

// The record of `file`, read as `text`: its hash and size.
InputFile input_file(const std::filesystem::path& file, const std::string& text);

}  // namespace pierre::io
