// report.xlsx: the entry point, and the workbook as a whole (properties, the sheets in the
// template's order). The sheets themselves are in xlsx_report_*.cpp (xlsx_report_writer.hpp).
#include "pierre/io/xlsx_report.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "pierre/io/output_folder.hpp"
#include "xlsx_parts_check.hpp"
#include "xlsx_report_writer.hpp"

namespace pierre::io {
namespace detail {

std::chrono::year_month_day parse_date(const std::string& s) {
  int y = 0;
  unsigned m = 0, d = 0;
  char dash1 = 0, dash2 = 0;
  if (s.size() >= 10 &&
      std::sscanf(s.substr(0, 10).c_str(), "%4d%c%2u%c%2u", &y, &dash1, &m, &dash2, &d) == 5 &&
      dash1 == '-' && dash2 == '-') {
    const std::chrono::year_month_day ymd{std::chrono::year{y}, std::chrono::month{m},
                                          std::chrono::day{d}};
    if (ymd.ok() && y >= 1900 && y <= 9999) return ymd;
  }
  throw std::runtime_error(fmt::format(
      "report.xlsx: the run's date \"{}\" is not an ISO date (YYYY-MM-DD); it fixes the "
      "workbook's creation time",
      s));
}

// ---- the whole workbook ----------------------------------------------------------------

// The document's properties, with a fixed creation time (the run's date at 00:00 UTC) for
// reproducible bytes. libxlsxwriter takes a creation time of 0 for "now": 1970-01-01 (a
// SOURCE_DATE_EPOCH below 86400) is written one second later, still that date and fixed.
void Report::properties() {
  const auto ymd = parse_date(d_.date);
  const auto created = std::chrono::sys_days(ymd).time_since_epoch();
  lxw_doc_properties props{};
  const std::string title = d_.scenario ? d_.scenario->scenario.name : std::string("pierre");
  const std::string comments =
      fmt::format("pierre {}, seed {}", d_.pierre_version, d_.seed);
  props.title = const_cast<char*>(title.c_str());
  props.subject = const_cast<char*>(t_.get("titles", "summary").c_str());
  props.author = const_cast<char*>("pierre");
  props.comments = const_cast<char*>(comments.c_str());
  props.created = std::max<time_t>(
      1, static_cast<time_t>(std::chrono::duration_cast<std::chrono::seconds>(created).count()));
  check(workbook_set_properties(wb_, &props), "workbook_set_properties");
}

void Report::write() {
  properties();
  // Create the sheets in the template's order (the tab order), then fill them.
  std::vector<std::string> used;
  auto add = [&](const std::string& name) {
    const lxw_error e = workbook_validate_sheet_name(wb_, name.c_str());
    if (e != LXW_NO_ERROR) fail(fmt::format("sheet name \"{}\"", name), e);
    used.push_back(lower(name));
    return check_ptr(workbook_add_worksheet(wb_, name.c_str()), "workbook_add_worksheet");
  };
  for (const char* k : {"summary", "inputs", "blocks", "profile", "trajectories", "crossings"})
    used.push_back(lower(t_.get("sheets", k)));
  used.push_back("history");  // reserved by Excel, which refuses a workbook with such a sheet
  std::vector<std::string> barrier_names, quarry_names;
  for (const auto& b : d_.barriers)
    barrier_names.push_back(item_sheet_name("barrier", b.spec.name, used));
  if (d_.quarry)
    for (const auto& row : d_.quarry->rows)
      quarry_names.push_back(item_sheet_name("quarry", row.name, used));
  used.clear();
  std::map<std::string, lxw_worksheet*> sheets;
  std::vector<lxw_worksheet*> barrier_sheets, quarry_sheets;
  for (const auto& key : t_.order) {
    if (key == "barriers") {
      for (const auto& n : barrier_names) barrier_sheets.push_back(add(n));
    } else if (key == "quarries") {
      for (const auto& n : quarry_names) quarry_sheets.push_back(add(n));
    } else {
      sheets[key] = add(t_.get("sheets", key));
    }
  }
  summary(sheets.at("summary"));
  for (std::size_t i = 0; i < d_.barriers.size(); ++i)
    barrier(barrier_sheets[i], barrier_names[i], d_.barriers[i]);
  for (std::size_t i = 0; i < quarry_sheets.size(); ++i)
    quarry(quarry_sheets[i], quarry_names[i], i);
  profile(sheets.at("profile"), t_.get("sheets", "profile"));
  inputs(sheets.at("inputs"));
  blocks(sheets.at("blocks"));
  trajectories(sheets.at("trajectories"));
  crossings(sheets.at("crossings"));
  worksheet_activate(sheets.at("summary"));
}

}  // namespace detail

namespace fs = std::filesystem;
using detail::parse_date;

void write_report(const std::filesystem::path& file, const ReportData& data,
                  const ReportTemplate& tpl) {
  parse_date(data.date);  // before anything is written
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  const fs::path tmp =
      dir / fmt::format(".{}.partial-{}", file.filename().string(), static_cast<long>(::getpid()));
  std::error_code ec;
  fs::remove(tmp, ec);

  lxw_workbook_options options{};
  options.constant_memory = LXW_FALSE;  // charts need the cells to fill their caches
  options.tmpdir = nullptr;
  options.use_zip64 = LXW_FALSE;
  const std::string tmp_name = tmp.string();
  lxw_workbook* wb = workbook_new_opt(tmp_name.c_str(), &options);
  if (!wb) throw std::runtime_error("report.xlsx: workbook_new failed (out of memory)");
  try {
    detail::Report(wb, data, tpl).write();
  } catch (...) {
    lxw_workbook_free(wb);
    fs::remove(tmp, ec);
    throw;
  }
  errno = 0;
  const lxw_error e = workbook_close(wb);  // writes the file and frees the workbook
  if (e != LXW_NO_ERROR) {
    // libxlsxwriter's own text for a failed write is "Zip generic error ZIP_ERRNO": the
    // system's reason (a full disk, a file size limit) beside it says more.
    std::string why = lxw_strerror(e);
    if (!why.empty() && why.back() == '.') why.pop_back();
    if (errno != 0) why += fmt::format(" ({})", std::strerror(errno));
    fs::remove(tmp, ec);
    throw OutputWriteError(file, why);
  }
  if (const auto part = detail::first_incomplete_part(tmp)) {
    fs::remove(tmp, ec);
    throw OutputWriteError(file, "its part " + *part +
                                     " came out cut short (a full disk, here or in the temporary "
                                     "folder, or a file size limit)");
  }
  fs::rename(tmp, file, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(tmp, ec);
    throw OutputWriteError(file, why);
  }
}

}  // namespace pierre::io
