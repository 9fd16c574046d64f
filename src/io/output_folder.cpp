#include "pierre/io/output_folder.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cerrno>
#include <system_error>

namespace pierre::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStagingPrefix = ".pierre-partial-";
// Longer than any result's name (trajectories.csv, report.xlsx, ...), with room to spare.
constexpr const char* kLongestResultName = "a-result-file-name-of-32-chars.x";

// The staging folders of runs that were killed (kill -9, out of memory, power loss) before they
// could take them away: their process is gone. A run still going in the same folder keeps its.
void remove_abandoned_staging(const fs::path& dir) noexcept {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(kStagingPrefix, 0) != 0) continue;
    const std::string id = name.substr(std::string_view(kStagingPrefix).size());
    if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos || id.size() > 9)
      continue;
    const auto pid = static_cast<pid_t>(std::stol(id));
    if (::kill(pid, 0) == -1 && errno == ESRCH) {
      std::error_code rm;
      fs::remove_all(it->path(), rm);
    }
  }
}

}  // namespace

OutputFolder::OutputFolder(fs::path dir) : dir_(std::move(dir)) {
  if (!fs::exists(dir_)) {
    // Remember the topmost folder we create, so that a failure can take it away again.
    fs::create_directories(dir_);
    created_dir_ = true;
  } else if (!fs::is_directory(dir_)) {
    throw fs::filesystem_error("the output path exists and is not a folder", dir_,
                               std::make_error_code(std::errc::not_a_directory));
  }
  try {
    remove_abandoned_staging(dir_);
    staging_ = dir_ / (kStagingPrefix + std::to_string(::getpid()));
    // The longest path a run uses is a result moved aside at commit (staging/.previous/name):
    // refused now if the system could not open it, not after the whole simulation.
    if ((staging_ / ".previous" / kLongestResultName).native().size() >= PATH_MAX)
      throw fs::filesystem_error("the output path is too long for the files a run writes in it",
                                 dir_, std::make_error_code(std::errc::filename_too_long));
    fs::remove_all(staging_);  // a left-over of a killed run with the same process id
    fs::create_directory(staging_);
  } catch (...) {
    discard();  // the folder created above, if any, goes again
    throw;
  }
}

OutputFolder::~OutputFolder() {
  if (!done_) discard();
}

std::vector<fs::path> OutputFolder::commit(const std::vector<std::string>& stale) {
  std::vector<fs::path> names;
  for (const auto& e : fs::directory_iterator(staging_))
    if (e.is_regular_file()) names.push_back(e.path().filename());
  std::sort(names.begin(), names.end());
  // Every file of DIR this commit replaces or removes: first checked, then moved aside into the
  // staging folder, so that the new files go in together or, when one cannot, the old ones all
  // come back (a report held open by another program must not leave half a run behind).
  std::vector<fs::path> old;
  for (const auto& n : names) old.push_back(n);
  for (const auto& s : stale)
    if (std::find(names.begin(), names.end(), fs::path(s)) == names.end()) old.push_back(s);
  std::vector<fs::path> present;
  for (const auto& n : old) {
    std::error_code ec;
    const auto st = fs::symlink_status(dir_ / n, ec);
    if (ec || !fs::exists(st)) continue;
    if (!fs::is_regular_file(st))
      throw CommitError(dir_ / n, "it is not a file (a folder or a link by a result's name)");
    present.push_back(n);
  }
  const fs::path aside = staging_ / ".previous";
  fs::create_directory(aside);
  std::vector<fs::path> moved, installed;
  auto roll_back = [&]() noexcept {
    std::error_code ec;
    for (const auto& n : installed) fs::rename(dir_ / n, staging_ / n, ec);
    for (const auto& n : moved) fs::rename(aside / n, dir_ / n, ec);
  };
  auto step = [&](const fs::path& from, const fs::path& to, const fs::path& file) {
    std::error_code ec;
    fs::rename(from, to, ec);
    if (!ec) return;
    roll_back();
    throw CommitError(file, ec.message() + " (is it open in another program?)");
  };
  for (const auto& n : present) {
    step(dir_ / n, aside / n, dir_ / n);
    moved.push_back(n);
  }
  for (const auto& n : names) {
    step(staging_ / n, dir_ / n, dir_ / n);
    installed.push_back(n);
  }
  std::vector<fs::path> out;
  for (const auto& n : names) out.push_back(dir_ / n);
  std::error_code ec;
  fs::remove_all(staging_, ec);
  done_ = true;
  return out;
}

CommitError::CommitError(const fs::path& file, const std::string& why)
    : std::runtime_error(file.string() + ": " + why +
                         "; the output folder is left as it was before this run"),
      file_(file) {}

void OutputFolder::discard() noexcept {
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (created_dir_ && fs::is_empty(dir_, ec) && !ec) fs::remove(dir_, ec);
  done_ = true;
}

}  // namespace pierre::io
