// Numbers written into check reasons and report texts: printf's %.<n>g, which does not follow
// the global locale (an ostringstream would write "1,5" in a program that set one).
#pragma once

#include <cstdio>
#include <string>

namespace pierre::design {

inline std::string number_text(double v, int significant = 4) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  return buf;
}

// The same with a fixed number of decimals (%.<n>f): for values a table prints so, e.g. /H.
inline std::string fixed_text(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

}  // namespace pierre::design
