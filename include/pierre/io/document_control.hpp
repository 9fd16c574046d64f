// The document control of a design report: what a signed report carries besides its content
// ([scenario] reference, revision, prepared_by, checked_by; each optional, empty when not given).
// Shown on the report's Summary and every printed page's header, and in summary.json.
#pragma once

#include <array>
#include <string>
#include <utility>

namespace pierre::io {

struct DocumentControl {
  std::string reference;    // the project's or document's number, as the firm writes it
  std::string revision;     // "A", "2", ...
  std::string prepared_by;
  std::string checked_by;

  // Each field with its key: in [scenario], in summary.json's "scenario" and among the report's
  // labels alike.
  std::array<std::pair<const char*, std::string*>, 4> fields() {
    return {{{"reference", &reference}, {"revision", &revision}, {"prepared_by", &prepared_by},
             {"checked_by", &checked_by}}};
  }
  std::array<std::pair<const char*, const std::string*>, 4> fields() const {
    const auto f = const_cast<DocumentControl*>(this)->fields();
    return {{f[0], f[1], f[2], f[3]}};
  }
};

}  // namespace pierre::io
