// Helpers for the io tests: a fresh temporary folder per test, files written into it, and the
// base scenario whose lines the error tests replace one at a time.
#pragma once

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace pierre::test {

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("pierre-io-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto p = path_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

 private:
  std::filesystem::path path_;
};

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The base scenario; comments give the line numbers the tests rely on.
inline std::vector<std::string> base_lines() {
  return {
      "[scenario]",                                                                       // 1
      "name = \"t\"",                                                                     // 2
      "",                                                                                 // 3
      "[simulation]",                                                                     // 4
      "seed = 1",                                                                         // 5
      "throws = 2",                                                                       // 6
      "",                                                                                 // 7
      "[profile]",                                                                        // 8
      "points = [[0.0, 10.0, \"rock\"], [10.0, 0.0, \"rock\"], [20.0, 0.0, \"\"]]",         // 9
      "",                                                                                 // 10
      "[materials.rock]",                                                                 // 11
      "normal_energy = 5.0",                                                              // 12
      "tangential_energy = 50.0",                                                         // 13
      "roughness = 0.5",                                                                  // 14
      "",                                                                                 // 15
      "[blocks]",                                                                         // 16
      "[[blocks.table]]",                                                                 // 17
      "mass = 100.0",                                                                     // 18
      "",                                                                                 // 19
      "[[sources]]",                                                                      // 20
      "x = 1.0",                                                                          // 21
      "z = 11.0",                                                                         // 22
      "",                                                                                 // 23
      "[[observation_lines]]",                                                            // 24
      "name = \"L\"",                                                                     // 25
      "x = 15.0",                                                                         // 26
  };
}

// The base scenario with each line n (1-based) replaced by its text (which may hold several
// lines).
inline std::string base_with(const std::vector<std::pair<int, std::string>>& changes) {
  auto lines = base_lines();
  for (const auto& [n, text] : changes) lines.at(static_cast<std::size_t>(n - 1)) = text;
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}
inline std::string base_with(int n, const std::string& text) { return base_with({{n, text}}); }

inline std::string base() { return base_with(3, ""); }

}  // namespace pierre::test
