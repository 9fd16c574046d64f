// The document control of a design report: what a signed report carries besides its content
// ([scenario] reference, revision, prepared_by, checked_by; each optional, empty when not given).
// Shown on the report's Summary and every printed page's header, and in summary.json.
#pragma once

#include <string>

namespace pierre::io {

struct DocumentControl {
  std::string reference;    // the project's or document's number, as the firm writes it
  std::string revision;     // "A", "2", ...
  std::string prepared_by;
  std::string checked_by;
};

}  // namespace pierre::io
