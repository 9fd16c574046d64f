// The programs some tests open a workbook with (unzip, LibreOffice's soffice). Without one a
// test is skipped on a developer's machine, but fails under CI ($CI set): there the workbook
// must be opened for real, and a skip would pass unseen (ctest counts it as passed).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace pierre::test {

inline bool have(const char* program) {
  return std::system(("command -v " + std::string(program) + " >/dev/null 2>&1").c_str()) == 0;
}

}  // namespace pierre::test

// In a test body: skip (or, under CI, fail) unless `program` is installed.
#define PIERRE_NEED_PROGRAM(program)                                                         \
  do {                                                                                       \
    if (!::pierre::test::have(program)) {                                                    \
      if (std::getenv("CI"))                                                                 \
        FAIL() << program << " is not installed, and CI must open the workbook for real "    \
                             "(bash tools/bootstrap test installs it)";                      \
      GTEST_SKIP() << program << " not installed (bash tools/bootstrap test installs it)";   \
    }                                                                                        \
  } while (0)
