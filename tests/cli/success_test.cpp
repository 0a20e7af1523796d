// `success when ...` end to end (tests/cli/data/success_study.esc): a study's summary.json
// holds every run's evaluations to success and each controller's count, its end table adds
// the successes and, per pair of the family, Fisher's exact test and the censored
// Mann-Whitney test; the report shows them; a study killed mid-run resumes to the same
// summary, byte for byte; `stop at success` ends each run at its first success and changes
// nothing before it.
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;
using nlohmann::json;

std::string study() { return std::string(ESC_SOURCE_DIR) + "/tests/cli/data/success_study.esc"; }

constexpr int kGenerations = 12;
constexpr int kLambda = 20;

TEST(Success, AStudyCountsComparesAndReportsSuccess) {
  const fs::path out = scratch("success-study");
  const Outcome o = esc("run " + study() + " --generations " + std::to_string(kGenerations) + " --threads 2 --out " +
                        out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const json s = read_json(out / "summary.json");
  int successes = 0, failures = 0;
  for (const json& c : s.at("conditions")) {
    EXPECT_EQ(c.at("success"), "avoid > 120") << c.dump();
    for (const auto& [name, controller] : c.at("controllers").items()) {
      int counted = 0;
      for (const json& r : controller.at("runs")) {
        const json& e = r.at("success_evaluation");
        if (e.is_null()) {
          ++failures;
          continue;
        }
        ++counted;
        ++successes;
        // Within the run's budget, and at or after the first generation whose best passed.
        EXPECT_GE(e.get<int>(), 1);
        EXPECT_LE(e.get<int>(), kGenerations * kLambda);
        std::size_t first = 0;
        while (r.at("best")[first].get<double>() <= 120.0) ++first;
        EXPECT_GT(e.get<int>(), static_cast<int>(first) * kLambda) << name << " " << r.dump();
        EXPECT_LE(e.get<int>(), static_cast<int>(first + 1) * kLambda) << name << " " << r.dump();
      }
      EXPECT_EQ(controller.at("success").at("successes"), counted);
      EXPECT_EQ(controller.at("success").at("runs"), 4);
    }
  }
  // The level is chosen so that the study has both (else the tests below test little).
  EXPECT_GT(successes, 0);
  EXPECT_GT(failures, 0);

  // The end table: successes per condition and controller, then both tests per pair.
  EXPECT_NE(o.output.find("success when avoid > 120: runs that succeeded"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("success (two-sided)"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("Fisher p"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("censored at"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("a run that never succeeded counts as more than the budget"), std::string::npos)
      << o.output;
  // The fitness's family and the success tests' hold the same 4 pairs.
  const std::string family = "Holm: p adjusted over the 4 comparisons shown (within each condition";
  const std::size_t first = o.output.find(family);
  ASSERT_NE(first, std::string::npos) << o.output;
  EXPECT_NE(o.output.find(family, first + 1), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("CC: inertia vs no_inertia"), std::string::npos) << o.output;
  // 241: a run that never succeeded counts as more than 12 x 20 evaluations.
  EXPECT_NE(o.output.find(" 241\n"), std::string::npos) << o.output;

  // `esc export --table success`: the same 4 pairs, with the counts of summary.json.
  const Outcome table = esc("export " + out.string() + " --table success");
  ASSERT_EQ(table.status, 0) << table.output;
  EXPECT_EQ(table.output.substr(0, table.output.find('\n')),
            "study,experiment,condition_a,controller_a,condition_b,controller_b,successes_a,runs_a,successes_b,runs_b,"
            "fisher_p,fisher_p_holm,odds_ratio,censored_u,censored_p,censored_p_holm,censored_at");
  const Outcome rows = esc("export " + out.string() + " --table success --format json");
  ASSERT_EQ(rows.status, 0) << rows.output;
  const json pairs = json::parse(rows.output);
  ASSERT_EQ(pairs.size(), 4u);
  EXPECT_EQ(std::count(table.output.begin(), table.output.end(), '\n'), 5);
  const auto successes_of = [&](const std::string& condition, const std::string& controller) {
    for (const json& c : s.at("conditions"))
      if (c.at("name") == condition) return c.at("controllers").at(controller).at("success").at("successes");
    return json();
  };
  for (const json& p : pairs) {
    EXPECT_EQ(p.at("study"), "success_study");
    EXPECT_EQ(p.at("successes_a"), successes_of(p.at("condition_a"), p.at("controller_a"))) << p.dump();
    EXPECT_EQ(p.at("successes_b"), successes_of(p.at("condition_b"), p.at("controller_b"))) << p.dump();
    EXPECT_EQ(p.at("runs_a"), 4);
    EXPECT_GE(p.at("fisher_p").get<double>(), 0.0);
    EXPECT_LE(p.at("fisher_p").get<double>(), p.at("fisher_p_holm").get<double>());
  }
  EXPECT_EQ(pairs[0].at("condition_a"), pairs[0].at("condition_b")) << "within a condition first";
  EXPECT_NE(table.output.find(",241\n"), std::string::npos) << table.output;

  // The report: the same numbers in the page's data, drawn without a script error.
  ASSERT_EQ(esc("report " + out.string()).status, 0);
  const std::string html = slurp(out / "report.html");
  EXPECT_NE(html.find("\"success_pairs\""), std::string::npos);
  EXPECT_NE(html.find("\"success_evaluation\""), std::string::npos);
  if (std::string(ESC_CHROMIUM).empty())
    GTEST_SKIP() << "configured without chromium (Debian package `chromium`; scripts/esc-setup.sh installs it)";
  const Outcome dom = report_dom(out);
  ASSERT_EQ(dom.status, 0);
  EXPECT_NE(dom.output.find("(ready)</title>"), std::string::npos) << dom.output.substr(0, 600);
  EXPECT_EQ(dom.output.find("class=\"esc-error\""), std::string::npos) << "script error in the page";
  EXPECT_NE(dom.output.find("Success compared (two-sided)"), std::string::npos);
  EXPECT_NE(dom.output.find("Success: avoid &gt; 120"), std::string::npos);
}

TEST(Success, AStudyKilledMidRunResumesToTheSameSuccesses) {
  const fs::path whole = scratch("success-whole"), killed = scratch("success-killed");
  const std::vector<std::string> args{"run", study(), "--generations", "40", "--seed", "5", "--threads", "1"};
  std::string line;
  for (const std::string& a : args) line += a + " ";
  ASSERT_EQ(esc(line + "--out " + whole.string()).status, 0);
  // 2 conditions x 2 controllers x 4 runs x 40 generations: stopped in the first condition,
  // before most runs succeeded (their first successes lie between generations 2 and 38).
  ASSERT_NO_FATAL_FAILURE(run_killed(args, killed, 100, 640));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 2");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_EQ(slurp(whole / "summary.json"), slurp(killed / "summary.json"));
  const json s = read_json(whole / "summary.json");
  int successes = 0;
  for (const json& c : s.at("conditions"))
    for (const auto& [name, controller] : c.at("controllers").items())
      successes += controller.at("success").at("successes").get<int>();
  EXPECT_GT(successes, 0) << "a study without a success tests little here";
}

// `stop at success` (here `--set stop_at_success=on`): a run that succeeds ends after the
// generation of its first success, with the evaluations to success and the generations up to
// there of the run that goes on; a run that never succeeds runs its budget. Killed mid-study
// and resumed: the same summary, byte for byte.
TEST(Success, StopAtSuccessEndsEachRunAfterItsFirstSuccess) {
  const fs::path going = scratch("success-going-on"), stopping = scratch("success-stopping"),
                 killed = scratch("success-stop-killed");
  const std::vector<std::string> args{"run",       study(), "--generations", "40", "--seed", "5", "--threads", "1",
                                      "--set",     "stop_at_success=on"};
  std::string line;
  for (const std::string& a : args) line += a + " ";
  ASSERT_EQ(esc("run " + study() + " --generations 40 --seed 5 --threads 2 --out " + going.string()).status, 0);
  const Outcome o = esc(line + "--out " + stopping.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const json full = read_json(going / "summary.json"), cut = read_json(stopping / "summary.json");
  int stopped = 0, unsolved = 0, generations = 0;
  std::string replayed;   // `esc replay` arguments of the first run that stopped
  std::size_t replayed_generations = 0;
  for (std::size_t c = 0; c < full.at("conditions").size(); ++c)
    for (const auto& [name, controller] : full.at("conditions")[c].at("controllers").items()) {
      const json& short_one = cut.at("conditions")[c].at("controllers").at(name);
      EXPECT_EQ(short_one.at("success"), controller.at("success")) << name;
      for (std::size_t r = 0; r < controller.at("runs").size(); ++r) {
        const json& whole = controller.at("runs")[r];
        const json& run = short_one.at("runs")[r];
        const json& first = whole.at("success_evaluation");
        EXPECT_EQ(run.at("success_evaluation"), first) << name << " run " << r + 1;
        generations += static_cast<int>(run.at("best").size());
        if (first.is_null()) {
          ++unsolved;
          EXPECT_FALSE(run.contains("stopped")) << run.dump();
          EXPECT_EQ(run.at("best"), whole.at("best"));
          continue;
        }
        ++stopped;
        EXPECT_EQ(run.at("stopped"), "stop_at_success");
        if (replayed.empty()) {
          replayed = (stopping / full.at("conditions")[c].at("name").get<std::string>()).string() + " --controller " +
                     name + " --run " + std::to_string(r + 1);
          replayed_generations = run.at("best").size();
        }
        // Up to and including the generation that evaluated the first success.
        const std::size_t upto = (first.get<std::size_t>() + kLambda - 1) / kLambda;
        ASSERT_EQ(run.at("best").size(), upto) << run.dump();
        for (std::size_t g = 0; g < upto; ++g) EXPECT_EQ(run.at("best")[g], whole.at("best")[g]) << g;
      }
    }
  EXPECT_GT(stopped, 0);
  EXPECT_GT(unsolved, 0);
  // One line per condition and controller, not one per run.
  EXPECT_NE(o.output.find(" of 4 runs stopped at their first success (stop_at_success)\n"), std::string::npos)
      << o.output;
  EXPECT_EQ(o.output.find("stopped its search after generation"), std::string::npos) << o.output;

  // Made again, the stopped run ends where it stopped, and its progress counts to there.
  const Outcome again = esc("replay " + replayed + " --evaluations --threads 2 --out " + scratch("success-again").string());
  ASSERT_EQ(again.status, 0) << again.output;
  const std::string n = std::to_string(replayed_generations);
  EXPECT_NE(again.output.find("made again: " + n + " of " + n + " generations"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("identical to the stored run in every generation: " +
                              std::to_string(replayed_generations * kLambda) + " evaluations"),
            std::string::npos)
      << again.output;

  ASSERT_NO_FATAL_FAILURE(run_killed(args, killed, generations / 3, generations));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 2");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_EQ(slurp(stopping / "summary.json"), slurp(killed / "summary.json"));
}

// A run that stops at its first success stores its front there, its last generation, whatever
// `members_every` says (here 100: no other generation but 0 stores one).
TEST(Success, ARunStoppedAtSuccessStoresItsFrontAtItsLastGeneration) {
  const fs::path dir = scratch("success-stopped-front");
  const Outcome o = esc("run " + study() + " --generations 40 --seed 5 --threads 2 --set stop_at_success=on " +
                        "--set networks=nsga2 --set members_every=100 --out " + dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const Outcome front = esc("export " + dir.string() + " --table front");
  ASSERT_EQ(front.status, 0) << front.output;
  std::map<std::string, std::set<int>> stored;   // condition, controller, run -> generations
  const auto rows = csv_rows(front.output);
  for (std::size_t i = 1; i < rows.size(); ++i)
    stored[rows[i][1] + " " + rows[i][2] + " " + rows[i][4]].insert(std::stoi(rows[i][5]));
  int stops = 0;
  const json s = read_json(dir / "summary.json");
  for (const json& c : s.at("conditions"))
    for (const auto& [name, controller] : c.at("controllers").items())
      for (const json& r : controller.at("runs")) {
        const int last = static_cast<int>(r.at("best").size()) - 1;
        stops += r.contains("stopped") ? 1 : 0;
        const std::string key = c.at("name").get<std::string>() + " " + name + " " + std::to_string(r.at("run").get<int>());
        EXPECT_EQ(stored[key], (std::set<int>{0, last})) << key;
      }
  EXPECT_GT(stops, 0);
}

}  // namespace
