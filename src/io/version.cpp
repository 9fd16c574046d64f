#include "pierre/io/version.hpp"

#ifndef PIERRE_VERSION
#define PIERRE_VERSION "unknown"
#endif

namespace pierre::io {

namespace detail {
extern const char kBuildId[];  // generated/build_id.cpp (cmake/build_id.cmake)
}

std::string_view version() { return PIERRE_VERSION; }

std::string_view build_id() { return detail::kBuildId; }

std::string version_text() {
  return std::string(version()) + " (build " + std::string(build_id()) + ")";
}

}  // namespace pierre::io
