// Golden results: every experiment of every shipped script, run short, must give exactly
// the per-generation results recorded in tests/golden/*.json (best, mean and sd of every
// generation of every run, and each run's best fitness), bit for bit. A refactoring or an
// optimisation that moves any of them fails here; a deliberate change of results is
// recorded by running this test with ESC_UPDATE_GOLDEN=1 (which rewrites the files), a bump
// of eval::kResultsRevision and a paragraph in docs/decisions.md.
//
// Each file names its script, experiment (or study) and command-line arguments; to cover a
// new experiment, add a file with those three and an empty "controllers" object (a study:
// an empty "conditions" object), then update. A study's file holds, per condition, what an
// experiment's holds.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"

namespace {

using namespace cli_test;
using nlohmann::json;

fs::path golden_dir() { return fs::path(ESC_SOURCE_DIR) / "tests" / "golden"; }

std::vector<std::string> golden_files() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(golden_dir()))
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Each run's per-generation sd, which summary.json does not keep, from `esc export --format
// json`: by condition ("" for an experiment), controller, then run.
json sds_of(const fs::path& out) {
  const Outcome o = esc("export " + out.string() + " --format json");
  EXPECT_EQ(o.status, 0) << o.output;
  const json doc = json::parse(o.output);
  json by = json::object();
  for (const json& e : doc.at("experiments")) {
    const std::string where = e.value("condition", "");
    for (const auto& [name, c] : e.at("controllers").items()) {
      json runs = json::array();
      for (const json& r : c.at("runs")) {
        json sd = json::array();
        for (const json& g : r.at("generations")) sd.push_back(g.at("sd"));
        runs.push_back(std::move(sd));
      }
      by[where][name] = std::move(runs);
    }
  }
  return by;
}

// The results proper of a summary.json's controllers: per controller, per run, the fitness
// figures (`sds`: the condition's sd arrays, by controller and run).
json results_of(const json& controllers, const json& sds) {
  json out = json::object();
  for (const auto& [name, c] : controllers.items()) {
    json runs = json::array();
    for (std::size_t i = 0; i < c.at("runs").size(); ++i) {
      const json& r = c.at("runs")[i];
      runs.push_back({{"best_fitness", r.at("best_fitness")}, {"best", r.at("best")}, {"mean", r.at("mean")},
                      {"sd", sds.at(name).at(i)}});
    }
    out[name] = runs;
  }
  return out;
}

// An experiment's results, or a study's: its conditions' by name.
json summary_results(const json& summary, const json& sds) {
  if (!summary.contains("conditions")) return results_of(summary.at("controllers"), sds.at(""));
  json out = json::object();
  for (const json& c : summary.at("conditions")) {
    const std::string name = c.at("name").get<std::string>();
    out[name] = results_of(c.at("controllers"), sds.at(name));
  }
  return out;
}

// Controller by controller, element by element, so that a failure names the first
// generation that moved.
void expect_same(const json& want, const json& got, const std::string& where) {
  ASSERT_EQ(want.size(), got.size()) << where << "controllers differ: " << got.dump();
  for (const auto& [name, runs] : want.items()) {
    ASSERT_TRUE(got.contains(name)) << where << "no controller " << name;
    for (std::size_t r = 0; r < runs.size(); ++r)
      for (const char* key : {"best", "mean", "sd"})
        for (std::size_t g = 0; g < runs[r][key].size(); ++g)
          ASSERT_EQ(runs[r][key][g].get<double>(), got[name][r][key][g].get<double>())
              << where << name << " run " << r << " generation " << g << " " << key;
    EXPECT_EQ(runs, got[name]) << where << name;
  }
}

class Golden : public ::testing::TestWithParam<std::string> {};

TEST_P(Golden, ShortRunGivesTheRecordedResults) {
  const fs::path file = golden_dir() / (GetParam() + ".json");
  json golden = read_json(file);
  const fs::path out = scratch("golden-" + GetParam());
  const std::string script = (fs::path(ESC_SOURCE_DIR) / golden.at("script").get<std::string>()).string();
  const Outcome o = esc("run " + script + " --experiment " + golden.at("experiment").get<std::string>() + " " +
                        golden.at("args").get<std::string>() + " --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const json got = summary_results(read_json(out / "summary.json"), sds_of(out));
  const char* key = golden.contains("conditions") ? "conditions" : "controllers";
  if (const char* update = std::getenv("ESC_UPDATE_GOLDEN"); update != nullptr && std::string(update) == "1") {
    golden[key] = got;
    std::ofstream(file) << golden.dump(1) << "\n";
    GTEST_SKIP() << "rewrote " << file;
  }
  if (std::string(key) == "controllers") {
    expect_same(golden.at(key), got, "");
    return;
  }
  const json& want = golden.at(key);
  ASSERT_EQ(want.size(), got.size()) << "conditions differ: " << got.dump();
  for (const auto& [condition, controllers] : want.items()) {
    ASSERT_TRUE(got.contains(condition)) << "no condition " << condition;
    expect_same(controllers, got[condition], "condition " + condition + ": ");
  }
}

INSTANTIATE_TEST_SUITE_P(ShippedScripts, Golden, ::testing::ValuesIn(golden_files()),
                         [](const auto& param_info) { return param_info.param; });

}  // namespace
