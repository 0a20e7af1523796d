// The HTML report: self-contained (Chart.js and the page's script embedded), data block
// with curves, statistics, usage and the replay. Rendering in a browser is tested end to
// end in tests/cli/results_test.cpp.
#include "runtime/report/html_report.hpp"

#include <gtest/gtest.h>

namespace esc::report {
namespace {

store::StoredExperiment experiment() {
  store::StoredExperiment e;
  e.name = "demo";
  e.status = "finished";
  e.runs = 3;
  e.generations = 2;
  e.arena = {{"width", 0.5}, {"height", 0.4}, {"boxes", nlohmann::json::array()}, {"cylinders", nlohmann::json::array()}};
  e.robot_radius_m = 0.0275;
  for (const char* name : {"CC", "SC"}) {
    store::StoredController c;
    c.name = name;
    c.head = name[0] == 'S' ? "symbolic" : "classical";
    if (c.head == "symbolic") c.actions = {"forward", "left"};
    for (int r = 0; r < 3; ++r) {
      eval::RunResult run;
      run.run = r;
      run.generations = {{0, 1.0 + r, 0.5, 0.1, 10, 100, 0.1}, {1, 2.0 + r + (c.head == "symbolic" ? 5 : 0), 1.0, 0.1, 10, 100, 0.1}};
      run.best_fitness = run.generations.back().best;
      if (c.head == "symbolic") run.action_usage = {30, 10};
      c.finished.push_back(run);
    }
    store::StoredReplay replay;
    replay.run = 2;
    for (int epoch = 0; epoch < 3; ++epoch)
      for (int s = 0; s < 4; ++s) {
        eval::TraceStep t;
        t.epoch = epoch;
        t.step = s;
        t.pose = {0.1 + 0.01 * s, 0.2, 0.0};
        t.action = c.head == "symbolic" ? s % 2 : -1;
        replay.steps.push_back(t);
      }
    c.replay = replay;
    e.controllers.push_back(c);
  }
  return e;
}

TEST(HtmlReport, DataHoldsCurvesStatisticsUsageAndReplay) {
  ReportOptions o;
  o.max_replay_steps = 9;   // cut at a whole epoch: 2 epochs of 4 steps
  const auto d = report_data({experiment()}, o);
  const auto& e = d["experiments"][0];
  ASSERT_EQ(e["controllers"].size(), 2U);
  // The fitness curves over the runs (bests 1, 2, 3 then 2, 3, 4): mean and sample sd per
  // generation; no run's series is embedded.
  EXPECT_EQ(e["controllers"][0]["curves"]["best"]["mean"], nlohmann::json({2.0, 3.0}));
  EXPECT_EQ(e["controllers"][0]["curves"]["best"]["sd"], nlohmann::json({1.0, 1.0}));
  EXPECT_EQ(e["controllers"][0]["curves"]["mean"]["sd"], nlohmann::json({0.0, 0.0}));
  EXPECT_FALSE(e["controllers"][0]["runs"][2].contains("best"));
  EXPECT_EQ(e["controllers"][0]["runs"][2]["best_fitness"], 4.0);
  EXPECT_EQ(e["controllers"][1]["usage"].size(), 3U);
  EXPECT_EQ(e["controllers"][1]["replay"]["rows"].size(), 8U);
  EXPECT_EQ(e["controllers"][1]["replay"]["total_steps"], 12);
  const auto& summary = e["stats"]["summary"];
  EXPECT_DOUBLE_EQ(summary[0]["mean"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(summary[1]["median"].get<double>(), 8.0);
  const auto& pair = e["stats"]["pairs"][0];
  EXPECT_EQ(pair["a"], "CC");
  EXPECT_LT(pair["welch_p"].get<double>(), 0.01);
  EXPECT_DOUBLE_EQ(pair["mwu_u"].get<double>(), 0.0);
}

// Success only where the experiment declares a test: each controller's count and both tests
// per pair; the data of an experiment without one is as before.
TEST(HtmlReport, SuccessIsShownOnlyWhenDeclared) {
  EXPECT_FALSE(report_data({experiment()}, {})["experiments"][0].contains("success"));
  store::StoredExperiment e = experiment();
  e.settings["success"] = "f > 3";
  for (store::StoredController& c : e.controllers)
    for (eval::RunResult& r : c.finished)
      if (r.best_fitness > 3) r.success_evaluation = 10 + r.run;   // SC's three runs, CC's last
  const auto d = report_data({e}, {})["experiments"][0];
  ASSERT_TRUE(d.contains("success"));
  EXPECT_EQ(d["success"]["test"], "f > 3");
  EXPECT_EQ(d["success"]["controllers"][0]["successes"], 1);
  EXPECT_EQ(d["success"]["controllers"][1]["successes"], 3);
  EXPECT_DOUBLE_EQ(d["success"]["controllers"][1]["median_evaluations"].get<double>(), 11.0);
  const auto& pair = d["success"]["pairs"][0];
  EXPECT_EQ(pair["a"], "CC");
  EXPECT_DOUBLE_EQ(pair["fisher_p"].get<double>(), 0.4);   // [[1, 2], [3, 0]]: scipy.stats.fisher_exact
  EXPECT_DOUBLE_EQ(pair["censored_at"].get<double>(), 21.0);   // 2 generations of 10 evaluations, + 1
  EXPECT_EQ(d["controllers"][1]["runs"][0]["success_evaluation"], 10);
}

TEST(HtmlReport, PageIsSelfContained) {
  const std::string page = html_report({experiment()});
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0U);
  EXPECT_NE(page.find("Chart.js v3"), std::string::npos);
  EXPECT_NE(page.find("id=\"esc-data\""), std::string::npos);
  EXPECT_NE(page.find("(ready)"), std::string::npos);
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
}

TEST(HtmlReport, ScriptEndTagsInDataAreEscaped) {
  store::StoredExperiment e = experiment();
  e.settings["note"] = "</script><script>alert(1)</script>";
  const std::string page = html_report({e});
  EXPECT_EQ(page.find("</script><script>alert"), std::string::npos);
  EXPECT_NE(page.find("<\\/script><script>alert(1)<\\/script>"), std::string::npos);
}

}  // namespace
}  // namespace esc::report
