// The layout of report.xlsx, read from templates/report.toml (the format is described in that
// file): sheet names and order, headings with units, number formats, titles and labels, chart
// titles and axis labels, colours of PASS / FAIL / WARN, page set-up and the row caps of the
// data sheets. Data, so that a firm restyles its report without recompiling.
//
// Every key the writer uses must have a value and every unknown key is an error:
// load_report_template throws InputError (file, line of the table or the value, the dotted
// field, what was found and what was expected). A key the file leaves out takes the value of
// the layout built into the program (templates/report.toml as it was at build time), so that a
// firm's restyled copy keeps working when a later version adds keys; those keys are listed in
// ReportTemplate::built_in_keys for the program to say so. A key an earlier layout had and this
// one dropped is accepted and ignored (ReportTemplate::retired_keys).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "pierre/io/input_error.hpp"
#include "pierre/io/input_files.hpp"

namespace pierre::io {

struct ReportTemplate {
  std::filesystem::path file;  // where it was read from
  InputFile source;            // the same, with its SHA-256 and size, for summary.json's inputs
  // The dotted keys (or whole tables) the file left out, taken from the built-in layout.
  std::vector<std::string> built_in_keys;
  // The dotted keys the file holds that an earlier layout had and this one no longer uses:
  // read and ignored, so that an older copy keeps working.
  std::vector<std::string> retired_keys;

  // Text by section and key: "sheets", "titles", "labels", "formats", "headings.<table>",
  // "chart.<chart>" (keys title, x_axis, y_axis). Every key of report_template_sections().
  std::map<std::string, std::map<std::string, std::string, std::less<>>, std::less<>> text;
  // Colours (0xRRGGBB) by key of the [colours] table.
  std::map<std::string, std::uint32_t, std::less<>> colours;

  // Sheet order by key: summary, barriers, quarries, profile, inputs, trajectories, crossings
  // (each once).
  std::vector<std::string> order;

  std::size_t trajectory_rows = 10000;  // cap of the Trajectories sheet
  std::size_t crossing_rows = 10000;    // cap of the Crossings sheet
  std::size_t print_rows = 200;         // data rows of those sheets in the print area

  bool landscape = true;
  int paper = 9;  // Excel paper code (9: A4)

  int histogram_bins = 30;
  int curve_points = 120;
  double profile_line_height = 10;  // m
  int chart_width = 620, chart_height = 330;  // px

  // The text of `section`.`key`; throws std::out_of_range naming both when absent (only a
  // template built or edited in code can lack one).
  const std::string& get(std::string_view section, std::string_view key) const;
  std::uint32_t colour(std::string_view key) const;
};

// The required keys of every text section (the schema the loader checks), by section name.
const std::map<std::string, std::vector<std::string>, std::less<>>& report_template_sections();
// The keys of [colours].
const std::vector<std::string>& report_template_colours();

// True for a sheet name that a formula would read as something else unless quoted: a cell
// reference (A1, xfd12, R1C1, R, C5) or a name starting with a digit or a point (2024, 1.5).
// libxlsxwriter 1.1 quotes only names holding other characters than letters, digits, _ and .,
// so chart ranges and print areas on such a sheet ("B1!$A$1") make Excel repair the file.
bool sheet_name_reads_as_reference(std::string_view name);

ReportTemplate load_report_template(const std::filesystem::path& file);

// The text of templates/report.toml as this program was built with it.
const std::string& shipped_report_template_text();

}  // namespace pierre::io
