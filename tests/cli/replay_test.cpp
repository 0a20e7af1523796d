// `esc replay`: a stored controller re-simulated from its stored seed writes an SVG (arena,
// paths, legend) and a CSV whose rows are the replay stored in esc.db, value for value; a
// genome file replays in another script's experiment; bad choices are errors, not crashes.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/store/results_db.hpp"
#include "tests/cli/esc_process.hpp"

namespace {

using cli_test::Outcome;
using cli_test::read_json;
using cli_test::scratch;
using cli_test::shell;
using cli_test::slurp;
using cli_test::tiny;
namespace fs = std::filesystem;
namespace store = ::esc::store;
namespace eval = ::esc::eval;

Outcome esc_command(const std::string& args) { return cli_test::esc(args); }

// One finished run of tiny.esc, made once for every test here.
const fs::path& tiny_run() {
  static const fs::path dir = [] {
    const fs::path d = scratch("replay-run");
    const Outcome o = esc_command("run " + tiny() + " --generations 3 --threads 2 --out " + d.string());
    EXPECT_EQ(o.status, 0) << o.output;
    return d;
  }();
  return dir;
}

std::vector<std::vector<std::string>> read_csv(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream cut(line);
    for (std::string cell; std::getline(cut, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(std::move(cells));
  }
  return rows;
}

double number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

// Whether the file is well-formed XML (Python's parser: python3 is one of the packages
// scripts/esc-setup.sh installs).
bool well_formed_xml(const fs::path& file) {
  return shell("python3 -c 'import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])' " + file.string()).status == 0;
}

TEST(Replay, RewritesTheStoredReplayBitForBitAsCsvAndSvg) {
  const fs::path dir = tiny_run();
  const fs::path out = scratch("replay-out");
  const Outcome o = esc_command("replay " + dir.string() + " --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("identical to the stored replay"), std::string::npos) << o.output;

  const store::StoredExperiment stored = store::ResultsDb::open(dir, true).load_single();
  for (const store::StoredController& c : stored.controllers) {
    ASSERT_TRUE(c.replay.has_value()) << c.name;
    const std::string stem = "replay-" + c.name + "-run-0" + std::to_string(c.replay->run + 1);
    const auto rows = read_csv(out / (stem + ".csv"));
    ASSERT_EQ(rows.size(), c.replay->steps.size() + 1) << c.name;
    const std::vector<std::string>& header = rows.front();
    const auto column = [&](const std::string& name) {
      const auto it = std::find(header.begin(), header.end(), name);
      EXPECT_NE(it, header.end()) << name;
      return static_cast<std::size_t>(it - header.begin());
    };
    for (std::size_t i = 0; i < c.replay->steps.size(); ++i) {
      const eval::TraceStep& t = c.replay->steps[i];
      const std::vector<std::string>& r = rows[i + 1];
      ASSERT_EQ(r.size(), header.size()) << "row " << i;
      EXPECT_EQ(std::stoi(r[column("epoch")]), t.epoch + 1);
      EXPECT_EQ(std::stoi(r[column("step")]), t.step + 1);
      EXPECT_EQ(number(r[column("x_m")]), t.pose.x_m) << "row " << i;
      EXPECT_EQ(number(r[column("y_m")]), t.pose.y_m) << "row " << i;
      EXPECT_EQ(number(r[column("heading_rad")]), t.pose.heading_rad) << "row " << i;
      EXPECT_EQ(number(r[column("left_command")]), t.left_command) << "row " << i;
      EXPECT_EQ(number(r[column("right_speed_mps")]), t.right_speed_mps) << "row " << i;
      for (std::size_t k = 0; k < t.ir.size(); ++k)
        EXPECT_EQ(number(r[column("ir" + std::to_string(k))]), t.ir[k]) << "row " << i;
      EXPECT_EQ(number(r[column("energy")]), t.energy) << "row " << i;
      EXPECT_EQ(number(r[column("fitness")]), t.fitness) << "row " << i;
      EXPECT_EQ(r[column("collided")], t.collided ? "1" : "0");
      EXPECT_EQ(r[column("behavior")], t.action >= 0 ? c.actions.at(static_cast<std::size_t>(t.action)) : "");
    }
    EXPECT_EQ(number(rows.back()[column("fitness")]), c.replay->fitness) << c.name;

    const fs::path svg = out / (stem + ".svg");
    EXPECT_TRUE(well_formed_xml(svg)) << svg;
    const std::string text = slurp(svg);
    EXPECT_NE(text.find("<svg"), std::string::npos);
    EXPECT_NE(text.find("<path stroke="), std::string::npos) << "no trajectory";
    EXPECT_NE(text.find("class=\"legend\""), std::string::npos);
    EXPECT_NE(text.find("wall or obstacle"), std::string::npos);
    EXPECT_NE(text.find("<circle"), std::string::npos) << "no cylinder";
  }
}

TEST(Replay, ChosenRunAndEpochs) {
  const fs::path dir = tiny_run();
  const fs::path out = scratch("replay-chosen");
  const Outcome o =
      esc_command("replay " + dir.string() + " --controller SC --run 2 --epochs 2-3 --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const auto rows = read_csv(out / "replay-SC-run-02.csv");
  ASSERT_GT(rows.size(), 1U);
  for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_TRUE(rows[i][0] == "2" || rows[i][0] == "3") << rows[i][0];
  // The whole evaluation was simulated: its last fitness is the run's best fitness.
  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(number(rows.back()[rows.front().size() - 2]),
            summary["controllers"]["SC"]["runs"][1]["best_fitness"].get<double>());
  EXPECT_FALSE(fs::exists(out / "replay-CC-run-02.csv"));
  const std::string svg = slurp(out / "replay-SC-run-02.svg");
  EXPECT_NE(svg.find("path, by acting behavior"), std::string::npos);
  EXPECT_NE(svg.find("forward ("), std::string::npos);
  EXPECT_NE(svg.find("epochs 2,3 of 3 drawn"), std::string::npos);
}

// The running fitness counts an epoch's end terms on its last step, so the last row is the
// evaluation's fitness here too, where an `epoch:` term adds -100 * |share(left) - 0.1|.
TEST(Replay, TheRunningFitnessCountsTheEndTermsWhereTheyApply) {
  const fs::path dir = scratch("replay-end-terms");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/behavior_use.esc";
  ASSERT_EQ(esc_command("run " + script + " --experiment constrained_use --generations 2 --out " + dir.string()).status,
            0);
  const auto summary = read_json(dir / "summary.json");
  int stored = 0;   // the controller's replay stored in esc.db: the same, value for value
  for (const int run : {1, 2}) {
    const Outcome o = esc_command("replay " + dir.string() + " --controller SV --run " + std::to_string(run));
    ASSERT_EQ(o.status, 0) << o.output;
    stored += o.output.find("identical to the stored replay") != std::string::npos ? 1 : 0;
    const auto rows = read_csv(dir / ("replay-SV-run-0" + std::to_string(run) + ".csv"));
    ASSERT_GT(rows.size(), 2U);
    const std::size_t fitness = rows.front().size() - 2;
    ASSERT_EQ(rows.front()[fitness], "fitness");
    EXPECT_EQ(number(rows.back()[fitness]),
              summary["controllers"]["SV"]["runs"][run - 1]["best_fitness"].get<double>()) << run;
  }
  EXPECT_EQ(stored, 1);
}

TEST(Replay, AGenomeFileInAnotherArena) {
  const fs::path dir = tiny_run();
  const fs::path out = scratch("replay-elsewhere");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/elsewhere.esc";
  const Outcome o = esc_command("replay " + (dir / "CC" / "run-01.best.json").string() + " --script " + script +
                        " --experiment elsewhere --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const fs::path svg = out / "replay-CC-run-01-in-elsewhere.svg";
  EXPECT_TRUE(well_formed_xml(svg));
  const std::string text = slurp(svg);
  EXPECT_NE(text.find("floor zone"), std::string::npos);   // the recharge zone and its light
  EXPECT_NE(text.find("light"), std::string::npos);
  EXPECT_NE(text.find("rotate("), std::string::npos);      // the turned block
  EXPECT_NE(text.find("path, by epoch"), std::string::npos);
  const auto rows = read_csv(out / "replay-CC-run-01-in-elsewhere.csv");
  ASSERT_GT(rows.size(), 2U);
  EXPECT_LE(rows.size(), 1U + 2U * 60U) << "2 epochs of at most 60 steps";
  EXPECT_EQ(rows[1][0], "1");
  EXPECT_EQ(rows.back()[0], "2");
  // The light sensors see the lamp (the stored replay has no light column: this is the
  // re-simulation's own reading).
  const auto light0 = static_cast<std::size_t>(std::find(rows[0].begin(), rows[0].end(), "light0") - rows[0].begin());
  double brightest = 0.0;
  for (std::size_t i = 1; i < rows.size(); ++i)
    for (std::size_t k = 0; k < 8; ++k) brightest = std::max(brightest, number(rows[i][light0 + k]));
  EXPECT_GT(brightest, 0.0);
}

TEST(Replay, AnimationWithoutAToolSaysSoAndKeepsThePicture) {
  const fs::path out = scratch("replay-no-tool");
  const Outcome o = shell("PATH=/nonexistent " + std::string(ESC_BINARY) + " replay " + tiny_run().string() +
                          " --controller CC --epochs 1 --animate --out " + out.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("--animate needs ffmpeg"), std::string::npos) << o.output;
  EXPECT_TRUE(fs::exists(out / "replay-CC-run-01.svg"));
  EXPECT_TRUE(fs::exists(out / "replay-CC-run-01.csv"));
}

TEST(Replay, AnimationWithFfmpeg) {
  if (shell("command -v ffmpeg").status != 0) GTEST_SKIP() << "ffmpeg is not installed (optional: Debian package ffmpeg)";
  const fs::path out = scratch("replay-movie");
  const Outcome o = esc_command("replay " + tiny_run().string() + " --controller SC --epochs 1 --animate --out " +
                                out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const fs::path movie = out / "replay-SC-run-01.mp4";
  ASSERT_TRUE(fs::exists(movie)) << o.output;
  if (shell("command -v ffprobe").status == 0) {
    const Outcome probe = shell("ffprobe -v error -select_streams v -show_entries stream=codec_type -of csv=p=0 " +
                                movie.string());
    EXPECT_NE(probe.output.find("video"), std::string::npos) << probe.output;
  }
}

// The report page's DOM once headless Chromium has run its script, checked to have run to
// the end without a script error; nullopt where the build has no Chromium.
std::optional<std::string> report_page(const fs::path& dir) {
  EXPECT_EQ(esc_command("report " + dir.string()).status, 0);
  if (std::string(ESC_CHROMIUM).empty()) return std::nullopt;
  const Outcome dom = cli_test::report_dom(dir);
  EXPECT_EQ(dom.status, 0) << dom.output.substr(0, 2000);
  EXPECT_NE(dom.output.find("(ready)</title>"), std::string::npos) << dom.output.substr(0, 600);
  EXPECT_EQ(dom.output.find("class=\"esc-error\""), std::string::npos) << "script error in the page";
  return dom.output;
}

// A group's replay (docs/groups.md): every robot re-simulated, identical to the stored
// replay; the CSV has a robot column, and the group quantities in it agree with the robots'
// positions recomputed from the same CSV; the SVG draws every robot; the report's replay
// panel shows the group in headless Chromium where it is installed.
TEST(Replay, AGroupIsReplayedWithEveryRobot) {
  const fs::path dir = scratch("replay-group");
  // Started in a line, set from the command line: several `--set` apply together.
  const Outcome run = esc_command("run " + tiny() + " --generations 3 --set robots=3 --set formation=line "
                                  "--set formation_spacing=12cm --threads 2 --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(read_json(dir / "settings.json")["settings"]["formation_spacing"], "0.12 m");
  // summary.json and the export name the group.
  EXPECT_EQ(read_json(dir / "summary.json")["robots"], 3);
  const Outcome exported = esc_command("export " + dir.string() + " --format json");
  ASSERT_EQ(exported.status, 0) << exported.output;
  EXPECT_NE(exported.output.find("\"robots\": 3"), std::string::npos) << exported.output.substr(0, 400);
  const Outcome o = esc_command("replay " + dir.string() + " --controller SC");
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("identical to the stored replay"), std::string::npos) << o.output;
  fs::path stem;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".csv" && entry.path().filename().string().rfind("replay-SC-run-", 0) == 0)
      stem = entry.path().parent_path() / entry.path().stem();
  ASSERT_FALSE(stem.empty()) << o.output;

  const auto csv = read_csv(stem.string() + ".csv");
  ASSERT_GT(csv.size(), 4U);
  std::map<std::string, std::size_t> at;
  for (std::size_t i = 0; i < csv[0].size(); ++i) at[csv[0][i]] = i;
  for (const char* column : {"robot", "x_m", "y_m", "centroid_x_m", "centroid_y_m", "centroid_distance_m",
                             "nearest_robot_m", "robot_distance_m", "spread_m"})
    ASSERT_TRUE(at.count(column)) << column;
  EXPECT_EQ(at["robot"], 2U) << "after epoch and step";
  ASSERT_EQ((csv.size() - 1) % 3, 0U) << "a row per robot per step";
  const auto cell = [&](std::size_t row, const char* column) { return number(csv[row][at[column]]); };
  for (std::size_t first = 1; first < csv.size(); first += 3) {
    double cx = 0.0, cy = 0.0;
    for (std::size_t r = 0; r < 3; ++r) {
      ASSERT_EQ(csv[first + r][at["robot"]], std::to_string(r + 1));
      ASSERT_EQ(csv[first + r][1], csv[first][1]) << "one step's rows";
      cx += cell(first + r, "x_m");
      cy += cell(first + r, "y_m");
    }
    cx /= 3.0;
    cy /= 3.0;
    double spread = 0.0, pairs = 0.0;
    for (std::size_t r = 0; r < 3; ++r) {
      const double x = cell(first + r, "x_m"), y = cell(first + r, "y_m");
      double nearest = 1e9;
      for (std::size_t q = 0; q < 3; ++q) {
        if (q == r) continue;
        const double d = std::hypot(x - cell(first + q, "x_m"), y - cell(first + q, "y_m"));
        nearest = std::min(nearest, d);
        if (q > r) pairs += d;
      }
      spread = std::max(spread, std::hypot(x - cx, y - cy));
      EXPECT_NEAR(cell(first + r, "centroid_x_m"), cx, 1e-12);
      EXPECT_NEAR(cell(first + r, "centroid_y_m"), cy, 1e-12);
      EXPECT_NEAR(cell(first + r, "centroid_distance_m"), std::hypot(x - cx, y - cy), 1e-12);
      EXPECT_NEAR(cell(first + r, "nearest_robot_m"), nearest, 1e-12);
    }
    for (std::size_t r = 0; r < 3; ++r) {
      EXPECT_NEAR(cell(first + r, "robot_distance_m"), pairs / 3.0, 1e-12);
      EXPECT_NEAR(cell(first + r, "spread_m"), spread, 1e-12);
    }
  }

  const std::string svg = slurp(stem.string() + ".svg");
  EXPECT_NE(svg.find("path, by robot"), std::string::npos);
  std::size_t bodies = 0;
  for (std::size_t i = svg.find(R"(fill-opacity="0.35")"); i != std::string::npos; i = svg.find(R"(fill-opacity="0.35")", i + 1))
    ++bodies;
  EXPECT_EQ(bodies, 3U * 3U) << "every robot at the end of each of 3 epochs";
  EXPECT_NE(svg.find(", 3 robots;"), std::string::npos);

  const std::optional<std::string> dom = report_page(dir);
  if (!dom) GTEST_SKIP() << "configured without chromium (Debian package `chromium`; scripts/esc-setup.sh installs it)";
  EXPECT_NE(dom->find(">robot 3</option>"), std::string::npos);
  EXPECT_NE(dom->find("A group of 3 robots"), std::string::npos);
}

// A group of two bodies (Kheperas' discs and an e-puck's larger one): the replay draws each
// robot with its own body, and the report's panel names each robot's.
TEST(Replay, AGroupOfTwoBodiesIsDrawnEachWithItsOwn) {
  const fs::path dir = scratch("replay-two-bodies");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/two_bodies.esc";
  const Outcome run = esc_command("run " + script + " --experiment two_bodies --threads 2 --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(read_json(dir / "settings.json")["settings"]["bodies"], "khepera x 2, epuck_ir x 1");
  EXPECT_EQ(read_json(dir / "settings.json")["settings"]["body2.body_radius"], "0.037 m");
  // summary.json and the export name the bodies.
  EXPECT_EQ(read_json(dir / "summary.json")["bodies"], "khepera x 2, epuck_ir x 1");
  const Outcome exported = esc_command("export " + dir.string() + " --format json");
  ASSERT_EQ(exported.status, 0) << exported.output;
  EXPECT_NE(exported.output.find("\"bodies\": \"khepera x 2, epuck_ir x 1\""), std::string::npos)
      << exported.output.substr(0, 400);
  const Outcome o = esc_command("replay " + dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("identical to the stored replay"), std::string::npos) << o.output;
  std::string svg;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".svg" && entry.path().filename().string().rfind("replay-CC-run-01", 0) == 0)
      svg = slurp(entry.path());
  ASSERT_FALSE(svg.empty()) << o.output;
  const auto count = [&svg](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t i = svg.find(what); i != std::string::npos; i = svg.find(what, i + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count(R"(r="27.5" fill=")"), 2U * 2U) << "the Kheperas at the end of each of 2 epochs";
  EXPECT_EQ(count(R"(r="37.0" fill=")"), 2U) << "the e-puck at the end of each epoch";

  const std::optional<std::string> dom = report_page(dir);
  if (!dom) GTEST_SKIP() << "configured without chromium (Debian package `chromium`; scripts/esc-setup.sh installs it)";
  EXPECT_NE(dom->find(">robot 3 (epuck_ir)</option>"), std::string::npos);
}

// Kheperas and Thymio IIs, each body driven by its own network (a controller per body): the
// replay re-simulates it to the bit, and its CSV holds the widest body's sensors for every row.
TEST(Replay, AGroupOfBodiesReadingOtherSensorsIsReplayedWithEveryRobotsSensors) {
  const fs::path dir = scratch("replay-per-body");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/experiments/examples/mixed_bodies.esc";
  const Outcome run = esc_command("run " + script + " --experiment mixed_dispersion --runs 1 --generations 2 "
                                  "--set epochs=1 --set steps=40 --set mu=2 --set lambda=4 --threads 2 --out " +
                                  dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("khepera 8-4-2 / thymio2 7-4-2"), std::string::npos) << run.output;
  EXPECT_EQ(read_json(dir / "summary.json")["bodies"], "khepera x 3, thymio2 x 3");
  const Outcome o = esc_command("replay " + dir.string() + " --controller sc");
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("identical to the stored replay"), std::string::npos) << o.output;
  const std::string csv = slurp(dir / "replay-sc-run-01.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_NE(header.find(",ir7,light0,"), std::string::npos) << header;
  EXPECT_NE(header.find(",ground_sensor0,ground_sensor1,energy,"), std::string::npos) << header << ": the Thymio's two";
  std::set<std::string> robots;
  for (std::size_t at = csv.find('\n'); at != std::string::npos && at + 1 < csv.size(); at = csv.find('\n', at + 1)) {
    const std::size_t a = csv.find(',', csv.find(',', at + 1) + 1) + 1;
    robots.insert(csv.substr(a, csv.find(',', a) - a));
  }
  EXPECT_EQ(robots, (std::set<std::string>{"1", "2", "3", "4", "5", "6"}));
  // Its genome holds the networks in the declaration's order: a controller listing the bodies
  // the other way round has as many weights, and is refused.
  const fs::path swapped = dir / "swapped.esc";
  std::ofstream(swapped) << "import \"" << script << "\"\n"
                         << "controller cs = per_body(thymio2: sc_thymio, khepera: sc_khepera)\n"
                         << "experiment swapped { arena open_floor  robot khepera { substeps 6 } x 3, thymio2 x 3\n"
                         << "  fitness spread_out  epochs 1 x 40 steps  compare cs as sc }\n";
  const Outcome refused = esc_command("replay " + (dir / "sc" / "run-01.best.json").string() + " --script " +
                                      swapped.string() + " --experiment swapped --out " + dir.string());
  EXPECT_NE(refused.status, 0) << refused.output;
  EXPECT_NE(refused.output.find("it was evolved by `khepera 8-4-6 / thymio2 7-4-6`, and `sc` here is `thymio2 7-4-6 / "
                                "khepera 8-4-6`"),
            std::string::npos)
      << refused.output;

  const std::optional<std::string> dom = report_page(dir);
  if (!dom) GTEST_SKIP() << "configured without chromium (Debian package `chromium`; scripts/esc-setup.sh installs it)";
  EXPECT_NE(dom->find(">robot 4 (thymio2)</option>"), std::string::npos);
}

TEST(Replay, ASupervisorReadsItsEvolvedBehaviorsFromTheCacheAndNeverRunsThem) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/evolved.esc";
  const fs::path dir = scratch("replay-supervisor");
  Outcome o = esc_command("run " + script + " --experiment supervised --runs 1 --threads 2 --out " + dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  o = esc_command("replay " + dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("dependency basic: reused"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("identical to the stored replay"), std::string::npos) << o.output;
  // Without the cache the evolved behavior is unknown: an error, and nothing is run.
  fs::rename(dir / "deps", dir / "deps-elsewhere");
  o = esc_command("replay " + dir.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("experiment `basic` (needed by `supervised`) has no finished run"), std::string::npos)
      << o.output;
  EXPECT_EQ(o.output.find("running into"), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(dir / "deps"));
}

// A dependency cache entry replays from its directory: its experiment is one the stored main
// file only imports, and its own evolved behaviors are the entries beside it.
TEST(Replay, ADependencyCacheEntryBesideItsOwnDependencies) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/evolved_nested.esc";
  const fs::path dir = scratch("replay-cache-entry");
  Outcome o = esc_command("run " + script + " --threads 2 --out " + dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  std::map<std::string, fs::path> entries;
  for (const auto& e : fs::directory_iterator(dir / "deps"))
    entries[e.path().filename().string().substr(0, e.path().filename().string().find('-'))] = e.path();
  ASSERT_EQ(entries.size(), 2U);
  const fs::path out = scratch("replay-cache-entry-out");
  o = esc_command("replay " + entries.at("basic").string() + " --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("replayed CC run"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("in basic (fitness"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("identical to the stored replay"), std::string::npos) << o.output;
  o = esc_command("replay " + entries.at("supervised").string() + " --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("dependency basic: reused " + entries.at("basic").string()), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("in supervised (fitness"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("identical to the stored replay"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("running into"), std::string::npos) << o.output;
}

// A study's condition replays from its directory (STUDY/CONDITION) with the condition's own
// settings: a condition that changes the motor's time constant replays bit-identically.
TEST(Replay, AStudysConditionFromItsDirectory) {
  const fs::path study = scratch("replay-study");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tiny_study.esc";
  Outcome o = esc_command("run " + script + " --experiment tiny_study_fewer --runs 2 --generations 2 --threads 2 --out " +
                          study.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const fs::path out = scratch("replay-study-out");
  o = esc_command("replay " + (study / "time_constant=200ms").string() + " --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("in tiny (fitness"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("identical to the stored replay"), std::string::npos) << o.output;
  // Its genome files too, by default beside them; run 2's fitness is the condition's.
  o = esc_command("replay " + (study / "no_inertia" / "SC" / "run-02.best.json").string());
  ASSERT_EQ(o.status, 0) << o.output;
  const auto rows = read_csv(study / "no_inertia" / "SC" / "replay-SC-run-02.csv");
  ASSERT_GT(rows.size(), 1U);
  const auto summary = read_json(study / "summary.json");
  for (const auto& c : summary["conditions"]) {
    if (c["name"] != "no_inertia") continue;
    EXPECT_EQ(number(rows.back()[rows.front().size() - 2]), c["controllers"]["SC"]["runs"][1]["best_fitness"].get<double>());
  }
  // The study's own directory names no condition; an unknown one is named.
  o = esc_command("replay " + study.string());
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("holds study `tiny_study_fewer`: replay one of its conditions"), std::string::npos) << o.output;
  o = esc_command("replay " + (study / "time_constant=100ms").string());
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("time_constant=100ms is not a condition of the study `tiny_study_fewer`"), std::string::npos)
      << o.output;
}

// A controller's directory of a plain run is not a condition: the message says how to
// replay that controller.
TEST(Replay, AControllersDirectoryNamesTheControllerOption) {
  const fs::path dir = tiny_run();
  const Outcome o = esc_command("replay " + (dir / "SC").string());
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("holds controller SC's files: esc replay " + dir.string() + " --controller SC"),
            std::string::npos)
      << o.output;
}

// A genome file named relative to where esc runs, from the run's directory and from the
// controller's, replays as from anywhere (both were refused: the relative path had no
// directories to climb).
TEST(Replay, AGenomeFileNamedFromInsideTheRun) {
  const fs::path dir = tiny_run();
  for (const auto& [where, file] : {std::pair{dir, std::string("SC/run-01.best.json")},
                                    std::pair{dir / "SC", std::string("run-01.best.json")}}) {
    const fs::path out = scratch("replay-inside-" + where.filename().string());
    const Outcome o = cli_test::shell("cd " + where.string() + " && " + std::string(ESC_BINARY) + " replay " + file +
                                      " --out " + out.string());
    EXPECT_EQ(o.status, 0) << o.output;
    EXPECT_NE(o.output.find("esc: replayed SC run 1 in tiny (fitness "), std::string::npos) << o.output;
    EXPECT_TRUE(fs::exists(out / "replay-SC-run-01.svg"));
  }
}

// A genome file carries a checksum of what a replay uses: a gene changed in the last digit
// is refused, never replayed as if it were the run's.
TEST(Replay, ADamagedGenomeFileIsRefused) {
  const fs::path dir = tiny_run();
  const nlohmann::json intact = read_json(dir / "CC" / "run-01.best.json");
  ASSERT_TRUE(intact.contains("checksum"));
  const fs::path copies = scratch("replay-damaged");
  fs::create_directories(copies);
  std::ofstream(copies / "intact.json") << intact.dump(1);
  nlohmann::json damaged = intact;
  damaged["genome"][0] = std::nextafter(intact["genome"][0].get<double>(), 2.0);
  std::ofstream(copies / "damaged.json") << damaged.dump(1);
  const std::string elsewhere = " --script " + tiny() + " --out " + copies.string();
  Outcome o = esc_command("replay " + (copies / "intact.json").string() + elsewhere);
  EXPECT_EQ(o.status, 0) << o.output;
  o = esc_command("replay " + (copies / "damaged.json").string() + elsewhere);
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("damaged.json is damaged: its genome, fitness or seed does not match its checksum"),
            std::string::npos)
      << o.output;
}

TEST(Replay, BadChoicesAreErrors) {
  const fs::path dir = tiny_run();
  Outcome o = esc_command("replay " + dir.string() + " --epochs 0");
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("between 1 and 3"), std::string::npos) << o.output;
  o = esc_command("replay " + dir.string() + " --epochs 3-2");
  EXPECT_EQ(o.status, 2) << o.output;
  o = esc_command("replay " + dir.string() + " --controller SX");
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("did you mean `SC`?"), std::string::npos) << o.output;
  o = esc_command("replay " + dir.string() + " --run 9");
  EXPECT_EQ(o.status, 1) << o.output;
  o = esc_command("replay " + scratch("not-a-run").string());
  EXPECT_EQ(o.status, 1) << o.output;
  o = esc_command("replay " + (dir / "CC" / "run-01.best.json").string() + " --script " + tiny() + " --experiment nope");
  EXPECT_EQ(o.status, 1) << o.output;
}

}  // namespace
