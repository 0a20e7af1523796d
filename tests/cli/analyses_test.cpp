// Section 4's analyses, end to end through `esc`: behavior usage per generation (stored as
// the run goes, exported as a tidy table, in summary.json), a fitness that reads the acting
// behavior, trees where networks go (supervised, started from, evaluated), and the
// generalization figures of a transferred controller.
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"

namespace {

using namespace cli_test;
using nlohmann::json;

std::string data(const std::string& file) { return std::string(ESC_SOURCE_DIR) + "/tests/cli/data/" + file; }

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

std::string best_file(int run) {
  char name[32];
  std::snprintf(name, sizeof name, "run-%02d.best.json", run);
  return name;
}

// The usage table's rows, keyed by column name.
std::vector<std::map<std::string, std::string>> usage_rows(const fs::path& dir) {
  const Outcome o = esc("export " + dir.string() + " --table usage");
  EXPECT_EQ(o.status, 0) << o.output;
  std::stringstream in(o.output);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header,
            "experiment,condition,controller,run,generation,behavior,best_steps,mean_steps,steps_total,library,useless");
  const std::vector<std::string> columns = split(header);
  std::vector<std::map<std::string, std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> cells = split(line);
    EXPECT_EQ(cells.size(), columns.size()) << line;
    auto& row = rows.emplace_back();
    for (std::size_t i = 0; i < cells.size() && i < columns.size(); ++i) row[columns[i]] = cells[i];
  }
  return rows;
}

// A paper script (`ARGS`: its file under experiments/paper and options) at a small size: one
// epoch of 60 steps, (2, 6)-ES, into `dir`.
Outcome run_small(const std::string& args, const fs::path& dir) {
  return esc("run " + std::string(ESC_SOURCE_DIR) + "/experiments/paper/" + args +
             " --set epochs=1 --set steps=60 --set mu=2 --set lambda=6 --threads 2 --out " + dir.string());
}

TEST(Analyses, TheUsageTableHasARowPerRunGenerationAndBehavior) {
  const fs::path dir = scratch("usage-table");
  const Outcome run = run_small("energy.esc --runs 2 --generations 2", dir);
  ASSERT_EQ(run.status, 0) << run.output;
  const auto rows = usage_rows(dir);
  // SC: 3 actions, CS and SS: 4 behaviors each; CC chooses nothing. 2 runs x 2 generations.
  std::map<std::string, std::size_t> per_controller;
  std::map<std::string, std::int64_t> sums, totals;
  for (const auto& r : rows) {
    ++per_controller[r.at("controller")];
    const std::string key = r.at("controller") + "/" + r.at("run") + "/" + r.at("generation");
    sums[key] += std::stoll(r.at("best_steps"));
    totals[key] = std::stoll(r.at("steps_total"));
    EXPECT_EQ(r.at("experiment"), "energy");
    EXPECT_EQ(r.at("condition"), "");   // a plain experiment
    // The library each behavior comes from, none for the SC's actions; nothing is useless here.
    const std::string library = r.at("controller") == "SC"   ? ""
                                : r.at("controller") == "CS" ? "classical_behaviors"
                                                             : "symbolic_behaviors";
    EXPECT_EQ(r.at("library"), library) << r.at("controller") << " " << r.at("behavior");
    EXPECT_EQ(r.at("useless"), "0");
  }
  EXPECT_EQ(per_controller.count("CC"), 0u);
  EXPECT_EQ(per_controller["SC"], 2u * 2u * 3u);
  EXPECT_EQ(per_controller["CS"], 2u * 2u * 4u);
  EXPECT_EQ(per_controller["SS"], 2u * 2u * 4u);
  // The best evaluation's steps are shared out among its behaviors.
  for (const auto& [key, sum] : sums) {
    EXPECT_EQ(sum, totals[key]) << key;
    EXPECT_GT(totals[key], 0) << key;
  }
  // The run's best evaluation, replayed at its end, is its generation's best: its counts are
  // that generation's.
  const json summary = read_json(dir / "summary.json");
  for (const char* controller : {"SC", "CS", "SS"})
    for (const json& r : summary["controllers"][controller]["runs"]) {
      const json best = read_json(dir / controller / best_file(r["run"].get<int>()));
      const int g = best["generation"].get<int>();
      const json& usage = r["usage"];
      ASSERT_EQ(usage["behaviors"].size(), r["behavior_usage"].size());
      for (std::size_t b = 0; b < usage["behaviors"].size(); ++b)
        EXPECT_EQ(usage["best_steps"][static_cast<std::size_t>(g)][b],
                  r["behavior_usage"][usage["behaviors"][b].get<std::string>()])
            << controller << " run " << r["run"] << " behavior " << usage["behaviors"][b];
    }
}

// A library marked `useless` is named in every row of its behaviors, with useless 1: what a
// script needs to follow their usage over the generations (the paper's sensitivity analysis).
TEST(Analyses, TheUsageTableMarksUselessBehaviors) {
  const fs::path dir = scratch("usage-useless");
  const Outcome run = run_small("sensitivity.esc --experiment behaviors_8 --runs 1 --generations 1", dir);
  ASSERT_EQ(run.status, 0) << run.output;
  std::map<std::string, std::pair<std::string, std::string>> marked;   // behavior -> (library, useless)
  for (const auto& r : usage_rows(dir))
    marked[r.at("controller") + "/" + r.at("behavior")] = {r.at("library"), r.at("useless")};
  ASSERT_EQ(marked.size(), 16u);   // CS and SS, 8 behaviors each
  for (const char* useful : {"avoid", "follow", "stop", "sweep"}) {
    EXPECT_EQ(marked[std::string("CS/") + useful].first, "classical_behaviors");
    EXPECT_EQ(marked[std::string("SS/") + useful].first, "symbolic_behaviors");
    EXPECT_EQ(marked[std::string("CS/") + useful].second, "0");
    EXPECT_EQ(marked[std::string("SS/") + useful].second, "0");
  }
  for (const char* useless : {"random", "avoid_light", "crash", "stick_to_walls"})
    for (const char* controller : {"CS/", "SS/"})
      EXPECT_EQ(marked[std::string(controller) + useless], std::make_pair(std::string("useless"), std::string("1")))
          << controller << useless;
}

TEST(Analyses, AStudysUsageRowsNameTheirCondition) {
  const fs::path dir = scratch("usage-study");
  const Outcome run = esc("run " + data("tiny_study.esc") + " --experiment tiny_study_fewer --runs 1 --generations 1 "
                          "--set epochs=1 --threads 2 --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  std::map<std::string, std::size_t> per_condition;
  for (const auto& r : usage_rows(dir)) {
    EXPECT_EQ(r.at("controller"), "SC");   // CC chooses nothing
    ++per_condition[r.at("condition")];
  }
  const json summary = read_json(dir / "summary.json");
  ASSERT_EQ(per_condition.size(), summary["conditions"].size());
  for (const json& c : summary["conditions"]) EXPECT_EQ(per_condition[c["name"].get<std::string>()], 3u) << c["name"];
}

TEST(Analyses, AFitnessOfUsingIsTheUsageCount) {
  const fs::path dir = scratch("using-fitness");
  const Outcome run = esc("run " + data("behavior_use.esc") + " --experiment counted --threads 2 --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const json summary = read_json(dir / "summary.json");
  int nonzero = 0;
  for (const char* controller : {"SC", "SV"})
    for (const json& r : summary["controllers"][controller]["runs"]) {
      const json& usage = r["usage"];
      const auto& behaviors = usage["behaviors"];
      std::size_t left = 0;
      while (left < behaviors.size() && behaviors[left].get<std::string>().rfind("left", 0) != 0) ++left;
      ASSERT_LT(left, behaviors.size());
      // The best evaluation of a generation is the one that used `left` most: its fitness.
      for (std::size_t g = 0; g < r["best"].size(); ++g) {
        EXPECT_EQ(r["best"][g].get<double>(), usage["best_steps"][g][left].get<double>()) << controller << " " << g;
        nonzero += r["best"][g].get<double>() > 0.0 ? 1 : 0;
      }
    }
  EXPECT_GT(nonzero, 0);
}

TEST(Analyses, TheConstraintOnBehaviorUseRunsAndIsResolved) {
  const fs::path dir = scratch("constrained-use");
  const Outcome run =
      esc("run " + data("behavior_use.esc") + " --experiment constrained_use --threads 2 --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const json settings = read_json(dir / "settings.json");
  EXPECT_EQ(settings["settings"]["fitness.epoch"], "-100 * abs(share(left) - 0.1)");
  EXPECT_FALSE(settings["settings"].contains("fitness.evaluation"));
  EXPECT_EQ(read_json(dir / "summary.json")["controllers"].size(), 2u);
}

TEST(Analyses, ASupervisorOverAnEvolvedTreeRuns) {
  const fs::path dir = scratch("over-trees");
  const Outcome run =
      esc("run " + data("trees_everywhere.esc") + " --experiment over_trees --threads 2 --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("controller GW frozen with the best genome"), std::string::npos) << run.output;
  const json summary = read_json(dir / "summary.json");
  for (const char* controller : {"SV", "TV"}) {
    const json& runs = summary["controllers"][controller]["runs"];
    ASSERT_EQ(runs.size(), 2u) << controller;
    EXPECT_TRUE(runs[0]["behavior_usage"].contains("evolved_gw")) << runs[0].dump();
  }
  // The cached dependency serves the next run, the frozen tree identical.
  const Outcome again = esc("run " + data("trees_everywhere.esc") + " --experiment over_trees --threads 1 --cache " +
                            (dir / "deps").string() + " --out " + (dir / "again").string());
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("esc: dependency trees: reused"), std::string::npos) << again.output;
  EXPECT_EQ(read_json(dir / "summary.json")["controllers"], read_json(dir / "again" / "summary.json")["controllers"]);
}

TEST(Analyses, TreesStartFromAndAreEvaluatedFromStoredTrees) {
  const fs::path dir = scratch("trees-transferred");
  const fs::path cache = dir / "cache";
  const Outcome onwards = esc("run " + data("trees_everywhere.esc") + " --experiment trees_onwards --threads 2 --cache " +
                              cache.string() + " --out " + (dir / "onwards").string());
  ASSERT_EQ(onwards.status, 0) << onwards.output;
  EXPECT_NE(onwards.output.find("from experiment trees"), std::string::npos) << onwards.output;
  const Outcome again = esc("run " + data("trees_everywhere.esc") + " --experiment trees_again --threads 2 --cache " +
                            cache.string() + " --out " + (dir / "again").string());
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("esc: dependency trees: reused"), std::string::npos) << again.output;
  const json origin = read_json(fs::directory_iterator(cache)->path() / "summary.json");
  std::map<std::string, std::vector<double>> origin_best;
  for (const auto& [name, c] : origin["controllers"].items())
    for (const json& r : c["runs"]) origin_best[name].push_back(r["best_fitness"].get<double>());
  // A fixed start pose: the stored tree scores here exactly what it scored there.
  for (const auto& [name, c] : read_json(dir / "onwards" / "summary.json")["controllers"].items())
    for (const json& r : c["runs"]) {
      const json& t = r["transfer"];
      const std::size_t from = static_cast<std::size_t>(t["origin_run"].get<int>() - 1);
      EXPECT_EQ(t["experiment"], "trees");
      EXPECT_EQ(t["origin_fitness"].get<double>(), origin_best[name].at(from));
      EXPECT_EQ(t["fitness_here"].get<double>(), t["origin_fitness"].get<double>()) << name;
      EXPECT_EQ(t["change_percent"].get<double>(), 0.0);
      EXPECT_EQ(t["regained_at_generation"], 0);
      EXPECT_GE(r["best"][0].get<double>(), t["origin_fitness"].get<double>());
    }
  const json evaluated = read_json(dir / "again" / "summary.json");
  const json& runs = evaluated["controllers"]["GW"]["runs"];
  ASSERT_EQ(runs.size(), 3u);
  for (const json& r : runs) {
    EXPECT_EQ(r["best"].size(), 1u);
    EXPECT_EQ(r["best_fitness"], r["transfer"]["origin_fitness"]);
    EXPECT_FALSE(r["transfer"].contains("regained_at_generation"));
  }
  EXPECT_EQ(runs[2]["transfer"]["origin_run"], 1);   // 3 runs from 2: run 3 takes run 1's tree
}

TEST(Analyses, TheEndTableAndTheReportShowTheChangeFromTheOrigin) {
  const fs::path dir = scratch("generalization-table");
  const std::string script = data("start_from.esc");
  const Outcome o = esc("run " + script + " --experiment onwards --threads 2 --out " + dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("from experiment basic"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("regained"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("+0.0%"), std::string::npos) << o.output;   // same setting, fixed start: no change
  EXPECT_NE(o.output.find("loss made up"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("n/a  3 of 3 runs"), std::string::npos) << o.output;   // nothing lost, nothing to make up
  const Outcome report = esc("report " + dir.string());
  ASSERT_EQ(report.status, 0) << report.output;
  const std::string page = slurp(dir / "report.html");
  EXPECT_NE(page.find("\"transfers\":{\"origin\":\"basic\""), std::string::npos);
  EXPECT_NE(page.find("\"loss_regained_pooled\":null"), std::string::npos);
}

}  // namespace
