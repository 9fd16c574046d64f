// The data sheets, Trajectories and Crossings: the first rows of trajectories.csv and
// crossings.csv (the cap stated on the sheet), in a quarry run each under its section.
#include "xlsx_report_writer.hpp"

#include "pierre/design/quarry_distances.hpp"

#include <algorithm>

namespace pierre::io::detail {

Row Report::cap_note(lxw_worksheet* ws, Row r, std::size_t shown, std::uint64_t total,
                     const char* csv) {
  const std::string key = total == 0 ? "no_rows" : shown < total ? "capped" : "complete";
  std::string s = replace_all(t_.get("titles", key), "{shown}", std::to_string(shown));
  s = replace_all(replace_all(s, "{total}", std::to_string(total)), "{file}", csv);
  s = replace_all(s, "{printed}", std::to_string(std::min<std::size_t>(shown, t_.print_rows)));
  text(ws, r++, 0, s, note());
  return r;
}

// The top of a data sheet: its title, the cap note and the heading row (in a quarry run the
// section column first), frozen and repeated on every printed page; returns the heading's row
// (left empty when there are no rows).
Row Report::data_sheet_head(lxw_worksheet* ws, std::string_view key, Col c0, std::size_t shown,
                            std::uint64_t total, const char* csv,
                            std::initializer_list<std::string_view> keys) {
  text(ws, 0, 0, t_.get("titles", key), title());
  const Row head = cap_note(ws, 1, shown, total, csv);
  if (shown == 0) return head;  // the note says there are none: no headings over nothing
  if (c0 > 0) headings(ws, head, 0, key, {"section"}, 45);
  headings(ws, head, c0, key, keys, 45);
  worksheet_freeze_panes(ws, head + 1, 1 + c0);
  check(worksheet_repeat_rows(ws, head, head), "worksheet_repeat_rows");
  return head;
}

// A data sheet prints its heading and the template's print_rows rows below it; `r` is the row
// after the last one written.
void Report::data_sheet_print_area(lxw_worksheet* ws, Row head, Row r, Col last_col) {
  const Row last = static_cast<Row>(std::min<std::size_t>(head + t_.print_rows, r > 0 ? r - 1 : 0));
  check(worksheet_print_area(ws, 0, 0, std::max(last, head), last_col), "worksheet_print_area");
}

void Report::trajectories(lxw_worksheet* ws) {
  page_setup(ws);
  // A quarry run leads with the section of each row; its names come from that section. It also
  // has the floor contact after the first impact, ID and RD from the toe, as trajectories.csv
  // does.
  const bool by_section = !d_.trajectory_sections.empty();
  const Col c0 = by_section ? 1 : 0;
  const Col f = by_section ? 4 : 0;  // the floor contact's two columns, ID and RD
  const Col last = 17 + c0 + f;
  widths(ws, 0, last, 11, {{0, by_section ? 16 : 11}, {1 + c0, 20}, {2 + c0, 12}, {10 + c0, 14}});
  const std::size_t shown = std::min(d_.trajectories.size(), t_.trajectory_rows);
  const std::uint64_t total = std::max<std::uint64_t>(d_.total_trajectories, d_.trajectories.size());
  const Row head = data_sheet_head(
      ws, "trajectories", c0, shown, total, "trajectories.csv",
      {"trajectory", "source", "block", "throw", "mass", "start_x", "start_z", "stop_x", "stop_z",
       "runout", "stop_reason", "duration", "impacts", "first_impact_x", "first_impact_z"});
  if (by_section)
    headings(ws, head, c0 + 15, "trajectories", {"floor_contact_x", "floor_contact_z", "id", "rd"}, 45);
  headings(ws, head, c0 + 15 + f, "trajectories", {"max_jump_height", "max_speed", "max_energy"}, 45);
  Row r = head + 1;
  lxw_format *cf = number("count"), *xf = number("coordinate"), *mf = number("mass"),
             *lf = number("length"), *tf = number("time"), *sf = number("speed"),
             *ef = number("energy");
  for (std::size_t i = 0; i < shown; ++i, ++r) {
    const auto& t = d_.trajectories[i];
    const DataRow row = data_row(ws, r, d_.trajectory_sections, i);
    const sim::Scenario* s = row.scenario;
    row.num(0, static_cast<double>(t.trajectory), cf);
    if (s && t.source < s->sources.size()) row.text(1, s->sources[t.source].name);
    else row.num(1, t.source, cf);
    if (s && t.block < s->blocks.size()) row.text(2, s->blocks[t.block].id);
    else row.num(2, t.block, cf);
    row.num(3, t.throw_index, cf);
    row.num(4, t.mass, mf);
    row.num(5, t.start.x, xf);
    row.num(6, t.start.z, xf);
    row.num(7, t.stop.x, xf);
    row.num(8, t.stop.z, xf);
    row.num(9, t.runout(), lf);
    row.text(10, std::string(sim::to_string(t.stop_reason)), centred());
    row.num(11, t.duration, tf);
    row.num(12, t.impacts, cf);
    if (t.has_first_impact) {
      row.num(13, t.first_impact.x, xf);
      row.num(14, t.first_impact.z, xf);
    }
    if (by_section && t.has_floor_contact) {
      row.num(15, t.floor_contact.x, xf);
      row.num(16, t.floor_contact.z, xf);
    }
    if (by_section && row.geometry) {
      const design::QuarryTrajectory q = design::quarry_trajectory(t, *row.geometry);
      if (q.reached_floor) row.num(17, q.id, lf);
      if (q.censored)
        row.text(18, t_.get("labels", "beyond_profile"));
      else
        row.num(18, q.rd, lf);
    }
    row.num(15 + f, t.max_jump_height, lf);
    row.num(16 + f, t.max_speed, sf);
    row.num(17 + f, t.max_energy / 1000, ef);
  }
  data_sheet_print_area(ws, head, r, last);
}

void Report::crossings(lxw_worksheet* ws) {
  page_setup(ws);
  const bool by_section = !d_.crossing_sections.empty();
  const Col c0 = by_section ? 1 : 0;
  // "Translational" and "Rotational" whole in their headings (a narrower column broke the word).
  widths(ws, 0, 14 + c0, 11,
         {{0, by_section ? 16 : 11}, {1 + c0, 16}, {3 + c0, 14}, {11 + c0, 14}, {12 + c0, 12}});
  const std::size_t shown = std::min(d_.crossings.size(), t_.crossing_rows);
  const std::uint64_t total = std::max<std::uint64_t>(d_.total_crossings, d_.crossings.size());
  const Row head = data_sheet_head(
      ws, "crossings", c0, shown, total, "crossings.csv",
      {"trajectory", "line", "chainage", "block", "mass", "time", "direction", "vx", "vz", "speed",
       "omega", "translational_energy", "rotational_energy", "passing_height", "sliding"});
  Row r = head + 1;
  lxw_format *cf = number("count"), *xf = number("coordinate"), *mf = number("mass"),
             *lf = number("length"), *tf = number("time"), *sf = number("speed"),
             *ef = number("energy"), *gf = number("general");
  for (std::size_t i = 0; i < shown; ++i, ++r) {
    const auto& c = d_.crossings[i];
    const DataRow row = data_row(ws, r, d_.crossing_sections, i);
    const sim::Scenario* s = row.scenario;
    row.num(0, static_cast<double>(c.trajectory), cf);
    row.text(1, line_name(c.line));
    row.num(2, line_chainage(c.line), xf);
    if (s && c.block < s->blocks.size()) row.text(3, s->blocks[c.block].id);
    else row.num(3, c.block, cf);
    row.num(4, c.mass, mf);
    row.num(5, c.time, tf);
    row.num(6, c.direction, gf);
    row.num(7, c.velocity.x, sf);
    row.num(8, c.velocity.z, sf);
    row.num(9, c.speed, sf);
    row.num(10, c.omega, sf);
    row.num(11, c.translational_energy / 1000, ef);
    row.num(12, c.rotational_energy / 1000, ef);
    row.num(13, c.height, lf);
    row.num(14, c.sliding ? 1 : 0, cf);
  }
  data_sheet_print_area(ws, head, r, 14 + c0);
}

}  // namespace pierre::io::detail
