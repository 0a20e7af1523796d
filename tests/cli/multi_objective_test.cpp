// Several objectives and behavior descriptors from the command line: NSGA-II
// (experiments/examples/speed_energy.esc) and MAP-Elites (behavior_map.esc) run, store their
// metrics, fronts and archives every generation, give the same results on any number of
// threads, and a run killed mid-run resumes to exactly the unbroken run, Lehman & Stanley's
// maze study too, whose fronts and archives export, draw and replay.
#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <sys/resource.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

std::string example(const std::string& name) {
  return std::string(ESC_SOURCE_DIR) + "/experiments/examples/" + name + ".esc";
}

// metric -> run -> its values by generation, from `esc export --table metrics`.
std::map<std::string, std::map<std::string, std::vector<double>>> metrics_of(const fs::path& dir) {
  const Outcome o = esc("export " + dir.string() + " --table metrics");
  EXPECT_EQ(o.status, 0) << o.output;
  std::map<std::string, std::map<std::string, std::vector<double>>> m;
  std::stringstream in(o.output);
  std::string line;
  std::getline(in, line);   // experiment,condition,controller,algorithm,run,generation,metric,value
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) f.push_back(c);
    if (f.size() == 8) m[f[6]][f[4]].push_back(std::stod(f[7]));
  }
  return m;
}

// The generations whose front `esc export --table front` holds, per run (from 1).
std::map<std::string, std::set<int>> front_generations(const fs::path& dir) {
  const Outcome front = esc("export " + dir.string() + " --table front");
  EXPECT_EQ(front.status, 0) << front.output;
  const auto rows = csv_rows(front.output);
  std::map<std::string, std::set<int>> out;
  for (std::size_t i = 1; i < rows.size(); ++i) out[rows[i][4]].insert(std::stoi(rows[i][5]));
  return out;
}

TEST(MultiObjective, MapElitesStoresItsArchiveMetricsEveryGeneration) {
  const fs::path dir = scratch("map-elites");
  const Outcome o = esc("run " + example("behavior_map") + " --runs 2 --generations 6 --set epochs=1 --out " +
                        dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const auto m = metrics_of(dir);
  ASSERT_EQ(m.at("qd_score").size(), 2u);
  for (const auto& [run, qd] : m.at("qd_score")) {
    ASSERT_EQ(qd.size(), 6u) << run;
    for (std::size_t g = 1; g < qd.size(); ++g) EXPECT_GE(qd[g], qd[g - 1]) << "an elite is only ever replaced by a better one";
    EXPECT_GT(qd.back(), 0.0);
    const std::vector<double>& coverage = m.at("coverage").at(run);
    EXPECT_GT(coverage.back(), 0.0);
    EXPECT_LE(coverage.back(), 1.0);
  }
}

TEST(MultiObjective, AnArchiveLargerThanMemoryIsRefusedBeforeTheRun) {
  const fs::path out = scratch("map-elites-huge");
  // 10,000 x 10,000 cells, about 6.5 GB of slots before any elite, under an address-space
  // limit of 4 GB that esc inherits (so the test does not depend on the machine's memory).
  rlimit before{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &before), 0);
  rlimit limited = before;
  limited.rlim_cur = std::min<rlim_t>(before.rlim_max, rlim_t{4} << 30);
  ASSERT_EQ(setrlimit(RLIMIT_AS, &limited), 0);
  const Outcome o = esc("run " + example("behavior_map") + " --set map_elites.bins=10000 --out " + out.string());
  ASSERT_EQ(setrlimit(RLIMIT_AS, &before), 0);
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("(MAP-Elites' archive of 100000000 cells (10000 bins per descriptor) for `CC_8_2`: "),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find(": lower `map_elites.bins`"), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(out)) << "refused before the run directory is made";
}

TEST(MultiObjective, NsgaIiStoresItsFrontAndHypervolumeEveryGeneration) {
  const fs::path dir = scratch("nsga2");
  const Outcome o = esc("run " + example("speed_energy") + " --runs 2 --generations 4 --set epochs=1 --out " +
                        dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const auto m = metrics_of(dir);
  for (const auto& [run, hv] : m.at("hypervolume")) {
    ASSERT_EQ(hv.size(), 4u) << run;
    // The reference is the worst corner of the declared ranges: 0 speed, 450 effort.
    for (const double v : hv) {
      EXPECT_GT(v, 0.0);
      EXPECT_LE(v, 450.0 * 450.0);
    }
    for (const double f : m.at("front").at(run)) {
      EXPECT_GE(f, 1.0);
      EXPECT_LE(f, 40.0);   // the population
    }
  }
}

// A front is stored at the multiples of `members_every` and at each run's last generation
// (a front that had not changed would not be stored again: these change every time), and
// what reads it reads the run's last: the report's fronts, a member's replay.
TEST(MultiObjective, AFrontIsStoredEveryMembersEveryGenerationsAndAtTheEnd) {
  const fs::path dir = scratch("members-every-7");
  const Outcome o = esc("run " + example("speed_energy") +
                        " --runs 2 --generations 23 --set epochs=1 --set members_every=7 --threads 1 --out " +
                        dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const auto stored = front_generations(dir);
  ASSERT_EQ(stored.size(), 2u);
  for (const auto& [run, generations] : stored) EXPECT_EQ(generations, (std::set<int>{0, 7, 14, 21, 22})) << run;
  EXPECT_EQ(read_json(dir / "settings.json")["settings"]["members_every"], "7");
  // The metrics (the front's size among them) stay per generation.
  EXPECT_EQ(metrics_of(dir).at("front").at("1").size(), 23u);
  const Outcome report = esc("report " + dir.string());
  ASSERT_EQ(report.status, 0) << report.output;
  bool pareto = false;
  for (const auto& f : fs::directory_iterator(dir / "figures"))
    pareto = pareto || f.path().filename().string().ends_with("-front.svg");
  EXPECT_TRUE(pareto);
  const Outcome replayed = esc("replay " + dir.string() + " --run 2 --member 0");
  EXPECT_EQ(replayed.status, 0) << replayed.output;

  const fs::path plain = scratch("members-every-default");
  ASSERT_EQ(esc("run " + example("speed_energy") + " --runs 1 --generations 12 --set epochs=1 --threads 1 --out " +
                plain.string())
                .status,
            0);
  EXPECT_EQ(front_generations(plain).at("1"), (std::set<int>{0, 10, 11}));
  EXPECT_FALSE(read_json(plain / "settings.json")["settings"].contains("members_every"));
  const Outcome bad = esc("run " + example("speed_energy") + " --set members_every=0 --out " + scratch("m0").string());
  EXPECT_EQ(bad.status, 1) << bad.output;
  EXPECT_NE(bad.output.find("members_every=0: `members_every` must be at least 1, found 0"), std::string::npos)
      << bad.output;
}

// Random start poses: an archive cell or a front member measures what it measured only in
// its own evaluation, whose seed the replay derives from where the optimizer's state says it
// was evaluated (not the run's best's, which starts elsewhere).
TEST(MultiObjective, AMemberReplaysInItsOwnEvaluation) {
  for (const auto& [name, member] : {std::pair<std::string, std::string>{"behavior_map", ""}, {"speed_energy", "0"}}) {
    const fs::path dir = scratch("member-seed-" + name);
    ASSERT_EQ(esc("run " + example(name) + " --runs 1 --generations 4 --set epochs=1 --out " + dir.string()).status, 0);
    std::string pick = member;
    if (pick.empty()) {   // the archive's first filled cell
      const Outcome archive = esc("export " + dir.string() + " --table archive");
      const auto rows = csv_rows(archive.output);
      ASSERT_GT(rows.size(), 1u) << archive.output;
      const auto cell = std::find(rows.front().begin(), rows.front().end(), "cell") - rows.front().begin();
      pick = rows[1][static_cast<std::size_t>(cell)];
    }
    const Outcome replayed = esc("replay " + dir.string() + " --member " + pick);
    EXPECT_EQ(replayed.status, 0) << replayed.output;
    EXPECT_NE(replayed.output.find(", as in its own evaluation)"), std::string::npos) << replayed.output;
    EXPECT_EQ(replayed.output.find("in its own evaluation;"), std::string::npos) << replayed.output;
    // Another seed is another evaluation: no claim to match it.
    const Outcome elsewhere = esc("replay " + dir.string() + " --member " + pick + " --seed 12345");
    EXPECT_EQ(elsewhere.status, 0) << elsewhere.output;
    EXPECT_EQ(elsewhere.output.find("as in its own evaluation"), std::string::npos) << elsewhere.output;
  }
}

TEST(MultiObjective, AnyNumberOfThreadsGivesTheSameResults) {
  for (const std::string name : {"behavior_map", "speed_energy"}) {
    const fs::path one = scratch(name + "-1"), two = scratch(name + "-2");
    const std::string run = "run " + example(name) + " --runs 2 --generations 3 --set epochs=1 --threads ";
    ASSERT_EQ(esc(run + "1 --out " + one.string()).status, 0);
    ASSERT_EQ(esc(run + "2 --runs-at-once 2 --out " + two.string()).status, 0);
    expect_same_results(one, two, {name == "behavior_map" ? "CC_8_2" : "C"}, 2);
    for (const std::string table : {"metrics", "front", "archive"})
      EXPECT_EQ(esc("export " + one.string() + " --table " + table).output,
                esc("export " + two.string() + " --table " + table).output)
          << name << " " << table;
  }
}

TEST(MultiObjective, ARunKilledMidRunResumesToTheUnbrokenRun) {
  for (const std::string name : {"behavior_map", "speed_energy"}) {
    const fs::path reference = scratch(name + "-reference"), killed = scratch(name + "-killed");
    const std::vector<std::string> shorter{"--set", "epochs=1"};
    ASSERT_EQ(esc("run " + example(name) + " --generations 100 --seed 5 --set epochs=1 --threads 1 --out " +
                  reference.string())
                  .status,
              0);
    ASSERT_NO_FATAL_FAILURE(run_killed_halfway(example(name), killed, 30, 300, "2", shorter));
    const Outcome resumed = esc("run --resume " + killed.string() + " --threads 1");
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    expect_same_results(reference, killed, {name == "behavior_map" ? "CC_8_2" : "C"}, 3);
    for (const std::string table : {"metrics", "front", "archive"})
      EXPECT_EQ(esc("export " + reference.string() + " --table " + table).output,
                esc("export " + killed.string() + " --table " + table).output)
          << name << " " << table;
    // Its fronts are stored every 10 generations and at the end, wherever the kill fell
    // between them: the resumed run stored the same rows (above).
    if (name == "speed_energy") {
      for (const auto& [run, generations] : front_generations(reference))
        for (const int g : generations) EXPECT_TRUE(g % 10 == 0 || g == 99) << run << " " << g;
    }
  }
}

// Lehman & Stanley's medium maze: one study of CMA-ES, novelty search (alone and with the
// fitness) and MAP-Elites, killed mid-study, resumes to exactly the unbroken study.
TEST(MultiObjective, TheMazeStudyKilledMidStudyResumesToTheUnbrokenStudy) {
  const std::string mazes = std::string(ESC_SOURCE_DIR) + "/experiments/lehman_stanley/mazes.esc";
  const fs::path reference = scratch("maze-reference"), killed = scratch("maze-killed");
  ASSERT_EQ(esc("run " + mazes + " --runs 2 --generations 100 --seed 5 --set steps=30 --threads 1 --out " +
                reference.string())
                .status,
            0);
  // 4 conditions x 2 runs x 100 generations.
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(mazes, killed, 150, 800, "2", {"--runs", "2", "--set", "steps=30"}));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_EQ(results_without_times(reference), results_without_times(killed));
  for (const std::string table : {"metrics", "front", "archive"})
    EXPECT_EQ(esc("export " + reference.string() + " --table " + table).output,
              esc("export " + killed.string() + " --table " + table).output)
        << table;
  // The mazes declare success: every run's evaluations to success (none reach the goal in 30
  // steps) and each method's count resume as they were.
  const std::string summary = slurp(reference / "summary.json");
  EXPECT_EQ(summary, slurp(killed / "summary.json"));
  EXPECT_NE(summary.find("\"success\": \"reach_goal > -0.0171875\""), std::string::npos);
}

// Every method of the maze study at a few generations: MAP-Elites' archive and novelty
// search's front (novelty and fitness) and archive (novelty alone) are exported per
// generation, the report draws the archive as a heatmap and the front as a Pareto plot, and
// an archive's cell or a front's member replays.
TEST(MultiObjective, TheMazeStudyExportsDrawsAndReplaysItsFrontsAndArchives) {
  const std::string mazes = std::string(ESC_SOURCE_DIR) + "/experiments/lehman_stanley/mazes.esc";
  const fs::path dir = scratch("maze-members");
  const Outcome ran = esc("run " + mazes + " --runs 2 --generations 3 --set steps=40 --out " + dir.string());
  ASSERT_EQ(ran.status, 0) << ran.output;
  // Fitness in metres below 1 keeps three significant digits in the end table (not -0.5 ± 0.0).
  const std::regex three_digits(R"(\nfitness_based +-0\.\d{3} ± 0\.\d{3} \(-0\.\d{3}\)\n)");
  EXPECT_TRUE(std::regex_search(ran.output, three_digits)) << ran.output;

  const Outcome archive = esc("export " + dir.string() + " --table archive");
  ASSERT_EQ(archive.status, 0) << archive.output;
  const auto rows = csv_rows(archive.output);
  ASSERT_GT(rows.size(), 1u);
  const std::vector<std::string>& header = rows.front();
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  ASSERT_LT(column("final_y"), header.size()) << archive.output.substr(0, 200);
  ASSERT_LT(column("reach_goal"), header.size());
  // MAP-Elites' archive after the last generation (each cell's last row) is as full as its
  // coverage says; novelty search archived behaviors without fitness.
  std::map<std::string, std::map<std::string, std::string>> last;   // run -> cell -> generation
  std::size_t novelty_rows = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& r = rows[i];
    ASSERT_EQ(r.size(), header.size()) << i;
    if (r[column("algorithm")] == "map_elites") {
      EXPECT_LT(std::stoi(r[column("cell")]), 400);
      EXPECT_FALSE(r[column("reach_goal")].empty());
      last[r[column("run")]][r[column("cell")]] = r[column("generation")];
    } else {
      EXPECT_EQ(r[column("algorithm")], "novelty");
      EXPECT_TRUE(r[column("reach_goal")].empty()) << "novelty search keeps behaviors alone";
      ++novelty_rows;
    }
  }
  EXPECT_GT(novelty_rows, 0u);
  const auto metrics = metrics_of(dir);
  ASSERT_EQ(last.size(), 2u);
  for (const auto& [run, cells] : last)
    EXPECT_DOUBLE_EQ(static_cast<double>(cells.size()) / 400.0, metrics.at("coverage").at(run).back()) << run;

  const Outcome front = esc("export " + dir.string() + " --table front");
  ASSERT_EQ(front.status, 0);
  const auto front_rows = csv_rows(front.output);
  ASSERT_GT(front_rows.size(), 1u);
  EXPECT_EQ(front_rows.front(), (std::vector<std::string>{"experiment", "condition", "controller", "algorithm", "run",
                                                          "generation", "cell", "novelty", "reach_goal", "final_x",
                                                          "final_y"}));

  const Outcome report = esc("report " + dir.string());
  ASSERT_EQ(report.status, 0) << report.output;
  std::string heatmap, pareto;
  for (const auto& f : fs::directory_iterator(dir / "figures")) {
    const std::string name = f.path().filename().string();
    if (name.ends_with("-archive.svg") && name.find("map_elites") != std::string::npos) heatmap = slurp(f.path());
    if (name.ends_with("-front.svg")) pareto = slurp(f.path());
  }
  EXPECT_NE(heatmap.find("archive (grid)"), std::string::npos);
  EXPECT_NE(heatmap.find("of 400 cells filled"), std::string::npos);
  EXPECT_NE(pareto.find("Pareto fronts"), std::string::npos);
  EXPECT_NE(slurp(dir / "report.html").find("archive (grid)"), std::string::npos);

  const std::string cell = last.at("1").begin()->first;
  const Outcome replayed = esc("replay " + (dir / "map_elites").string() + " --run 1 --member " + cell);
  ASSERT_EQ(replayed.status, 0) << replayed.output;
  EXPECT_NE(replayed.output.find("run 1 cell " + cell), std::string::npos) << replayed.output;
  EXPECT_TRUE(fs::exists(dir / "map_elites" / ("replay-navigator_net-run-01-cell-" + cell + ".svg")));
  // What the navigator senses is in its replay: the CSV's and the report's rangefinders and radars.
  const std::string csv = slurp(dir / "map_elites" / ("replay-navigator_net-run-01-cell-" + cell + ".csv"));
  EXPECT_NE(csv.find(",light7,range0,range1,range2,range3,range4,range5,radar0,radar1,radar2,radar3,energy,"),
            std::string::npos)
      << csv.substr(0, 300);
  EXPECT_NE(slurp(dir / "report.html").find(R"("light","range","radar"])"), std::string::npos);
  const Outcome member = esc("replay " + (dir / "novelty_fitness").string() + " --run 2 --member 0");
  EXPECT_EQ(member.status, 0) << member.output;
  const Outcome empty = esc("replay " + (dir / "map_elites").string() + " --run 1 --member 399");
  if (!last.at("1").contains("399")) {
    EXPECT_EQ(empty.status, 1);
    EXPECT_NE(empty.output.find("cell 399 of navigator_net run 1's archive is empty"), std::string::npos) << empty.output;
  }
  // A 20 x 20 grid has cells 0-399: 400 is no cell, not an empty one.
  const Outcome outside = esc("replay " + (dir / "map_elites").string() + " --run 1 --member 400");
  EXPECT_EQ(outside.status, 1);
  EXPECT_NE(outside.output.find("archive has no cell 400: its cells are numbered 0-399"), std::string::npos)
      << outside.output;
  const Outcome behaviors = esc("replay " + (dir / "novelty").string() + " --member 0");
  EXPECT_EQ(behaviors.status, 1);
  EXPECT_NE(behaviors.output.find("keeps behaviors, not the genomes"), std::string::npos) << behaviors.output;
}

}  // namespace
