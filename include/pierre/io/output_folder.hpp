// Atomic output: a run writes into a staging folder of its own inside the output folder
// (`DIR/.pierre-partial-XXXXXX/`, locked with flock while the run lives) and moves each file
// into DIR only once the run has succeeded (commit). Without a commit — an exception, a failed
// sink — the destructor removes the staging folder, and the folders this object created for
// DIR when they are left empty, so a failed run leaves nothing behind. The staging folders of
// killed runs (no lock on them) are taken away by the next run in the same folder. Runs into
// one DIR at the same time commit one after the other (a lock on DIR): the last one's files
// are there as a set. Files are synced to the disk before they are renamed into place.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pierre::io {

// A commit that could not replace a file of DIR; DIR is as it was before it.
class CommitError : public std::runtime_error {
 public:
  CommitError(const std::filesystem::path& file, const std::string& why);
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
};

// A result that could not be written into the staging folder (a full disk, a file size limit,
// an I/O error). Nothing of DIR was replaced: the message names the result as it would have
// stood in DIR, with the system's reason.
class OutputWriteError : public std::runtime_error {
 public:
  // `staged`: the file being written (in the staging folder, or anywhere else as it is).
  OutputWriteError(const std::filesystem::path& staged, const std::string& why);
};

// A result an earlier run may have left in DIR that this run does not write (impacts.csv
// without --impacts): removed at commit only when its first line is one of `headers`, that is
// when pierre wrote it; a file of the user's by that name is left alone (OutputFolder::kept).
struct StaleResult {
  std::string name;
  std::vector<std::string> headers;
};

class OutputFolder {
 public:
  // Creates DIR (and its parents) when missing, then the staging folder. Throws
  // std::filesystem::filesystem_error when DIR cannot be created, is not a folder, cannot be
  // written in, or is too long a path for the files of a run.
  explicit OutputFolder(std::filesystem::path dir);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::filesystem::path& dir() const { return dir_; }
  const std::filesystem::path& staging() const { return staging_; }
  std::filesystem::path staged(std::string_view name) const { return staging_ / name; }

  // Moves every staged file into DIR (replacing files of the same name), removes the files of
  // DIR named in `stale` that this run did not produce and an earlier run of pierre did (by
  // their first line), removes the staging folder. Returns the final paths, sorted by name. All
  // or nothing: when a file cannot be replaced (held open, not a file), DIR is put back as it
  // was and CommitError names the file.
  std::vector<std::filesystem::path> commit(const std::vector<StaleResult>& stale = {});
  // After commit: the files of DIR by a stale result's name that were left as they are, their
  // first line not being pierre's.
  const std::vector<std::filesystem::path>& kept() const { return kept_; }
  // Removes the staging folder (and DIR when created here and empty); never throws.
  void discard() noexcept;

 private:
  void release_staging() noexcept;

  std::filesystem::path dir_, staging_;
  std::vector<std::filesystem::path> kept_;
  std::filesystem::path created_top_;  // the topmost folder created for DIR; empty: none
  int staging_lock_ = -1;              // the staging folder, flock'ed while the run lives
  bool done_ = false;
};

}  // namespace pierre::io
