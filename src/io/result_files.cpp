// The result files (result_writer.hpp): trajectories.csv, crossings.csv, impacts.csv, streamed
// as the runner delivers its chunks.
#include "pierre/io/result_writer.hpp"
#include "pierre/io/output_folder.hpp"
#include "pierre/design/quarry_distances.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <stdexcept>

#include <fmt/compile.h>
#include <fmt/format.h>


namespace pierre::io {
namespace {

constexpr std::size_t kFlushBytes = 1 << 20;

// RFC 4180: quote a text cell that holds a comma, a quote or a line break.
void text_cell(fmt::memory_buffer& b, const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) {
    b.append(s.data(), s.data() + s.size());
    return;
  }
  b.push_back('"');
  for (char c : s) {
    if (c == '"') b.push_back('"');
    b.push_back(c);
  }
  b.push_back('"');
}

void num(fmt::memory_buffer& b, double v) { fmt::format_to(fmt::appender(b), FMT_COMPILE("{:.9g}"), v); }
// A number that may be undefined (NaN): an empty cell then, as a missing first impact is.
void optional_num(fmt::memory_buffer& b, double v) {
  if (!std::isnan(v)) num(b, v);
}

std::string_view to_string(model::ImpactResult r) {
  switch (r) {
    case model::ImpactResult::rebound: return "rebound";
    case model::ImpactResult::sliding: return "sliding";
    case model::ImpactResult::stopped: return "stopped";
  }
  return "rebound";
}

}  // namespace

class ResultFiles::Csv {
 public:
  Csv(std::filesystem::path path, std::string_view header) : path_(std::move(path)) {
    f_ = std::fopen(path_.c_str(), "wb");
    if (!f_)
      throw OutputWriteError(path_, std::strerror(errno));
    buf.append(header.data(), header.data() + header.size());
    buf.push_back('\n');
  }
  ~Csv() {
    if (f_) std::fclose(f_);
  }
  void write(const fmt::memory_buffer& text) {
    buf.append(text.data(), text.data() + text.size());
    if (buf.size() >= kFlushBytes) flush();
  }
  void flush() {
    if (buf.size() && std::fwrite(buf.data(), 1, buf.size(), f_) != buf.size())
      throw OutputWriteError(path_, std::strerror(errno));
    buf.clear();
  }
  void close() {
    flush();
    std::FILE* f = f_;
    f_ = nullptr;
    if (std::fclose(f) != 0)
      throw OutputWriteError(path_, std::strerror(errno));
  }
  fmt::memory_buffer buf;

 private:
  std::filesystem::path path_;
  std::FILE* f_ = nullptr;
};

ResultFiles::ResultFiles(const std::filesystem::path& folder, const sim::Scenario& scenario,
                         bool impacts, bool every_crossing)
    : scenario_(&scenario),
      samples_(scenario.lines.size(), scenario.profile.main_direction(), every_crossing) {
  open(folder, impacts);
}

ResultFiles::ResultFiles(const std::filesystem::path& folder, bool impacts) : sectioned_(true) {
  open(folder, impacts);
}

void ResultFiles::open(const std::filesystem::path& folder, bool impacts) {
  const std::string lead = sectioned_ ? "section," : "";
  // A quarry's ID is measured from the first floor contact, not the first impact (always on the
  // face there): the contact is given, and ID and RD from it and the stop point.
  const std::string floor = sectioned_ ? "floor_contact_x_m,floor_contact_z_m,ID_m,RD_m," : "";
  trajectories_ = std::make_unique<Csv>(
      folder / kTrajectoriesCsv,
      lead +
          "trajectory,source,block_id,throw,mass_kg,start_x_m,start_z_m,stop_x_m,stop_z_m,runout_m,"
          "stop_reason,duration_s,impacts,first_impact_x_m,first_impact_z_m," +
          floor + "max_jump_height_m,max_speed_m_s,max_energy_kJ");
  crossings_ = std::make_unique<Csv>(
      folder / kCrossingsCsv,
      lead +
          "trajectory,line,chainage_m,block_id,mass_kg,time_s,direction,vx_m_s,vz_m_s,speed_m_s,"
          "omega_rad_s,translational_energy_kJ,rotational_energy_kJ,passing_height_m,sliding");
  if (impacts) impacts_ = std::make_unique<Csv>(folder / kImpactsCsv, impacts_csv_header(sectioned_));
}

std::string impacts_csv_header(bool sectioned) {
  return std::string(sectioned ? "section," : "") +
         "trajectory,impact,time_s,x_m,z_m,segment,material,result,slope_deg,roughness_deg,"
         "r_eff_m,vt_in_m_s,vn_in_m_s,vt_out_m_s,vn_out_m_s,vt_in_rot_m_s,vn_in_rot_m_s,"
         "vt_out_rot_m_s,vn_out_rot_m_s,kn,kt,kn_apparent,kt_apparent,incidence_deg,contained,"
         "energy_in_kJ,energy_out_kJ";
}

StaleResult stale_impacts_csv() {
  return {kImpactsCsv, {impacts_csv_header(false), impacts_csv_header(true)}};
}

void ResultFiles::begin_section(const sim::Scenario& scenario, std::string name,
                                const design::QuarryGeometry& geometry) {
  scenario_ = &scenario;
  geometry_ = &geometry;
  section_ = std::move(name);
  samples_ = design::RunSamples(scenario.lines.size(), scenario.profile.main_direction());
}

ResultFiles::~ResultFiles() = default;

// The CSV text of a chunk: made by prepare on the worker that simulated it, appended in order by
// consume.
struct ResultFiles::Text final : sim::PreparedChunk {
  fmt::memory_buffer trajectories, crossings, impacts;
};

void ResultFiles::prepare(sim::ChunkResult& chunk) const { chunk.prepared = format(chunk); }

std::unique_ptr<ResultFiles::Text> ResultFiles::format(const sim::ChunkResult& chunk) const {
  if (!scenario_) throw std::logic_error("ResultFiles: begin_section before the first chunk");
  const sim::Scenario& sc = *scenario_;
  auto text = std::make_unique<Text>();
  auto out = [](fmt::memory_buffer& b) { return fmt::appender(b); };
  auto lead = [&](fmt::memory_buffer& b) {
    if (!sectioned_) return;
    text_cell(b, section_);
    b.push_back(',');
  };
  {
    fmt::memory_buffer& b = text->trajectories;
    for (const sim::TrajectorySummary& t : chunk.trajectories) {
      lead(b);
      fmt::format_to(out(b), FMT_COMPILE("{},"), t.trajectory);
      text_cell(b, t.source < sc.sources.size() ? sc.sources[t.source].name : "");
      b.push_back(',');
      text_cell(b, t.block < sc.blocks.size() ? sc.blocks[t.block].id : "");
      fmt::format_to(out(b), FMT_COMPILE(",{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{},{:.9g},{},"),
                     t.throw_index, t.mass, t.start.x, t.start.z, t.stop.x, t.stop.z, t.runout(),
                     sim::to_string(t.stop_reason), t.duration, t.impacts);
      if (t.has_first_impact)
        fmt::format_to(out(b), FMT_COMPILE("{:.9g},{:.9g}"), t.first_impact.x, t.first_impact.z);
      else
        b.push_back(',');
      if (sectioned_) {
        if (t.has_floor_contact)
          fmt::format_to(out(b), FMT_COMPILE(",{:.9g},{:.9g}"), t.floor_contact.x, t.floor_contact.z);
        else
          fmt::format_to(out(b), FMT_COMPILE(",,"));
        // As the section's statistics count it (fmt writes +infinity as "inf").
        const design::QuarryTrajectory q = design::quarry_trajectory(t, *geometry_);
        b.push_back(',');
        optional_num(b, q.id);
        b.push_back(',');
        num(b, q.rd);
      }
      fmt::format_to(out(b), FMT_COMPILE(",{:.9g},{:.9g},{:.9g}\n"), t.max_jump_height, t.max_speed,
                     t.max_energy / 1000.0);
    }
  }
  {
    fmt::memory_buffer& b = text->crossings;
    for (const sim::Crossing& c : chunk.crossings) {
      lead(b);
      fmt::format_to(out(b), FMT_COMPILE("{},"), c.trajectory);
      const bool known = c.line < sc.lines.size();
      text_cell(b, known ? sc.lines[c.line].name : "");
      b.push_back(',');
      if (known) num(b, sc.lines[c.line].x);
      b.push_back(',');
      text_cell(b, c.block < sc.blocks.size() ? sc.blocks[c.block].id : "");
      fmt::format_to(out(b), FMT_COMPILE(",{:.9g},{:.9g},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{}\n"),
                     c.mass, c.time, c.direction, c.velocity.x, c.velocity.z, c.speed, c.omega,
                     c.translational_energy / 1000.0, c.rotational_energy / 1000.0, c.height,
                     c.sliding ? 1 : 0);
    }
  }
  if (impacts_) {
    fmt::memory_buffer& b = text->impacts;
    for (const sim::ImpactRecord& r : chunk.impacts) {
      const model::ImpactDetail& d = r.detail;
      lead(b);
      fmt::format_to(out(b), FMT_COMPILE("{},{},{:.9g},{:.9g},{:.9g},{},"), r.trajectory, r.index, r.time,
                     r.position.x, r.position.z, r.segment);
      std::string material;
      if (r.segment < sc.profile.segment_count()) {
        const int m = sc.profile.segment(r.segment).material;
        if (m >= 0 && static_cast<std::size_t>(m) < sc.materials.size())
          material = sc.materials[static_cast<std::size_t>(m)].name;
      }
      text_cell(b, material);
      fmt::format_to(out(b), FMT_COMPILE(",{},{:.9g},{:.9g},{:.9g},"), to_string(r.result), d.slope_deg,
                     d.roughness_deg, d.r_eff);
      fmt::format_to(out(b), FMT_COMPILE("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},"), d.vt_in,
                     d.vn_in, d.vt_out, d.vn_out, d.vt_in_rot, d.vn_in_rot, d.vt_out_rot,
                     d.vn_out_rot);
      fmt::format_to(out(b), FMT_COMPILE("{:.9g},{:.9g},"), d.kn, d.kt);
      optional_num(b, d.kn_apparent);
      b.push_back(',');
      optional_num(b, d.kt_apparent);
      fmt::format_to(out(b), FMT_COMPILE(",{:.9g},{},{:.9g},{:.9g}\n"), d.incidence_deg,
                     d.contained ? 1 : 0, d.energy_in / 1000.0, d.energy_out / 1000.0);
    }
  }
  return text;
}

void ResultFiles::consume(sim::ChunkResult&& chunk) {
  // A chunk that came without prepare (a caller other than the runner) is formatted here.
  std::unique_ptr<Text> own;
  const Text* text = dynamic_cast<const Text*>(chunk.prepared.get());
  if (!text) {
    own = format(chunk);
    text = own.get();
  }
  for (const sim::TrajectorySummary& t : chunk.trajectories) samples_.add(t);
  for (const sim::Crossing& c : chunk.crossings) samples_.add(c);
  trajectories_->write(text->trajectories);
  crossings_->write(text->crossings);
  if (impacts_) impacts_->write(text->impacts);
}

void ResultFiles::close() {
  trajectories_->close();
  crossings_->close();
  if (impacts_) impacts_->close();
}

}  // namespace pierre::io
