// The result files: exact headers, one row per trajectory / crossing / impact with units
// converted (J → kJ), empty first-impact cells, CSV quoting, a quarry run's section and floor
// contact columns; the samples kept for the statistics; summary.json; the atomic output folder.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <thread>

#include <nlohmann/json.hpp>

#include "pierre/design/quarry_geometry.hpp"
#include "pierre/io/output_folder.hpp"
#include "pierre/io/result_writer.hpp"
#include "pierre/io/version.hpp"
#include "test_files.hpp"

namespace {

using namespace pierre;
using pierre::test::read_file;
using pierre::test::TempDir;

sim::Scenario scenario() {
  sim::Scenario s;
  s.name = "w";
  std::vector<geometry::ProfileIssue> issues;
  s.profile = *geometry::Profile::build({{0, 10}, {10, 0}, {20, 0}}, {0, 0}, &issues);
  s.materials.push_back(model::Material{"rock", "scenario", 5, 0.5, 50, 0.95, 0.5, 30});
  model::Block b;
  b.id = "big, round";  // needs quoting
  b.mass = 100;
  s.blocks.push_back(b);
  s.sources.push_back({"top", {1, 11}, {0, 0}, 0});
  s.lines.push_back({"L1", 15});
  s.lines.push_back({"L2", 18});
  s.settings.throws = 2;
  return s;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::size_t p = 0;
  while (p < text.size()) {
    const auto n = text.find('\n', p);
    out.push_back(text.substr(p, n - p));
    p = n + 1;
  }
  return out;
}

sim::ChunkResult chunk() {
  sim::ChunkResult c;
  sim::TrajectorySummary t;
  t.trajectory = 0;
  t.mass = 100;
  t.start = {1, 11};
  t.stop = {16.5, 0};
  t.stop_reason = sim::StopReason::energy;
  t.duration = 3.25;
  t.impacts = 4;
  t.has_first_impact = true;
  t.first_impact = {2, 8};
  t.max_jump_height = 1.5;
  t.max_speed = 12;
  t.max_energy = 7200;  // J
  c.trajectories.push_back(t);
  t.trajectory = 1;
  t.throw_index = 1;
  t.stop = {21, -1};
  t.stop_reason = sim::StopReason::boundary;
  t.has_first_impact = false;
  c.trajectories.push_back(t);
  sim::Crossing x;
  x.trajectory = 0;
  x.line = 0;
  x.mass = 100;
  x.time = 2;
  x.direction = 1;
  x.velocity = {6, -8};
  x.speed = 10;
  x.translational_energy = 5000;
  x.rotational_energy = 250;
  x.height = 0.75;
  c.crossings.push_back(x);
  x.direction = -1;  // backwards: not kept for the statistics
  x.speed = 99;
  c.crossings.push_back(x);
  x.direction = 1;  // a second forward crossing of the same line: not kept either
  x.speed = 98;
  c.crossings.push_back(x);
  x.trajectory = 1;
  x.speed = 20;
  c.crossings.push_back(x);
  sim::ImpactRecord r;
  r.trajectory = 0;
  r.index = 0;
  r.time = 0.5;
  r.position = {2, 8};
  r.segment = 0;
  r.detail.energy_in = 3000;
  r.detail.energy_out = 1000;
  r.detail.contained = true;
  c.impacts.push_back(r);
  return c;
}

TEST(ResultFiles, WritesHeadersRowsAndUnits) {
  TempDir dir;
  const sim::Scenario s = scenario();
  sim::ResultCollector dummy;
  io::ResultFiles files(dir.path(), s, true);
  files.consume(chunk());
  files.close();

  const auto traj = lines_of(read_file(dir.path() / "trajectories.csv"));
  ASSERT_EQ(traj.size(), 3u);
  EXPECT_EQ(traj[0],
            "trajectory,source,block_id,throw,mass_kg,start_x_m,start_z_m,stop_x_m,stop_z_m,"
            "runout_m,stop_reason,duration_s,impacts,first_impact_x_m,first_impact_z_m,"
            "max_jump_height_m,max_speed_m_s,max_energy_kJ");
  EXPECT_EQ(traj[1], "0,top,\"big, round\",0,100,1,11,16.5,0,15.5,energy,3.25,4,2,8,1.5,12,7.2");
  EXPECT_EQ(traj[2], "1,top,\"big, round\",1,100,1,11,21,-1,20,boundary,3.25,4,,,1.5,12,7.2");

  const auto cross = lines_of(read_file(dir.path() / "crossings.csv"));
  ASSERT_EQ(cross.size(), 5u);
  EXPECT_EQ(cross[0],
            "trajectory,line,chainage_m,block_id,mass_kg,time_s,direction,vx_m_s,vz_m_s,"
            "speed_m_s,omega_rad_s,translational_energy_kJ,rotational_energy_kJ,"
            "passing_height_m,sliding");
  EXPECT_EQ(cross[1], "0,L1,15,\"big, round\",100,2,1,6,-8,10,0,5,0.25,0.75,0");

  const auto imp = lines_of(read_file(dir.path() / "impacts.csv"));
  ASSERT_EQ(imp.size(), 2u);
  EXPECT_EQ(imp[0].rfind("trajectory,impact,time_s,x_m,z_m,segment,material,result,slope_deg,", 0), 0u);
  EXPECT_NE(imp[0].find("energy_in_kJ,energy_out_kJ"), std::string::npos);
  EXPECT_EQ(imp[1].rfind("0,0,0.5,2,8,0,rock,rebound,", 0), 0u) << imp[1];
  EXPECT_NE(imp[1].find(",1,3,1"), std::string::npos) << imp[1];  // contained, 3 kJ in, 1 kJ out

  // Statistics samples: the first forward crossing of each trajectory on each line only.
  const auto& smp = files.samples();
  ASSERT_EQ(smp.lines().size(), 2u);
  EXPECT_EQ(smp.lines()[0].speed, (std::vector<double>{10, 20}));
  EXPECT_TRUE(smp.lines()[1].speed.empty());
  EXPECT_EQ(smp.runout(), (std::vector<double>{15.5, 20}));
  EXPECT_EQ(smp.stop_reasons()[static_cast<int>(sim::StopReason::energy)], 1u);
  EXPECT_EQ(smp.stop_reasons()[static_cast<int>(sim::StopReason::boundary)], 1u);
}

// The runner has the rows formatted on its workers (prepare) and written in order (consume); a
// chunk handed straight to consume is formatted there. Both give the same bytes, and the
// statistics samples are kept either way.
TEST(ResultFiles, APreparedChunkWritesTheSameBytesAsAnUnpreparedOne) {
  TempDir dir;
  const sim::Scenario s = scenario();
  std::filesystem::create_directories(dir.path() / "plain");
  std::filesystem::create_directories(dir.path() / "prepared");
  io::ResultFiles plain(dir.path() / "plain", s, true);
  io::ResultFiles prepared(dir.path() / "prepared", s, true);
  for (int k = 0; k < 2; ++k) {
    plain.consume(chunk());
    sim::ChunkResult c = chunk();
    prepared.prepare(c);
    ASSERT_NE(c.prepared, nullptr);
    c.trajectories[0].mass = -1;  // after prepare: the text is already made, not remade
    prepared.consume(std::move(c));
  }
  plain.close();
  prepared.close();
  for (const char* f : {"trajectories.csv", "crossings.csv", "impacts.csv"})
    EXPECT_EQ(read_file(dir.path() / "plain" / f), read_file(dir.path() / "prepared" / f)) << f;
  EXPECT_EQ(lines_of(read_file(dir.path() / "prepared" / "trajectories.csv")).size(), 5u);
  EXPECT_EQ(prepared.samples().runout(), plain.samples().runout());
  EXPECT_EQ(prepared.samples().lines()[0].speed, (std::vector<double>{10, 20, 10, 20}));
}

// A quarry run's rows are led by their section and carry the first floor contact (ID's origin,
// design-checks.md §2) after the first impact, then ID and RD from the toe: the contact's cells
// and ID empty for a block that never reached the floor, as the first impact's are without one.
// The section here: a face from (0, 10) to its toe at (10, 0), then 10 m of floor.
TEST(ResultFiles, AQuarryRunGivesTheFirstFloorContactAndTheDistancesFromTheToe) {
  TempDir dir;
  const sim::Scenario s = scenario();
  const auto geometry = design::quarry_geometry(s.profile, {});
  ASSERT_TRUE(geometry.ok());
  ASSERT_EQ(geometry->toe.x, 10.0);
  io::ResultFiles files(dir.path(), false);
  files.begin_section(s, "North", *geometry);
  sim::ChunkResult c = chunk();
  c.trajectories[0].has_floor_contact = true;
  c.trajectories[0].floor_contact = {12.25, 0};  // stops at 16.5: ID 2.25 m, RD 6.5 m
  c.trajectories[1].has_floor_contact = true;   // left at the runout end (x 20): RD censored
  c.trajectories[1].floor_contact = {10, 0};    // at the toe itself: ID 0
  sim::TrajectorySummary on_face = c.trajectories[0];  // stopped on the face: RD 0, no ID
  on_face.trajectory = 2;
  on_face.throw_index = 2;
  on_face.has_floor_contact = false;
  on_face.stop = {4, 6};
  c.trajectories.push_back(on_face);
  files.consume(std::move(c));
  files.close();

  const auto traj = lines_of(read_file(dir.path() / "trajectories.csv"));
  ASSERT_EQ(traj.size(), 4u);
  EXPECT_EQ(traj[0],
            "section,trajectory,source,block_id,throw,mass_kg,start_x_m,start_z_m,stop_x_m,stop_z_m,"
            "runout_m,stop_reason,duration_s,impacts,first_impact_x_m,first_impact_z_m,"
            "floor_contact_x_m,floor_contact_z_m,ID_m,RD_m,max_jump_height_m,max_speed_m_s,"
            "max_energy_kJ");
  EXPECT_EQ(traj[1], "North,0,top,\"big, round\",0,100,1,11,16.5,0,15.5,energy,3.25,4,2,8,12.25,0,2.25,6.5,1.5,12,7.2");
  EXPECT_EQ(traj[2], "North,1,top,\"big, round\",1,100,1,11,21,-1,20,boundary,3.25,4,,,10,0,0,inf,1.5,12,7.2");
  EXPECT_EQ(traj[3], "North,2,top,\"big, round\",2,100,1,11,4,6,3,energy,3.25,4,2,8,,,,0,1.5,12,7.2");
}

TEST(ResultFiles, NoImpactsFileUnlessAsked) {
  TempDir dir;
  const sim::Scenario s = scenario();
  io::ResultFiles files(dir.path(), s, false);
  files.consume(chunk());
  files.close();
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "impacts.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "crossings.csv"));
}

TEST(SummaryJson, CarriesRunInfoAndStatistics) {
  const sim::Scenario s = scenario();
  design::RunSamples smp(2, 1);
  sim::ChunkResult c = chunk();
  for (const auto& t : c.trajectories) smp.add(t);
  for (const auto& x : c.crossings) smp.add(x);
  const auto stats = design::run_statistics(s.lines, smp);
  io::RunInfo info;
  info.scenario_name = "w";
  info.scenario_file = "w.toml";
  info.seed = 7;
  info.throws = 2;
  info.trajectories = 2;
  info.threads = 3;
  info.document.reference = "P-17";
  info.document.checked_by = "B. Checker";
  const auto j = nlohmann::json::parse(io::summary_json(info, stats));
  EXPECT_EQ(j["pierre_version"], PIERRE_VERSION);
  EXPECT_EQ(j["pierre_build"], std::string(io::build_id()));
  EXPECT_FALSE(io::build_id().empty());
  EXPECT_EQ(j["scenario"]["name"], "w");
  // The document control given, and only that.
  EXPECT_EQ(j["scenario"]["reference"], "P-17");
  EXPECT_EQ(j["scenario"]["checked_by"], "B. Checker");
  EXPECT_FALSE(j["scenario"].contains("revision"));
  EXPECT_FALSE(j["scenario"].contains("prepared_by"));
  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["trajectories"], 2);
  EXPECT_EQ(j["threads"], 3);
  EXPECT_EQ(j["stop_reasons"]["energy"], 1);
  EXPECT_EQ(j["stop_reasons"]["boundary"], 1);
  EXPECT_EQ(j["stop_reasons"]["numerical"], 0);
  ASSERT_EQ(j["lines"].size(), 2u);
  EXPECT_EQ(j["lines"][0]["name"], "L1");
  EXPECT_EQ(j["lines"][0]["chainage_m"], 15.0);
  EXPECT_EQ(j["lines"][0]["count"], 2);
  EXPECT_EQ(j["lines"][0]["not_reached"], 0);
  EXPECT_DOUBLE_EQ(j["lines"][0]["speed_m_s"]["mean"].get<double>(), 15.0);
  EXPECT_DOUBLE_EQ(j["lines"][0]["speed_m_s"]["max"].get<double>(), 20.0);
  EXPECT_DOUBLE_EQ(j["lines"][0]["translational_energy_kJ"]["p50"].get<double>(), 5.0);
  EXPECT_EQ(j["lines"][1]["count"], 0);
  EXPECT_EQ(j["lines"][1]["not_reached"], 2);
  EXPECT_TRUE(j["lines"][1]["speed_m_s"]["mean"].is_null());  // no crossing: null, not 0
  EXPECT_DOUBLE_EQ(j["runout_m"]["max"].get<double>(), 20.0);
  EXPECT_DOUBLE_EQ(j["runout_m"]["p50"].get<double>(), 17.75);
  // The 20 m runout left the profile: every statistic interpolates towards it (P50 = 17.75 m
  // halfway from the 15.5 m at rest), so all are lower bounds.
  EXPECT_EQ(j["runout_m"]["lower_bounds"], nlohmann::json::array({"p50", "p95", "p99", "max"}));
  // Nothing to check: the keys a script reads are there all the same.
  ASSERT_TRUE(j.contains("checks"));
  EXPECT_TRUE(j["checks"].is_array());
  EXPECT_TRUE(j["checks"].empty());
  EXPECT_EQ(j["checks_failed"], false);
}

TEST(OutputFolder, CommitMovesFilesAndRemovesStaging) {
  TempDir dir;
  const auto out = dir.path() / "new" / "out";
  std::filesystem::create_directories(dir.path() / "old");
  {
    io::OutputFolder f(out);
    EXPECT_TRUE(std::filesystem::is_directory(f.staging()));
    EXPECT_EQ(f.staging().parent_path(), out);
    std::ofstream(f.staged("a.csv")) << "a\n";
    std::ofstream(out / "impacts.csv") << io::impacts_csv_header(true) << "\r\nsome,rows\n";
    const auto written = f.commit({io::stale_impacts_csv()});
    ASSERT_EQ(written.size(), 1u);
    EXPECT_EQ(written[0], out / "a.csv");
    EXPECT_FALSE(std::filesystem::exists(f.staging()));
    EXPECT_TRUE(f.kept().empty());
  }
  EXPECT_EQ(read_file(out / "a.csv"), "a\n");
  EXPECT_FALSE(std::filesystem::exists(out / "impacts.csv"));  // stale output of another run
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(out), {}), 1);
}

// Whether a stale result is pierre's goes by its first line, not its name: a field record of
// the user's called impacts.csv (new-user review: it was deleted by a run without --impacts)
// stays, and so does a folder by that name; both are reported as kept.
TEST(OutputFolder, AStaleNameThatIsNotPierresIsLeftAlone) {
  TempDir dir;
  const auto out = dir.path() / "out";
  std::filesystem::create_directories(out / "sub");
  const std::string mine = "my field survey of impacts\nx,z\n1,2\n";
  std::ofstream(out / "impacts.csv") << mine;
  // pierre's header with a column more: not the header pierre writes.
  std::ofstream(out / "other.csv") << io::impacts_csv_header(false) << ",note\n";
  {
    io::OutputFolder f(out);
    std::ofstream(f.staged("a.csv")) << "a\n";
    f.commit({io::stale_impacts_csv(), {"other.csv", {io::impacts_csv_header(false)}},
              {"sub", {"x"}}, {"absent.csv", {"x"}}});
    ASSERT_EQ(f.kept().size(), 3u);
    EXPECT_EQ(f.kept()[0], out / "impacts.csv");
    EXPECT_EQ(f.kept()[1], out / "other.csv");
    EXPECT_EQ(f.kept()[2], out / "sub");
  }
  EXPECT_EQ(read_file(out / "impacts.csv"), mine);
  EXPECT_TRUE(std::filesystem::exists(out / "other.csv"));
  EXPECT_TRUE(std::filesystem::is_directory(out / "sub"));
  EXPECT_EQ(read_file(out / "a.csv"), "a\n");
}

TEST(OutputFolder, WithoutCommitNothingIsLeft) {
  TempDir dir;
  const auto out = dir.path() / "out";
  {
    io::OutputFolder f(out);
    std::ofstream(f.staged("a.csv")) << "a\n";
  }
  EXPECT_FALSE(std::filesystem::exists(out));  // created by the run, removed with it

  std::filesystem::create_directories(out);
  std::ofstream(out / "keep.txt") << "mine\n";
  {
    io::OutputFolder f(out);
    std::ofstream(f.staged("a.csv")) << "a\n";
  }
  EXPECT_TRUE(std::filesystem::exists(out / "keep.txt"));  // a folder of the user's stays
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(out), {}), 1);
}

// A commit that cannot replace one file leaves the folder as it was: here a folder of the user's
// by a result's name (a file held open by another program fails the same way, later). Before,
// the files sorted ahead of it were replaced and the others not: half of each run.
TEST(OutputFolder, CommitIsAllOrNothing) {
  TempDir dir;
  const auto out = dir.path() / "out";
  std::filesystem::create_directories(out / "b.json");  // in the way of b.json
  std::ofstream(out / "a.csv") << "old a\n";
  std::ofstream(out / "c.csv") << "old c\n";
  std::ofstream(out / "impacts.csv") << io::impacts_csv_header(false) << "\nold impacts\n";
  {
    io::OutputFolder f(out);
    for (const char* n : {"a.csv", "b.json", "c.csv"}) std::ofstream(f.staged(n)) << "new\n";
    try {
      f.commit({io::stale_impacts_csv()});
      FAIL() << "no CommitError";
    } catch (const io::CommitError& e) {
      EXPECT_EQ(e.file(), out / "b.json");
      EXPECT_NE(std::string(e.what()).find("not a file"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("left as it was"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(read_file(out / "a.csv"), "old a\n");
  EXPECT_EQ(read_file(out / "c.csv"), "old c\n");
  // pierre's stale impacts.csv, but not removed either
  EXPECT_EQ(read_file(out / "impacts.csv"), io::impacts_csv_header(false) + "\nold impacts\n");
  EXPECT_TRUE(std::filesystem::is_directory(out / "b.json"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(out), {}), 4);  // no staging left
}

// A run killed outright (kill -9, out of memory) cannot take its staging folder away: the next
// run in the folder does, as nothing holds its lock. A run still going (its lock held, here by
// this test, whatever its process id or PID namespace) keeps its own.
TEST(OutputFolder, TheStagingOfAKilledRunIsTakenAway) {
  TempDir dir;
  const auto out = dir.path() / "out";
  const auto dead = out / ".pierre-partial-dead01";
  const auto alive = out / ".pierre-partial-alive1";
  for (const auto& p : {dead, alive}) {
    std::filesystem::create_directories(p);
    std::ofstream(p / "trajectories.csv") << "partial\n";
  }
  const int held = ::open(alive.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(held, 0);
  ASSERT_EQ(::flock(held, LOCK_EX | LOCK_NB), 0);
  {
    io::OutputFolder f(out);
    f.commit();
  }
  ::close(held);
  EXPECT_FALSE(std::filesystem::exists(dead));
  EXPECT_TRUE(std::filesystem::exists(alive / "trajectories.csv"));
}

// Two runs into one folder at once, here in one process (as two runs with the same process id
// in two containers): each has its own staging folder, and neither takes the other's away.
// Before, the staging folder was named by the process id and the second run emptied the first's.
TEST(OutputFolder, TwoRunsAtOnceKeepTheirOwnStaging) {
  TempDir dir;
  const auto out = dir.path() / "out";
  io::OutputFolder a(out);
  std::ofstream(a.staged("x.csv")) << "a\n";
  io::OutputFolder b(out);
  std::ofstream(b.staged("x.csv")) << "b\n";
  EXPECT_NE(a.staging(), b.staging());
  EXPECT_EQ(read_file(a.staged("x.csv")), "a\n");
  a.commit();
  EXPECT_EQ(read_file(out / "x.csv"), "a\n");
  b.commit();
  EXPECT_EQ(read_file(out / "x.csv"), "b\n");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(out), {}), 1);
}

// A commit waits while another run commits into the same folder (its lock on the folder, here
// held by the test), so the two sets cannot interleave file by file.
TEST(OutputFolder, ACommitWaitsForAnotherRunsCommit) {
  TempDir dir;
  const auto out = dir.path() / "out";
  io::OutputFolder f(out);
  std::ofstream(f.staged("x.csv")) << "new\n";
  const int held = ::open(out.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(held, 0);
  ASSERT_EQ(::flock(held, LOCK_EX), 0);
  std::atomic<bool> started{false}, committed{false};
  std::thread t([&] {
    started = true;
    f.commit();
    committed = true;
  });
  // Once the other thread is on its way to the commit, give it ample time to pass a broken lock.
  while (!started.load()) std::this_thread::yield();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_FALSE(committed.load());  // cannot have gone on while the lock is held
  EXPECT_FALSE(std::filesystem::exists(out / "x.csv"));
  ::close(held);  // the other commit is done
  t.join();
  EXPECT_TRUE(committed.load());
  EXPECT_EQ(read_file(out / "x.csv"), "new\n");
}

// A run that fails takes away every folder it created for DIR, not only DIR itself.
TEST(OutputFolder, AFailedRunTakesAwayTheFoldersItCreated) {
  TempDir dir;
  const auto out = dir.path() / "new" / "a" / "b";
  std::filesystem::create_directories(dir.path() / "kept");
  {
    io::OutputFolder f(out);
    std::ofstream(f.staged("x.csv")) << "x\n";
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "new"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "kept"));
}

TEST(OutputFolder, OutputPathThatIsAFileIsRefused) {
  TempDir dir;
  const auto f = dir.write("file", "x");
  EXPECT_THROW(io::OutputFolder{f}, std::filesystem::filesystem_error);
}

// A folder whose results' paths the system cannot open is refused when opened (before the run),
// and the folder it created for the purpose is taken away again.
TEST(OutputFolder, OutputPathTooLongForItsFilesIsRefused) {
  TempDir dir;
  std::filesystem::path deep = dir.path();
  // Folders of 200 characters (each within NAME_MAX) until the path is ~40 short of PATH_MAX:
  // it can be created, but not staging/.previous/<result>.
  while (deep.native().size() + 201 < PATH_MAX - 40) deep /= std::string(200, 'a');
  std::filesystem::create_directories(deep);
  deep /= std::string(PATH_MAX - 40 - deep.native().size() - 1, 'b');
  ASSERT_LT(deep.native().size(), static_cast<std::size_t>(PATH_MAX));
  try {
    io::OutputFolder out{deep};
    FAIL() << "no error for a path of " << deep.native().size() << " characters";
  } catch (const std::filesystem::filesystem_error& e) {
    EXPECT_EQ(e.code(), std::make_error_code(std::errc::filename_too_long)) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(deep));
  // Two hundred characters shorter it works.
  const std::filesystem::path fits = deep.parent_path().parent_path() / "c";
  ASSERT_GT(fits.native().size(), static_cast<std::size_t>(PATH_MAX - 300));
  io::OutputFolder ok{fits};
  EXPECT_TRUE(std::filesystem::is_directory(ok.staging()));
}

}  // namespace
