// End-to-end tests of results that last: a run killed with SIGKILL mid-way and resumed ends
// bit-identical to an uninterrupted run; resume refuses finished, foreign, damaged and
// changed inputs without touching anything; export; the HTML report in headless Chromium.

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

namespace fs = std::filesystem;

using namespace cli_test;

constexpr const char* kLonger = " --generations 100 --seed 5 ";   // 4 x 100 generations, about 2.5 s

TEST(Results, KilledRunResumesBitIdentical) {
  const fs::path reference = scratch("reference");
  const fs::path killed = scratch("killed");
  ASSERT_EQ(esc("run " + tiny() + kLonger + "--threads 2 --out " + reference.string()).status, 0);

  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny(), killed, 40, 400));

  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 2");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming"), std::string::npos) << resumed.output;
  expect_same_summary(reference, killed);
  for (const char* run : {"CC/run-01", "CC/run-02", "SC/run-01", "SC/run-02"})
    EXPECT_EQ(slurp(reference / (std::string(run) + ".best.json")), slurp(killed / (std::string(run) + ".best.json")))
        << run;
  EXPECT_EQ(committed_generations(killed), 400);

  // Resuming a finished run changes nothing and says so.
  const std::string before = slurp(killed / "summary.json");
  const Outcome again = esc("run --resume " + killed.string());
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("complete"), std::string::npos) << again.output;
  EXPECT_EQ(slurp(killed / "summary.json"), before);

  // The exports agree with each other and with summary.json.
  const auto exported = nlohmann::json::parse(esc("export " + killed.string() + " --format json").output);
  const auto& e = exported["experiments"][0];
  EXPECT_EQ(e["status"], "finished");
  EXPECT_EQ(e["controllers"]["SC"]["runs"][1]["best_fitness"],
            read_json(killed / "summary.json")["controllers"]["SC"]["runs"][1]["best_fitness"]);
  EXPECT_EQ(e["controllers"]["SC"]["runs"][0]["behavior_usage"].size(), 3U);
}

// A group (`--set robots=3`, docs/groups.md) resumes as one robot does, its stored replay too.
TEST(Results, AGroupKilledResumesBitIdentical) {
  const fs::path reference = scratch("group-reference");
  const fs::path killed = scratch("group-killed");
  ASSERT_EQ(esc("run " + tiny() + kLonger + "--set robots=3 --threads 2 --out " + reference.string()).status, 0);
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny(), killed, 40, 400, "1", {"--set", "robots=3"}));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 2");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_summary(reference, killed);
  EXPECT_EQ(read_json(killed / "settings.json").dump().find("\"robots\":\"3\"") != std::string::npos, true)
      << slurp(killed / "settings.json");
  const Outcome replay = esc("replay " + killed.string() + " --controller CC");
  EXPECT_EQ(replay.status, 0) << replay.output;
  EXPECT_NE(replay.output.find("identical to the stored replay"), std::string::npos) << replay.output;
}

// A group whose bodies read other sensors, each driven by its body's network (a controller per
// body, experiments/examples/mixed_bodies.esc), resumes as a robot alone does.
TEST(Results, AGroupWithANetworkPerBodyKilledResumesBitIdentical) {
  const fs::path reference = scratch("per-body-reference");
  const fs::path killed = scratch("per-body-killed");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/experiments/examples/mixed_bodies.esc";
  const std::vector<std::string> shorter{"--experiment", "mixed_dispersion", "--runs", "2", "--set", "epochs=1",
                                         "--set", "steps=40", "--set", "mu=2", "--set", "lambda=4"};
  std::string flat;
  for (const std::string& a : shorter) flat += a + " ";
  ASSERT_EQ(esc("run " + script + kLonger + flat + "--threads 2 --out " + reference.string()).status, 0);
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(script, killed, 40, 400, "1", shorter));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 2");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_summary(reference, killed);
  EXPECT_EQ(read_json(killed / "summary.json")["controllers"]["sc"]["architecture"], "khepera 8-4-6 / thymio2 7-4-6");
}

// A controller per body's genome is evaluated in a group of other counts and order of the same
// bodies, and refused by a controller listing its networks the other way round
// (tests/cli/data/per_body_transfer.esc).
TEST(Results, AGenomeOfANetworkPerBodyIsReadInItsNetworksOrderOnly) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/per_body_transfer.esc";
  const fs::path cache = scratch("per-body-transfer-cache");
  const Outcome in_order = esc("run " + script + " --experiment in_order --cache " + cache.string() + " --out " +
                               scratch("per-body-in-order").string());
  ASSERT_EQ(in_order.status, 0) << in_order.output;
  const Outcome reversed = esc("run " + script + " --experiment reversed --cache " + cache.string() + " --out " +
                               scratch("per-body-reversed").string());
  EXPECT_NE(reversed.status, 0) << reversed.output;
  EXPECT_NE(reversed.output.find("it was evolved by `khepera 8-2-2 / thymio2 7-2-2`, and `team` here is `thymio2 "
                                 "7-2-2 / khepera 8-2-2`"),
            std::string::npos)
      << reversed.output;
}

// A controller evolved with three robots, tested with five and with three (`evaluate from`,
// tests/cli/data/group_transfer.esc): each test is its own group's, from the same genomes.
TEST(Results, AGroupsControllerIsTestedWithAnotherGroupSize) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/group_transfer.esc";
  const fs::path cache = scratch("group-transfer-cache");
  std::map<std::string, nlohmann::json> tested;
  for (const char* experiment : {"tested_with_five", "tested_with_three"}) {
    const fs::path out = scratch(experiment);
    const Outcome run = esc("run " + script + " --experiment " + experiment + " --cache " + cache.string() +
                            " --out " + out.string());
    ASSERT_EQ(run.status, 0) << run.output;
    tested[experiment] = read_json(out / "settings.json")["settings"];
    const auto runs = read_json(out / "summary.json")["controllers"]["CC"]["runs"];
    ASSERT_EQ(runs.size(), 2U);
    tested[std::string(experiment) + " fitness"] = runs[0]["best_fitness"];
  }
  EXPECT_EQ(tested["tested_with_five"]["robots"], "5");
  EXPECT_EQ(tested["tested_with_three"]["robots"], "3");
  EXPECT_NE(tested["tested_with_five fitness"], tested["tested_with_three fitness"]);
  // One body's setting is the group's alone: the dependency, whose robots have one body, is
  // reused as it was stored.
  const fs::path lit = scratch("tested-with-a-lit-one");
  const Outcome run = esc("run " + script + " --experiment tested_with_a_lit_one --set body2.emission=0.5 --cache " +
                          cache.string() + " --out " + lit.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const nlohmann::json settings = read_json(lit / "settings.json")["settings"];
  EXPECT_EQ(settings["body2.emission"], "0.5");
  EXPECT_EQ(settings["robot.emission"], "0");
  // Replayed with its stored settings, the dependency again without them.
  const Outcome replay = esc("replay " + lit.string() + " --out " + scratch("tested-with-a-lit-one-replay").string());
  ASSERT_EQ(replay.status, 0) << replay.output;
  EXPECT_NE(replay.output.find("identical to the stored replay"), std::string::npos) << replay.output;
  // Given with every body's, it is refused before anything runs.
  const fs::path both = scratch("tested-with-both");
  const Outcome refused = esc("run " + script + " --experiment tested_with_a_lit_one --set robot.emission=1 --set "
                              "body2.emission=0.5 --cache " + cache.string() + " --out " + both.string());
  EXPECT_EQ(refused.status, 1) << refused.output;
  EXPECT_NE(refused.output.find("body2.emission=0.5: `robot.emission` sets every body of the group and "
                                "`body2.emission` one of them"),
            std::string::npos)
      << refused.output;
  EXPECT_FALSE(fs::exists(both));
}

// Roles (docs/groups.md): the genome of two roles holds both networks; it is tested with six
// robots of the same two roles, replayed as stored, and refused by a clonal team.
TEST(Results, RolesEvolvedTogetherAreTestedWithAnotherGroupSize) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/roles_transfer.esc";
  const fs::path cache = scratch("roles-cache");
  const fs::path six = scratch("roles-of-six");
  const Outcome run = esc("run " + script + " --experiment two_roles_of_six --cache " + cache.string() + " --out " +
                          six.string());
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("2 epochs x 60 steps, 6 robots in 2 roles, seed 4"), std::string::npos) << run.output;
  const nlohmann::json summary = read_json(six / "summary.json");
  EXPECT_EQ(summary["robots"], 6);
  EXPECT_EQ(summary["roles"], 2);
  EXPECT_EQ(summary["controllers"]["CC"]["genome_size"], 2 * 46);   // CC: 8-4-2, 46 weights a role
  const nlohmann::json best = read_json(six / "CC" / "run-01.best.json");
  EXPECT_EQ(best["genome"].size(), 2U * 46U);
  EXPECT_EQ(best["roles"], 2);
  const fs::path replayed = scratch("roles-replay");
  const Outcome replay = esc("replay " + six.string() + " --controller CC --run 1 --out " + replayed.string());
  EXPECT_EQ(replay.status, 0) << replay.output;
  EXPECT_EQ(replay.output.find("differ"), std::string::npos) << replay.output;
  const Outcome clonal = esc("run " + script + " --experiment one_role --cache " + cache.string() + " --out " +
                             scratch("one-role").string());
  EXPECT_NE(clonal.status, 0);
  EXPECT_NE(clonal.output.find("`two_roles` evolves 2 roles in one genome and `one_role` has 1"), std::string::npos)
      << clonal.output;
  // Refused before the dependency runs: no run of it is started for nothing.
  const fs::path fresh = scratch("roles-fresh-cache");
  const Outcome early = esc("run " + script + " --experiment one_role --cache " + fresh.string() + " --out " +
                            scratch("one-role-early").string());
  EXPECT_NE(early.status, 0);
  EXPECT_EQ(early.output.find("running into"), std::string::npos) << early.output;
}

TEST(Results, KilledWithSeveralRunsInProgressResumesBitIdentical) {
  // Two threads: tiny's 20 offspring are fewer than 16 per worker, so both runs of a
  // controller advance together and are both in progress when the process is killed.
  const fs::path reference = scratch("reference-1");
  const fs::path killed = scratch("killed-together");
  ASSERT_EQ(esc("run " + tiny() + kLonger + "--threads 1 --out " + reference.string()).status, 0);
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny(), killed, 40, 400, "2"));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_summary(reference, killed);
  for (const char* run : {"CC/run-01", "CC/run-02", "SC/run-01", "SC/run-02"}) {
    EXPECT_EQ(slurp(reference / (std::string(run) + ".best.json")), slurp(killed / (std::string(run) + ".best.json")))
        << run;
    // A header and one line per generation, whichever process wrote it.
    const std::string csv = slurp(killed / (std::string(run) + ".csv"));
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 101) << run;
  }
  EXPECT_EQ(committed_generations(killed), 400);
}

TEST(Results, ResumeRefusesWhatItCannotContinue) {
  // Not an esc directory.
  const fs::path foreign = scratch("foreign");
  fs::create_directories(foreign);
  std::ofstream(foreign / "notes.txt") << "mine";
  Outcome o = esc("run --resume " + foreign.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("not an esc run directory"), std::string::npos) << o.output;
  EXPECT_EQ(slurp(foreign / "notes.txt"), "mine");
  EXPECT_EQ(esc("run --resume " + (foreign / "missing").string()).status, 1);

  // A damaged database: garbage over the header, then a truncated file.
  const fs::path damaged = scratch("damaged");
  ASSERT_EQ(esc("run " + tiny() + " --generations 2 --out " + damaged.string()).status, 0);
  std::string db = slurp(damaged / "esc.db");
  ASSERT_GT(db.size(), 4096U);
  const std::string summary = slurp(damaged / "summary.json");
  std::string garbled = db;
  for (std::size_t i = 0; i < 100; ++i) garbled[i] = static_cast<char>('x' + i % 3);
  std::ofstream(damaged / "esc.db", std::ios::binary | std::ios::trunc) << garbled;
  o = esc("run --resume " + damaged.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("esc: error:"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("esc.db"), std::string::npos) << o.output;
  EXPECT_EQ(slurp(damaged / "esc.db"), garbled);
  EXPECT_EQ(slurp(damaged / "summary.json"), summary);
  std::ofstream(damaged / "esc.db", std::ios::binary | std::ios::trunc) << db.substr(0, db.size() / 2);
  o = esc("run --resume " + damaged.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_EQ(esc("report " + damaged.string()).status, 1);
  EXPECT_FALSE(fs::exists(damaged / "report.html"));

  // A script that changed since the run started.
  const fs::path src = scratch("src");
  fs::create_directories(src);
  fs::copy_file(tiny(), src / "tiny.esc");
  const fs::path changed = scratch("changed");
  const pid_t child = spawn_esc(
      {"run", (src / "tiny.esc").string(), "--generations", "200", "--threads", "1", "--out", changed.string()});
  ASSERT_GE(child, 0);
  ASSERT_GE(kill_when_committed(child, changed, 3).seen, 3);
  std::ofstream(src / "tiny.esc", std::ios::app) << "\n// an edit\n";
  const std::string csv = slurp(changed / "CC" / "run-01.csv");
  o = esc("run --resume " + changed.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("has changed"), std::string::npos) << o.output;
  EXPECT_EQ(slurp(changed / "CC" / "run-01.csv"), csv);

  // Options that would change the run are refused with --resume.
  EXPECT_EQ(esc("run --resume " + changed.string() + " --runs 3").status, 2);

  // A script moved away: resume says where it can be given, and continues when it is (a
  // campaign is known by its files' names and texts, not their directories).
  fs::rename(src / "tiny.esc", src / "edited.esc");
  o = esc("run --resume " + changed.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("is gone; give its new place: esc run FILE --resume"), std::string::npos) << o.output;
  fs::create_directories(src / "elsewhere");
  fs::copy_file(tiny(), src / "elsewhere" / "tiny.esc");
  o = esc("run " + (src / "elsewhere" / "tiny.esc").string() + " --resume " + changed.string() + " --threads 2");
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(committed_generations(changed), 2 * 2 * 200);   // controllers x runs x generations
}

TEST(Results, ExportFormats) {
  const fs::path out = scratch("export");
  ASSERT_EQ(esc("run " + tiny() + " --generations 3 --out " + out.string()).status, 0);
  const Outcome csv = esc("export " + out.string() + " --format csv");
  ASSERT_EQ(csv.status, 0) << csv.output;
  EXPECT_EQ(csv.output.rfind("experiment,controller,run,run_seed,status,generation,best,mean,sd", 0), 0U);
  EXPECT_NE(csv.output.find("\ntiny,SC,2,"), std::string::npos);
  ASSERT_EQ(esc("export " + out.string() + " --format json --out " + (out / "all.json").string()).status, 0);
  const auto j = read_json(out / "all.json");
  EXPECT_EQ(j["experiments"][0]["name"], "tiny");
  EXPECT_EQ(j["experiments"][0]["controllers"]["CC"]["runs"][0]["generations"].size(), 3U);
  EXPECT_FALSE(j["experiments"][0]["sources"].empty());
  EXPECT_EQ(esc("export " + out.string() + " --format xml").status, 2);
}

// The report in a real browser: loads with no script error, and the screenshot is not blank.
TEST(Results, ReportRendersInHeadlessChromium) {
  const fs::path out = scratch("report");
  ASSERT_EQ(esc("run " + tiny() + " --generations 8 --out " + out.string()).status, 0);
  const Outcome rep = esc("report " + out.string());
  ASSERT_EQ(rep.status, 0) << rep.output;
  const fs::path page = out / "report.html";
  ASSERT_TRUE(fs::exists(page));
  const std::string html = slurp(page);
  // Self-contained: no script, style sheet or image loaded from elsewhere.
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_NE(html.find("Chart.js v3"), std::string::npos);

  // Chromium is optional (ESC_WITH_CHROMIUM): found when configuring, or this part is skipped.
  if (std::string(ESC_CHROMIUM).empty())
    GTEST_SKIP() << "configured without chromium (Debian package `chromium`; scripts/esc-setup.sh installs it)";
  const std::string browser = std::string(ESC_CHROMIUM) + " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage "
                              "--user-data-dir=" + (out / "profile").string() + " ";
  const Outcome dom = shell("timeout 60 " + browser + "--virtual-time-budget=3000 --dump-dom file://" +
                            page.string() + " 2>/dev/null");
  ASSERT_EQ(dom.status, 0) << dom.output.substr(0, 2000);
  EXPECT_NE(dom.output.find("(ready)</title>"), std::string::npos) << dom.output.substr(0, 600);
  EXPECT_EQ(dom.output.find("class=\"esc-error\""), std::string::npos) << "script error in the page";
  EXPECT_EQ(dom.output.find("(script error)</title>"), std::string::npos);
  EXPECT_NE(dom.output.find("Replay of the best controllers"), std::string::npos);
  EXPECT_NE(dom.output.find("Behavior usage: SC"), std::string::npos);

  const fs::path png = out / "report.png";
  const Outcome shot = shell("timeout 60 " + browser + "--window-size=1280,2000 --screenshot=" + png.string() +
                             " file://" + page.string());
  ASSERT_EQ(shot.status, 0) << shot.output;
  ASSERT_TRUE(fs::exists(png));
  const std::string image = slurp(png);
  EXPECT_EQ(image.substr(1, 3), "PNG");
  // A blank 1280x2000 page compresses to a few kilobytes; plots, text and the arena do not.
  EXPECT_GT(image.size(), 60000U) << "the screenshot looks blank";
}

// The report of a study of four optimizers (the widest figures: three panels and a legend)
// and of an experiment of three controllers (the widest table: their pairwise comparisons)
// fit a window 1280 pixels wide: neither the page nor any figure, table or card scrolls
// sideways. Measured in the page itself, loaded in a frame of that width.
TEST(Results, AReportFitsAWindow1280PixelsWide) {
  if (std::string(ESC_CHROMIUM).empty())
    GTEST_SKIP() << "configured without chromium (Debian package `chromium`; scripts/esc-setup.sh installs it)";
  for (const std::string script : {"lehman_stanley/mazes.esc", "examples/homing.esc"}) {
    SCOPED_TRACE(script);
    const fs::path out = scratch("report-width-" + fs::path(script).stem().string());
    ASSERT_EQ(esc("run " + std::string(ESC_SOURCE_DIR) + "/experiments/" + script +
                  " --runs 2 --generations 3 --set steps=20 --out " + out.string()).status, 0);
    ASSERT_EQ(esc("report " + out.string()).status, 0);
    std::ofstream(out / "probe.html")
        << "<!DOCTYPE html><html><body><iframe id=\"f\" src=\"report.html\" style=\"width:1280px;height:3000px\">"
           "</iframe><script>document.getElementById('f').onload = () => setTimeout(() => {"
           "const d = document.getElementById('f').contentDocument, de = d.documentElement;"
           "const wide = [...d.querySelectorAll('.figure .svg, .card, table, section')]"
           ".filter(e => e.scrollWidth > e.clientWidth + 1).map(e => e.className + ' ' + e.scrollWidth);"
           "document.body.setAttribute('data-probe', (de.scrollWidth > de.clientWidth ? 'page ' : '') + wide.join(', ') + "
           "'|measured');}, 1500);</script></body></html>";
    const Outcome dom = shell("timeout 90 " + std::string(ESC_CHROMIUM) +
                              " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --allow-file-access-from-files "
                              "--user-data-dir=" + (out / "profile").string() +
                              " --virtual-time-budget=8000 --dump-dom file://" + (out / "probe.html").string() +
                              " 2>/dev/null");
    ASSERT_EQ(dom.status, 0) << dom.output.substr(0, 2000);
    EXPECT_NE(dom.output.find("data-probe=\"|measured\""), std::string::npos)
        << "wider than 1280 pixels: " << dom.output.substr(std::min(dom.output.find("data-probe"), dom.output.size()), 300);
  }
}

}  // namespace
