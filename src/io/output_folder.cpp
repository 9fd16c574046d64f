#include "pierre/io/output_folder.hpp"

#include <unistd.h>

#include <algorithm>
#include <system_error>

namespace pierre::io {

namespace fs = std::filesystem;

OutputFolder::OutputFolder(fs::path dir) : dir_(std::move(dir)) {
  if (!fs::exists(dir_)) {
    // Remember the topmost folder we create, so that a failure can take it away again.
    fs::create_directories(dir_);
    created_dir_ = true;
  } else if (!fs::is_directory(dir_)) {
    throw fs::filesystem_error("the output path exists and is not a folder", dir_,
                               std::make_error_code(std::errc::not_a_directory));
  }
  staging_ = dir_ / (".pierre-partial-" + std::to_string(::getpid()));
  fs::remove_all(staging_);  // a left-over of a killed run with the same process id
  fs::create_directory(staging_);
}

OutputFolder::~OutputFolder() {
  if (!done_) discard();
}

std::vector<fs::path> OutputFolder::commit(const std::vector<std::string>& stale) {
  std::vector<fs::path> names;
  for (const auto& e : fs::directory_iterator(staging_))
    if (e.is_regular_file()) names.push_back(e.path().filename());
  std::sort(names.begin(), names.end());
  std::vector<fs::path> out;
  for (const auto& n : names) {
    fs::rename(staging_ / n, dir_ / n);
    out.push_back(dir_ / n);
  }
  for (const auto& s : stale)
    if (std::find(names.begin(), names.end(), fs::path(s)) == names.end()) {
      std::error_code ec;
      fs::remove(dir_ / s, ec);
    }
  fs::remove_all(staging_);
  done_ = true;
  return out;
}

void OutputFolder::discard() noexcept {
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (created_dir_ && fs::is_empty(dir_, ec) && !ec) fs::remove(dir_, ec);
  done_ = true;
}

}  // namespace pierre::io
