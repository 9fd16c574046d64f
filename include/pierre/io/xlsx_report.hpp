// report.xlsx, the design report (libxlsxwriter): everything in ReportData laid out by a
// ReportTemplate (templates/report.toml).
//
// Sheets, in the template's order: Summary (run, recommended barriers, observation-line
// statistics, every check line with PASS / FAIL / WARN coloured by conditional formats);
// one sheet per barrier (statistics and fits, bootstrap intervals, the design table of the
// thesis's Table 4.1 with the partial factors and how they were resolved, the exceedance table
// of Table 4.2, its check lines, native charts — histograms with the fitted densities and
// empirical against fitted CDFs — reading a data block on the same sheet); Profile (slope,
// sample trajectories, observation lines, barriers as vertical segments); Inputs (the scenario
// as read, with its text one line per row); Trajectories and Crossings (data, capped at the
// template's row counts, the cap stated on the sheet).
//
// Histograms and empirical CDFs are drawn from ReportData::crossings (the first crossing of
// each trajectory at the barrier's line in the main direction): pass every crossing at the
// barrier lines for exact charts; the sheet says how many crossings they were drawn from. The
// fitted curves come from the BarrierDesign fits (the whole sample).
//
// Numbers are written as numbers (a NaN or infinity as an empty cell), units are in the
// headings. The bytes depend only on the inputs: the document's creation time is
// ReportData::date at 00:00 UTC. The file is written atomically: to a temporary file in the
// same folder, renamed over `file` only when complete; on any error (every libxlsxwriter
// return code is checked) the temporary file is removed and std::runtime_error says why.
#pragma once

#include <filesystem>

#include "pierre/io/report_data.hpp"
#include "pierre/io/report_template.hpp"

namespace pierre::io {

inline constexpr const char* kReportXlsx = "report.xlsx";

void write_report(const std::filesystem::path& file, const ReportData& data,
                  const ReportTemplate& tpl);

}  // namespace pierre::io
