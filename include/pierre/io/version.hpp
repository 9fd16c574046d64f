// The program's version and the commit it was built from, for the record of a result: two
// builds of one version differ, and a firm regenerating reports must tell which made which.
#pragma once

#include <string>
#include <string_view>

namespace pierre::io {

std::string_view version();   // the project's version, e.g. "0.1.0"
std::string_view build_id();  // `git describe` of the source built ("…-dirty": with changes), or "unknown"
std::string version_text();   // "0.1.0 (build 7623e12…)", as --version and the report show it

}  // namespace pierre::io
