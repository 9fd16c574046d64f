#include "pierre/io/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <fstream>
#include <system_error>

namespace pierre::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStagingPrefix = ".pierre-partial-";
// Longer than any result's name (trajectories.csv, report.xlsx, ...), with room to spare.
constexpr const char* kLongestResultName = "a-result-file-name-of-32-chars.x";

// An exclusive flock(2) on a folder, held while the object lives. Runs writing into one DIR
// take DIR's for their set-up (the sweep below, making their staging folder) and their commit,
// so two runs' commits cannot interleave: the last one's files are there as a set. Best effort:
// where the file system has no flock (some network file systems), it goes on without.
class FolderLock {
 public:
  explicit FolderLock(const fs::path& folder, bool wait = true) noexcept
      : fd_(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (fd_ < 0) return;
    int r;
    do r = ::flock(fd_, LOCK_EX | (wait ? 0 : LOCK_NB));
    while (r != 0 && errno == EINTR && wait);
    locked_ = r == 0;
  }
  ~FolderLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  bool locked() const { return locked_; }
  int fd() const { return fd_; }
  int release() {  // the descriptor, still locked, for the caller to close
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_;
  bool locked_ = false;
};

// The staging folders of runs that ended without taking them away (kill -9, out of memory,
// power loss): a live run holds a lock on its own (whatever its process id or PID namespace),
// so a staging folder whose lock can be taken is abandoned. Where locks cannot be taken at
// all, nothing is removed.
void remove_abandoned_staging(const fs::path& dir) noexcept {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(kStagingPrefix, 0) != 0) continue;
    std::error_code st;
    if (!it->is_directory(st) || st) continue;
    const FolderLock probe(it->path(), false);
    if (probe.locked()) {
      std::error_code rm;
      fs::remove_all(it->path(), rm);
    }
  }
}

// Writes a file's data to the disk, so that a power loss after the rename cannot leave an
// empty or truncated file under a result's name.
void sync_file(const fs::path& file) noexcept {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

OutputFolder::OutputFolder(fs::path dir) : dir_(std::move(dir)) {
  if (!fs::exists(dir_)) {
    // The topmost folder this creates, so that a failure can take them all away again.
    for (fs::path p = dir_; !p.empty() && !fs::exists(p); p = p.parent_path()) {
      created_top_ = p;
      if (p == p.parent_path()) break;
    }
    fs::create_directories(dir_);
  } else if (!fs::is_directory(dir_)) {
    throw fs::filesystem_error("the output path exists and is not a folder", dir_,
                               std::make_error_code(std::errc::not_a_directory));
  }
  try {
    // The longest path a run uses is a result moved aside at commit (staging/.previous/name):
    // refused now if the system could not open it, not after the whole simulation.
    const fs::path longest =
        dir_ / (std::string(kStagingPrefix) + "XXXXXX") / ".previous" / kLongestResultName;
    if (longest.native().size() >= PATH_MAX)
      throw fs::filesystem_error("the output path is too long for the files a run writes in it",
                                 dir_, std::make_error_code(std::errc::filename_too_long));
    const FolderLock lock(dir_);
    remove_abandoned_staging(dir_);
    // A name of its own (not the process id: runs in other PID namespaces share those).
    std::string name = (dir_ / (std::string(kStagingPrefix) + "XXXXXX")).native();
    if (!::mkdtemp(name.data()))
      throw fs::filesystem_error("cannot make a staging folder in the output folder", dir_,
                                 std::error_code(errno, std::generic_category()));
    staging_ = name;
    FolderLock mine(staging_, false);  // held until the run commits or discards
    staging_lock_ = mine.release();
  } catch (...) {
    discard();  // the folders created above, if any, go again
    throw;
  }
}

OutputFolder::~OutputFolder() {
  if (!done_) discard();
}

namespace {
// Whether the first line of `file` is one of `headers` (a CR before the LF ignored).
bool starts_with_header(const fs::path& file, const std::vector<std::string>& headers) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!in || !std::getline(in, line)) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return std::find(headers.begin(), headers.end(), line) != headers.end();
}
}  // namespace

std::vector<fs::path> OutputFolder::commit(const std::vector<StaleResult>& stale) {
  std::vector<fs::path> names;
  for (const auto& e : fs::directory_iterator(staging_))
    if (e.is_regular_file()) names.push_back(e.path().filename());
  std::sort(names.begin(), names.end());
  for (const auto& n : names) sync_file(staging_ / n);  // before the lock: it can take a while
  // One commit in DIR at a time: two runs into one folder leave the last one's set, not a mix.
  const FolderLock lock(dir_);
  // Every file of DIR this commit replaces or removes: first checked, then moved aside into the
  // staging folder, so that the new files go in together or, when one cannot, the old ones all
  // come back (a report held open by another program must not leave half a run behind).
  std::vector<fs::path> old;
  for (const auto& n : names) old.push_back(n);
  kept_.clear();
  for (const auto& s : stale) {
    if (std::find(names.begin(), names.end(), fs::path(s.name)) != names.end()) continue;
    std::error_code ec;
    const auto st = fs::symlink_status(dir_ / s.name, ec);
    if (ec || !fs::exists(st)) continue;
    if (fs::is_regular_file(st) && starts_with_header(dir_ / s.name, s.headers))
      old.push_back(s.name);
    else
      kept_.push_back(dir_ / s.name);
  }
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
  if (lock.fd() >= 0) ::fsync(lock.fd());  // the renames themselves
  std::vector<fs::path> out;
  for (const auto& n : names) out.push_back(dir_ / n);
  std::error_code ec;
  fs::remove_all(staging_, ec);
  release_staging();
  done_ = true;
  return out;
}

CommitError::CommitError(const fs::path& file, const std::string& why)
    : std::runtime_error(file.string() + ": " + why +
                         "; the output folder is left as it was before this run"),
      file_(file) {}

namespace {
// The result's place in DIR for a file of a staging folder; any other path as it is.
fs::path shown_in_dir(const fs::path& staged) {
  const std::string folder = staged.parent_path().filename().string();
  if (folder.rfind(kStagingPrefix, 0) != 0) return staged;
  return staged.parent_path().parent_path() / staged.filename();
}
}  // namespace

OutputWriteError::OutputWriteError(const fs::path& staged, const std::string& why)
    : std::runtime_error("cannot write " + shown_in_dir(staged).string() + ": " + why +
                         "; no result was replaced, the output folder is left as it was before "
                         "this run") {}

void OutputFolder::discard() noexcept {
  done_ = true;
  std::error_code ec;
  if (!staging_.empty()) fs::remove_all(staging_, ec);
  release_staging();
  if (created_top_.empty()) return;
  // The folders this run created, from DIR up, each only while empty (another run may have
  // begun in one): under DIR's lock, so that none is taken from under a run setting up in it.
  const FolderLock lock(dir_);
  for (fs::path p = dir_;; p = p.parent_path()) {
    if (!fs::remove(p, ec) || p == created_top_ || p == p.parent_path()) break;
  }
}

void OutputFolder::release_staging() noexcept {
  if (staging_lock_ >= 0) ::close(staging_lock_);
  staging_lock_ = -1;
}

}  // namespace pierre::io
