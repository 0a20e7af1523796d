// Studies end to end: one `esc run` runs every condition into one directory (one database,
// one summary.json, one table); a condition's results are those of its experiment run alone
// with its settings and the study's seed, and do not move when another condition is removed
// or with the thread count and runs advancing together; a study stopped by SIGKILL resumes
// bit-identical; `esc export` and `esc report` take several directories.
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;
using nlohmann::json;

std::string studies() { return std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tiny_study.esc"; }

// The condition `name` of a study's summary.json.
json condition(const json& summary, const std::string& name) {
  for (const json& c : summary.at("conditions"))
    if (c.at("name") == name) return c;
  ADD_FAILURE() << "no condition " << name << " in " << summary.dump();
  return json::object();
}

TEST(Study, OneRunRunsEveryConditionIntoOneDirectory) {
  const fs::path out = scratch("study");
  const Outcome o = esc("run " + studies() + " --generations 2 --threads 2 --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const json s = read_json(out / "summary.json");
  EXPECT_EQ(s["study"], "tiny_study");   // the file's first declaration
  EXPECT_EQ(s["seed"], "1");   // a string, as every seed in JSON
  ASSERT_EQ(s["conditions"].size(), 4u);
  const json& off = s["conditions"][0];
  EXPECT_EQ(off["name"], "no_inertia");
  EXPECT_EQ(off["experiment"], "tiny");
  EXPECT_EQ(off["settings"], json({{"robot.inertia", "off"}}));
  EXPECT_EQ(s["conditions"][3]["name"], "time_constant=200ms");
  EXPECT_EQ(s["conditions"][3]["settings"], json({{"robot.time_constant", "200ms"}}));
  for (const json& c : s["conditions"]) {
    ASSERT_EQ(c["controllers"].size(), 2u) << c["name"];
    EXPECT_EQ(c["controllers"]["SC"]["runs"].size(), 2u) << c["name"];
    EXPECT_EQ(c["controllers"]["SC"]["runs"][0]["best"].size(), 2u) << c["name"];
  }
  EXPECT_NE(condition(s, "time_constant=50ms")["controllers"], condition(s, "time_constant=200ms")["controllers"]);
  // One database and one summary; each condition's files in its own directory.
  EXPECT_TRUE(fs::exists(out / "esc.db"));
  EXPECT_TRUE(fs::exists(out / "sources"));
  EXPECT_FALSE(fs::exists(out / "no_inertia" / "summary.json"));
  EXPECT_TRUE(fs::exists(out / "no_inertia" / "CC" / "run-01.csv"));
  EXPECT_TRUE(fs::exists(out / "time_constant=150ms" / "SC" / "run-02.best.json"));
  const json settings = read_json(out / "time_constant=150ms" / "settings.json");
  EXPECT_EQ(settings["study"], "tiny_study");
  EXPECT_EQ(settings["condition"], "time_constant=150ms");
  EXPECT_EQ(settings["settings"]["robot.time_constant"], "0.15 s");
  EXPECT_EQ(read_json(out / "settings.json")["conditions"].size(), 4u);
  // The table: controllers by conditions, then one family of comparisons.
  EXPECT_NE(o.output.find("study tiny_study: 4 conditions, seed 1"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("no_inertia: CC vs SC"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("SC: time_constant=150ms vs time_constant=200ms"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("Holm: p adjusted over the 16 comparisons shown"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("SC time_constant=50ms forward"), std::string::npos) << o.output;   // usage per condition
  // Finished: nothing to resume.
  const Outcome again = esc("run --resume " + out.string());
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("is complete"), std::string::npos) << again.output;
}

TEST(Study, AConditionGivesItsExperimentsResultsWhateverElseTheStudyHolds) {
  const std::string common = " --generations 2 --threads 2 --out ";
  const fs::path all = scratch("seed-all"), fewer = scratch("seed-fewer"), alone = scratch("seed-alone"),
                 off = scratch("seed-off");
  ASSERT_EQ(esc("run " + studies() + common + all.string()).status, 0);
  ASSERT_EQ(esc("run " + studies() + " --experiment tiny_study_fewer" + common + fewer.string()).status, 0);
  // The experiment alone with the point's setting and the study's seed.
  const Outcome a = esc("run " + tiny() + " --set robot.time_constant=200ms --seed 1" + common + alone.string());
  ASSERT_EQ(a.status, 0) << a.output;
  ASSERT_EQ(esc("run " + tiny() + " --set robot.inertia=off --seed 1" + common + off.string()).status, 0);
  const json s_all = read_json(all / "summary.json"), s_fewer = read_json(fewer / "summary.json");
  const json point = condition(s_all, "time_constant=200ms")["controllers"];
  EXPECT_EQ(point, read_json(alone / "summary.json")["controllers"]);
  // Removing the 150ms point changes no other point.
  EXPECT_EQ(condition(s_fewer, "time_constant=200ms")["controllers"], point);
  EXPECT_EQ(condition(s_fewer, "time_constant=50ms")["controllers"], condition(s_all, "time_constant=50ms")["controllers"]);
  EXPECT_EQ(condition(s_all, "no_inertia")["controllers"], read_json(off / "summary.json")["controllers"]);
}

TEST(Study, ASettingThatFlattensNothingIsSetForTheWholeStudy) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/alike_study.esc";
  const std::string shorter = " --set generations=1 --runs 1 --set epochs=1 --out ";
  const fs::path alike = scratch("study-alike"), by_default = scratch("study-alike-by-default");
  for (const auto& [study, out] : {std::pair{"alike", alike}, std::pair{"alike_by_default", by_default}}) {
    const Outcome o = esc("run " + script + " --experiment " + study + shorter + out.string());
    ASSERT_EQ(o.status, 0) << o.output;
    for (const json& c : read_json(out / "summary.json")["conditions"])
      EXPECT_EQ(c["controllers"]["CC"]["runs"][0]["best"].size(), 1u) << c.dump();
  }
  // What the study compares is still compared.
  EXPECT_EQ(read_json(alike / "inertia" / "settings.json")["settings"]["robot.inertia"], "on");
  EXPECT_EQ(read_json(alike / "no_inertia" / "settings.json")["settings"]["robot.inertia"], "off");
}

TEST(Study, ASettingThatMakesConditionsAlikeIsRefusedNamingWhatTheyDifferIn) {
  const std::string data = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/";
  struct Case {
    std::string script, study, set, varied;
  };
  for (const Case& c : std::vector<Case>{
           // The key itself.
           {"alike_study.esc", "alike", "robot.inertia=on", "`robot.inertia` across its conditions (`inertia`: on, "
                                                            "`no_inertia`: off)"},
           // robot.KEY sets every body; the conditions differ in the second's.
           {"alike_study.esc", "leader_or_all_lit", "robot.emission=0",
            "`body2.emission` across its conditions (`all_lit`: as the first body, `leader`: 0)"},
           // `networks es` drops CMA-ES and its settings.
           {"alike_study.esc", "cmaes_settings", "networks=es",
            "`cmaes.lambda` across its conditions (`smaller`: 6, `as_by_default`: 0)"},
           // `generations` sets GP's too.
           {"alike_gp_study.esc", "gp_generations", "generations=2", "`gp.generations` across its conditions"}}) {
    const fs::path out = scratch("study-flattened-" + c.study);
    const Outcome o = esc("run " + data + c.script + " --experiment " + c.study + " --set " + c.set + " --out " +
                          out.string());
    EXPECT_EQ(o.status, 1) << c.study << "\n" << o.output;
    EXPECT_NE(o.output.find(c.set + ": study `" + c.study + "` varies " + c.varied), std::string::npos)
        << c.study << "\n" << o.output;
    EXPECT_FALSE(fs::exists(out)) << c.study;
  }
}

// `robot.KEY` sets every body and `body2.KEY` one: one from the study and the other from the
// command line would override the study's without saying so, varied or not.
TEST(Study, EveryBodysSettingAgainstOneBodysIsRefused) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/alike_study.esc";
  struct Case {
    std::string study, set, said;
  };
  for (const Case& c : std::vector<Case>{
           {"every_body_swept", "body2.emission=0.8",
            "body2.emission=0.8: condition `emission=0` of study `every_body_swept` sets `robot.emission`, and "
            "`body2.emission` would override it"},
           {"second_lit_or_not", "robot.emission=0",
            "robot.emission=0: condition `both_lit` of study `second_lit_or_not` sets `body2.emission`, and "
            "`robot.emission` would override it"},
           {"darker_second", "robot.emission=0",
            "robot.emission=0: study `darker_second` gives `body2.emission` to experiment `lit_group` in its "
            "conditions (lit_group.body2.emission 0.3)"}}) {
    const fs::path out = scratch("study-overlap-" + c.study);
    const Outcome o = esc("run " + script + " --experiment " + c.study + " --set " + c.set + " --out " + out.string());
    EXPECT_EQ(o.status, 1) << c.study << "\n" << o.output;
    EXPECT_NE(o.output.find(c.said), std::string::npos) << c.study << "\n" << o.output;
    EXPECT_FALSE(fs::exists(out)) << c.study;
  }
}

// `esc export --table comparisons` writes the end table's tests, pair by pair, as computed:
// each row's p values and A12 are those `esc run` printed, rounded as it prints them.
TEST(Study, ExportedComparisonsAreTheEndTables) {
  const fs::path out = scratch("study-comparisons");
  const Outcome o = esc("run " + studies() + " --experiment tiny_study_fewer --runs 3 --generations 2 --set epochs=1 "
                        "--out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const Outcome table = esc("export " + out.string() + " --table comparisons");
  ASSERT_EQ(table.status, 0) << table.output;
  const auto rows = csv_rows(table.output);
  ASSERT_EQ(rows.size(), 1u + 9u) << table.output;   // 3 conditions x 1 pair, 2 controllers x 3 pairs
  const std::vector<std::string>& header = rows.front();
  const auto at = [&](const std::vector<std::string>& row, const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << name;
    return row.at(static_cast<std::size_t>(it - header.begin()));
  };
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto& row = rows[r];
    EXPECT_EQ(at(row, "study"), "tiny_study_fewer");
    const std::string label = at(row, "condition_a") == at(row, "condition_b")
                                  ? at(row, "condition_a") + ": " + at(row, "controller_a") + " vs " + at(row, "controller_b")
                                  : at(row, "controller_a") + ": " + at(row, "condition_a") + " vs " + at(row, "condition_b");
    // The end table's line: the label, then its 11 numbers, each rounded as printed.
    const std::size_t line = o.output.find("\n" + label + " ");
    ASSERT_NE(line, std::string::npos) << label << "\n" << o.output;
    std::istringstream printed(o.output.substr(line + 1 + label.size()));
    const std::vector<std::pair<std::string, double>> columns{
        {"welch_t", 5e-4},        {"welch_df", 0.05},    {"welch_p", 5e-5},
        {"welch_p_holm", 5e-5},   {"mann_whitney_u", 0.05}, {"mann_whitney_p", 5e-5},
        {"mann_whitney_p_holm", 5e-5}, {"a12", 5e-3},    {"sd_ratio", 5e-3},
        {"brown_forsythe_p", 5e-5}, {"brown_forsythe_p_holm", 5e-5}};
    for (const auto& [column, rounding] : columns) {
      double shown = 0;
      ASSERT_TRUE(printed >> shown) << label << ": " << column;
      EXPECT_NEAR(std::stod(at(row, column)), shown, rounding) << label << ": " << column;
    }
  }
  // The JSON holds the same rows.
  const json j = json::parse(esc("export " + out.string() + " --table comparisons --format json").output);
  ASSERT_EQ(j.size(), rows.size() - 1);
  for (std::size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(j[r - 1]["condition_a"], at(rows[r], "condition_a"));
    EXPECT_EQ(j[r - 1]["mann_whitney_exact"], at(rows[r], "mann_whitney_exact") == "1");
    EXPECT_EQ(j[r - 1]["welch_p_holm"].get<double>(), std::stod(at(rows[r], "welch_p_holm")));
  }
  // A plain experiment: one pair, named by its experiment.
  const fs::path plain = scratch("comparisons-plain");
  ASSERT_EQ(esc("run " + tiny() + " --runs 3 --generations 2 --set epochs=1 --out " + plain.string()).status, 0);
  const auto pair = csv_rows(esc("export " + plain.string() + " --table comparisons").output);
  ASSERT_EQ(pair.size(), 2u);
  EXPECT_EQ(at(pair[1], "experiment"), "tiny");
  EXPECT_EQ(at(pair[1], "study"), "");
  EXPECT_EQ(at(pair[1], "controller_a") + " " + at(pair[1], "controller_b"), "CC SC");
}

TEST(Study, ThreadsAndRunsAtOnceChangeNothing) {
  const fs::path a = scratch("study-threads-1"), b = scratch("study-threads-2");
  const std::string args = "run " + studies() + " --experiment tiny_study_fewer --generations 3 --out ";
  ASSERT_EQ(esc(args + a.string() + " --threads 1 --runs-at-once 1").status, 0);
  ASSERT_EQ(esc(args + b.string() + " --threads 2 --runs-at-once 3").status, 0);
  EXPECT_EQ(slurp(a / "summary.json"), slurp(b / "summary.json"));
}

TEST(Study, SettingAVariedKeyIsRefusedOtherSettingsApplyToEveryCondition) {
  const fs::path out = scratch("study-set");
  const Outcome varied = esc("run " + studies() + " --set robot.time_constant=50ms --out " + out.string());
  EXPECT_EQ(varied.status, 1);
  EXPECT_NE(varied.output.find("study `tiny_study` varies `robot.time_constant` across its conditions"),
            std::string::npos) << varied.output;
  EXPECT_FALSE(fs::exists(out));
  const Outcome ok = esc("run " + studies() + " --experiment tiny_study_fewer --runs 1 --generations 1 --set epochs=1 "
                         "--seed 4 --out " + out.string());
  ASSERT_EQ(ok.status, 0) << ok.output;
  const json s = read_json(out / "summary.json");
  EXPECT_EQ(s["seed"], "4");
  for (const json& c : s["conditions"]) EXPECT_EQ(c["controllers"]["CC"]["runs"].size(), 1u);
  EXPECT_EQ(read_json(out / "no_inertia" / "settings.json")["settings"]["epochs"], "1");
  // A bad value for one condition names it.
  const Outcome bad = esc("run " + studies() + " --set robot.max_speed=1m/s --out " + scratch("study-bad").string());
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.output.find("condition `no_inertia`: robot.max_speed=1m/s"), std::string::npos) << bad.output;
  // A key no experiment has is the command line's: named once, without a condition.
  const Outcome typo = esc("run " + studies() + " --set epocs=2 --out " + scratch("study-typo").string());
  EXPECT_EQ(typo.status, 1);
  EXPECT_EQ(typo.output.rfind("esc: error: epocs=2: unknown setting `epocs`; did you mean `epochs`?", 0), 0U)
      << typo.output;
  EXPECT_EQ(typo.output.find("condition `"), std::string::npos) << typo.output;
  // One line: with a suggestion, not the hundred keys besides.
  EXPECT_EQ(typo.output, "esc: error: epocs=2: unknown setting `epocs`; did you mean `epochs`?\n");
  // Without one, the plain keys and the groups, not every key of every group.
  const Outcome far = esc("run " + studies() + " --set zzzz=2 --out " + scratch("study-far").string());
  EXPECT_EQ(far.status, 1);
  EXPECT_NE(far.output.find("epochs, steps, runs"), std::string::npos) << far.output;
  EXPECT_NE(far.output.find("robot.*"), std::string::npos) << far.output;
  EXPECT_EQ(far.output.find("robot.max_speed"), std::string::npos) << far.output;
  EXPECT_LT(far.output.size(), 600U) << far.output;
}

TEST(Study, AnUnknownNameListsExperimentsAndStudies) {
  const Outcome o = esc("run " + studies() + " --experiment tiny_studdy --out " + scratch("unknown").string());
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.output.find("has no experiment or study `tiny_studdy`; it declares studies `tiny_study`, "
                          "`tiny_study_fewer`"),
            std::string::npos) << o.output;
}

TEST(Study, KilledHalfwayResumesBitIdentical) {
  const fs::path whole = scratch("study-whole"), killed = scratch("study-killed");
  const std::vector<std::string> args = {"run", studies(), "--experiment", "tiny_study_fewer", "--generations", "30",
                                         "--threads", "1"};
  std::vector<std::string> w = args;
  w.insert(w.end(), {"--out", whole.string()});
  std::string line;
  for (const auto& a : w) line += " " + a;
  ASSERT_EQ(esc(line.substr(1)).status, 0);
  // 3 conditions x 2 controllers x 2 runs x 30 generations: stopped in the second condition.
  ASSERT_NO_FATAL_FAILURE(run_killed(args, killed, 150, 360));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 2");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming study tiny_study_fewer"), std::string::npos) << resumed.output;
  EXPECT_EQ(slurp(whole / "summary.json"), slurp(killed / "summary.json"));
  EXPECT_EQ(slurp(whole / "time_constant=200ms" / "SC" / "run-02.best.json"),
            slurp(killed / "time_constant=200ms" / "SC" / "run-02.best.json"));
}

TEST(Study, ExportAndReportTakeSeveralDirectories) {
  const fs::path study = scratch("many-study"), plain = scratch("many-plain");
  ASSERT_EQ(esc("run " + studies() + " --experiment tiny_study_fewer --generations 2 --out " + study.string()).status, 0);
  ASSERT_EQ(esc("run " + tiny() + " --generations 2 --out " + plain.string()).status, 0);
  const Outcome csv = esc("export " + study.string() + " " + plain.string() + " --format csv");
  ASSERT_EQ(csv.status, 0) << csv.output;
  EXPECT_EQ(csv.output.rfind("experiment,controller,run,run_seed,status,generation,best,mean,sd,evaluations,steps,"
                             "seconds,condition,study,directory,algorithm\n", 0), 0U);
  EXPECT_NE(csv.output.find(",time_constant=200ms,tiny_study_fewer," + study.string() + ",es\n"), std::string::npos);
  EXPECT_NE(csv.output.find(",tiny,," + plain.string() + ",es\n"), std::string::npos);
  // 3 conditions and one experiment, 2 controllers x 2 runs x 2 generations each.
  EXPECT_EQ(std::count(csv.output.begin(), csv.output.end(), '\n'), 1 + 4 * 8);
  const json j = json::parse(esc("export " + study.string() + " " + plain.string() + " --format json").output);
  ASSERT_EQ(j["experiments"].size(), 4u);
  EXPECT_EQ(j["experiments"][0]["study"], "tiny_study_fewer");
  EXPECT_EQ(j["experiments"][0]["condition_settings"], json({{"robot.inertia", "off"}}));
  EXPECT_FALSE(j["experiments"][3].contains("study"));

  EXPECT_EQ(esc("report " + study.string() + " " + plain.string()).status, 2);   // where to?
  const fs::path page = scratch("many-report") / "report.html";
  fs::create_directories(page.parent_path());
  const Outcome r = esc("report " + study.string() + " " + plain.string() + " --out " + page.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string html = slurp(page);
  EXPECT_NE(html.find("\"studies\":[{"), std::string::npos);
  EXPECT_NE(html.find("tiny_study_fewer-sweep.svg"), std::string::npos);
  for (const char* f : {"tiny_study_fewer-sweep.svg", "tiny_study_fewer-best-by-condition.svg",
                        "tiny_study_fewer-no_inertia-fitness.svg", "tiny-fitness.svg", "tiny-best.svg"}) {
    const std::string svg = slurp(page.parent_path() / "figures" / f);
    EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0U) << f;
  }
  // One directory: its report and figures go into it.
  ASSERT_EQ(esc("report " + study.string()).status, 0);
  EXPECT_TRUE(fs::exists(study / "report.html"));
  EXPECT_TRUE(fs::exists(study / "figures" / "tiny_study_fewer-sweep.svg"));

  // A condition's directory, as `esc replay` takes it, exports that condition alone; a
  // directory of a run that is no condition is refused, naming the run.
  const Outcome one = esc("export " + (study / "time_constant=200ms").string() + " --format csv");
  ASSERT_EQ(one.status, 0) << one.output;
  EXPECT_EQ(std::count(one.output.begin(), one.output.end(), '\n'), 1 + 8);
  EXPECT_NE(one.output.find(",time_constant=200ms,tiny_study_fewer," + study.string() + ",es\n"), std::string::npos);
  const Outcome no = esc("export " + (plain / "CC").string());
  EXPECT_NE(no.status, 0);
  EXPECT_NE(no.output.find("is a directory of run `" + plain.string() + "`"), std::string::npos) << no.output;
}

// A condition's setting of an experiment it depends on (`basic.generations 2`) runs that
// experiment with it into a cache entry of its own, beside the one as declared, and is
// stored among the condition's settings; a carried-on study prepares the same entry again.
TEST(Study, AConditionSetsAnExperimentItDependsOn) {
  const fs::path out = scratch("study-dependency-setting");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/start_from.esc";
  const Outcome o = esc("run " + script + " --experiment from_shorter --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  std::vector<std::string> generations;
  for (const auto& e : fs::directory_iterator(out / "deps"))
    if (e.path().filename().string().rfind("basic-", 0) == 0)
      generations.push_back(read_json(e.path() / "settings.json")["settings"]["generations"].get<std::string>());
  std::sort(generations.begin(), generations.end());
  EXPECT_EQ(generations, (std::vector<std::string>{"2", "4"}));
  const json s = read_json(out / "summary.json");
  EXPECT_EQ(condition(s, "again_after_2")["settings"], json({{"basic.generations", "2"}}));
  EXPECT_EQ(read_json(out / "again_after_2" / "settings.json")["settings"]["basic.generations"], "2");
  // Each condition evaluates the best genomes of its own `basic`: those of 2 generations
  // are another set (3 runs of a seed-independent evaluation: they would match only if
  // every run's best had appeared by generation 2).
  EXPECT_NE(condition(s, "again")["controllers"], condition(s, "again_after_2")["controllers"]);
  const Outcome replay = esc("replay " + (out / "again_after_2").string() + " --controller SC --run 1 --out " +
                             scratch("study-dependency-setting-replay").string());
  EXPECT_EQ(replay.status, 0) << replay.output;

  const fs::path onwards = scratch("study-dependency-setting-onwards");
  Outcome o2 = esc("run " + script + " --experiment onwards_from_shorter --out " + onwards.string());
  ASSERT_EQ(o2.status, 0) << o2.output;
  o2 = esc("run --resume " + onwards.string() + " --generations 3");
  ASSERT_EQ(o2.status, 0) << o2.output;
  EXPECT_NE(o2.output.find("esc: dependency basic: reused"), std::string::npos) << o2.output;
  EXPECT_EQ(o2.output.find("running into"), std::string::npos) << o2.output;
  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(onwards / "deps"))
    if (e.path().filename().string().rfind("basic-", 0) == 0) entries.push_back(e.path());
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(read_json(entries[0] / "settings.json")["settings"]["generations"], "2");
  EXPECT_EQ(read_json(onwards / "summary.json")["conditions"][0]["controllers"]["CC"]["runs"][0]["best"].size(), 3u);
}

}  // namespace
