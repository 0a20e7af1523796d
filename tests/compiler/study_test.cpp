// Studies in scripts: `conditions`, `condition NAME = EXP { KEY VALUE }`, `sweep EXP { KEY
// [VALUES] }` and their grids, the study's `runs` and `seed`, the precedence of settings,
// `compare C as NAME`, and which declaration `esc run` runs by default. Each diagnostic has
// a file in tests/bad/ (study_*.esc, compare_as_twice.esc).
#include <gtest/gtest.h>

#include <algorithm>

#include "helpers.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;

const std::string kBase = R"(
import "lib/khepera.esc"
arena a { size 1m x 1m }
fitness f { step: speed }
controller c = mlp(ir[0..7] -> wheels)
controller sym = symbolic(mlp(ir[0..7] -> hidden 3), actions [forward, backward])
experiment e {
  arena a
  fitness f
  robot khepera { time_constant 80ms }
  evolve es(mu 10, lambda 20)
  runs 4
  seed 9
  compare c, sym
}
)";

CompileResult compile(const std::string& text) { return compile_source(kBase + text, "study.esc", options()); }

const eval::StudySpec& study(const CompileResult& r, const std::string& name) {
  const auto it = std::find_if(r.studies.begin(), r.studies.end(), [&](const auto& s) { return s.name == name; });
  if (it == r.studies.end()) throw std::runtime_error("no study " + name);
  return *it;
}

std::vector<std::string> names(const eval::StudySpec& s) {
  std::vector<std::string> v;
  for (const auto& c : s.conditions) v.push_back(c.name);
  return v;
}

TEST(Study, ConditionsConditionAndSweepInTheirOrder) {
  const CompileResult r = compile(R"(
study s {
  conditions e
  condition no_inertia = e { robot.inertia off  mu 5 }
  sweep e { robot.time_constant [25ms, 50ms] }
}
)");
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::StudySpec& s = study(r, "s");
  EXPECT_EQ(names(s), (std::vector<std::string>{"e", "no_inertia", "time_constant=25ms", "time_constant=50ms"}));
  EXPECT_TRUE(s.conditions[0].settings.empty());
  EXPECT_DOUBLE_EQ(s.conditions[0].experiment.robot.motor.time_constant_s, 0.08);
  // A condition's settings over the experiment's own.
  const eval::ExperimentSpec& off = s.conditions[1].experiment;
  EXPECT_FALSE(off.robot.motor.inertia);
  EXPECT_EQ(es_of(off).mu, 5);
  EXPECT_EQ(off.resolved_settings.at("mu"), "5");
  EXPECT_EQ(off.resolved_settings.at("robot.inertia"), "off");
  ASSERT_EQ(s.conditions[1].settings.size(), 2u);
  EXPECT_EQ(s.conditions[1].settings[0].key, "robot.inertia");
  EXPECT_EQ(s.conditions[1].settings[0].value, "off");
  EXPECT_FALSE(s.conditions[1].settings[0].swept);
  EXPECT_FALSE(s.conditions[1].sweep.has_value());
  // Sweep points: their value in SI, as written in the settings, and on the plot's axis.
  const eval::ConditionSpec& p = s.conditions[3];
  EXPECT_DOUBLE_EQ(p.experiment.robot.motor.time_constant_s, 0.05);
  EXPECT_NE(p.experiment.resolved_settings.at("robot.time_constant"),
            s.conditions[2].experiment.resolved_settings.at("robot.time_constant"));
  EXPECT_EQ(p.sweep, 0);
  ASSERT_EQ(p.settings.size(), 1u);
  EXPECT_EQ(p.settings[0].value, "50ms");
  EXPECT_TRUE(p.settings[0].swept);
  EXPECT_EQ(p.settings[0].x, 50.0);
  EXPECT_EQ(p.settings[0].x_unit, "ms");
  EXPECT_EQ(p.directory, "time_constant=50ms");
}

TEST(Study, SeveralSettingsSweepTheirGridFirstSlowest) {
  const CompileResult r = compile(R"(
study grid {
  sweep e { mu [2, 4]  selection [comma, plus]  robot.max_speed [40mm/s, 6cm/s] }
}
)");
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::StudySpec& s = study(r, "grid");
  ASSERT_EQ(s.conditions.size(), 8u);
  EXPECT_EQ(s.conditions[0].name, "mu=2,selection=comma,max_speed=40mm/s");
  EXPECT_EQ(s.conditions[1].name, "mu=2,selection=comma,max_speed=6cm/s");
  EXPECT_EQ(s.conditions[7].name, "mu=4,selection=plus,max_speed=6cm/s");
  EXPECT_EQ(es_of(s.conditions[7].experiment).mu, 4);
  EXPECT_EQ(es_of(s.conditions[7].experiment).selection, evo::Selection::Plus);
  EXPECT_DOUBLE_EQ(s.conditions[7].experiment.robot.motor.max_speed_mps, 0.06);
  // A file name: no `/`.
  EXPECT_EQ(s.conditions[0].directory, "mu=2,selection=comma,max_speed=40mm_per_s");
  // Words are no numbers: no place on a numeric axis; values in two units neither.
  EXPECT_FALSE(s.conditions[0].settings[1].x.has_value());
  EXPECT_FALSE(s.conditions[0].settings[2].x.has_value());
  EXPECT_EQ(s.conditions[0].settings[0].x, 2.0);
}

TEST(Study, KeysThatShareTheirLastPartAreNamedInFull) {
  const CompileResult r = compile(R"(
study g { sweep e { generations [3, 4]  gp.generations [5, 6] } }
)");
  ASSERT_TRUE(r.ok()) << rendered(r);
  EXPECT_EQ(study(r, "g").conditions[0].name, "generations=3,gp.generations=5");
}

// One body's setting is not every body's: its condition names keep the body.
TEST(Study, OneBodysSettingKeepsItsBodyInTheConditionsNames) {
  const CompileResult r = compile(R"(
robot lit = khepera { emission 1 }
experiment pair { arena a  fitness f  robot khepera, lit  compare c }
study g { sweep pair { body2.emission [0, 0.5]  robot.max_speed [5cm/s, 6cm/s] } }
)");
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::StudySpec& g = study(r, "g");
  EXPECT_EQ(g.conditions[0].name, "body2.emission=0,max_speed=5cm/s");
  EXPECT_EQ(g.conditions[1].experiment.robot_params()[1].emission.intensity, 0.0);
  EXPECT_EQ(g.conditions[2].experiment.robot_params()[1].emission.intensity, 0.5);
  EXPECT_EQ(g.conditions[2].experiment.robot_params()[0].emission.intensity, 0.0);
}

TEST(Study, RangesAreSweptAsListsOfRanges) {
  const CompileResult r = compile(R"(
study b {
  sweep e { bounds [[-1, 1], [-2, 2]] }
  condition wide = e { bounds [-5, 5] }
}
)");
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::StudySpec& s = study(r, "b");
  EXPECT_EQ(names(s), (std::vector<std::string>{"bounds=[-1,1]", "bounds=[-2,2]", "wide"}));
  EXPECT_EQ(es_of(s.conditions[1].experiment).lower, -2.0);
  EXPECT_EQ(es_of(s.conditions[2].experiment).upper, 5.0);
}

TEST(Study, RunsAndSeedOfTheStudyOverTheExperimentsAConditionsRunsOverBoth) {
  const CompileResult r = compile(R"(
study plain { conditions e }
study given {
  condition more = e { runs 7 }
  conditions e
  runs 3
  seed 12
}
)");
  ASSERT_TRUE(r.ok()) << rendered(r);
  // The study's seed (default 1) is every condition's master seed, whatever the experiment says.
  const eval::StudySpec& plain = study(r, "plain");
  EXPECT_EQ(plain.seed, 1u);
  EXPECT_EQ(plain.conditions[0].experiment.seed, 1u);
  EXPECT_EQ(plain.conditions[0].experiment.runs, 4);
  const eval::StudySpec& given = study(r, "given");
  EXPECT_EQ(given.seed, 12u);
  EXPECT_EQ(given.conditions[0].experiment.runs, 7);
  EXPECT_EQ(given.conditions[1].experiment.runs, 3);
  EXPECT_EQ(given.conditions[1].experiment.seed, 12u);
  EXPECT_EQ(given.conditions[1].experiment.resolved_settings.at("seed"), "12");
  EXPECT_EQ(given.conditions[1].experiment.resolved_settings.at("runs"), "3");
}

TEST(Study, TheFirstDeclaredExperimentOrStudyIsTheDefault) {
  const auto first = [](const std::string& text) {
    const CompileResult r = compile_source(kBase + text, "d.esc", options());
    EXPECT_TRUE(r.ok()) << rendered(r);
    return r.first_declared;
  };
  EXPECT_EQ(first(""), "e");
  EXPECT_EQ(first("study s { conditions e }"), "e");
  const CompileResult r = compile_source("study s { conditions e }\n" + kBase, "d.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  EXPECT_EQ(r.first_declared, "s");
}

TEST(Study, ImportedStudiesAreCheckedButNotReturned) {
  const CompileResult r =
      compile_source("import \"paper/loophole.esc\"\n", "imports.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  EXPECT_TRUE(r.studies.empty());
  EXPECT_TRUE(r.first_declared.empty());
}

TEST(Study, ShippedStudies) {
  const auto shipped = [](const char* file) {
    const CompileResult r = compile_file(test::source_dir() / file, options());
    EXPECT_TRUE(r.ok()) << rendered(r);
    return r;
  };
  const CompileResult loophole = shipped("experiments/paper/loophole.esc");
  EXPECT_EQ(loophole.first_declared, "loophole");
  EXPECT_EQ(names(study(loophole, "loophole")), (std::vector<std::string>{"loophole_no_inertia", "loophole_inertia", "loophole_wide_weights"}));
  const CompileResult sweep = shipped("experiments/studies/inertia_sweep.esc");
  const eval::StudySpec& s = study(sweep, "inertia_sweep");
  ASSERT_GE(s.conditions.size(), 6u);
  EXPECT_FALSE(s.conditions.front().experiment.robot.motor.inertia);
  EXPECT_EQ(s.conditions.back().name, "time_constant=200ms");
  const CompileResult sensitivity = shipped("experiments/paper/sensitivity.esc");
  for (const eval::ConditionSpec& c : study(sensitivity, "sensitivity").conditions) {
    ASSERT_EQ(c.experiment.controllers.size(), 2u) << c.name;
    EXPECT_EQ(c.experiment.controllers[0].name, "CS") << c.name;
    EXPECT_EQ(c.experiment.controllers[1].name, "SS") << c.name;
  }
  EXPECT_EQ(study(sensitivity, "sensitivity").conditions[2].experiment.controllers[0].behaviors.size(), 24u);
}

TEST(CompareAs, TheControllerIsComparedStoredAndDependedOnUnderItsNewName) {
  const CompileResult r = compile_source(kBase + R"(
experiment renamed { arena a  fitness f  compare c as plain, sym as SC }
behavior evolved_sc = evolved from experiment renamed controller SC
controller sup = supervisor(mlp(ir[0..7]), behaviors [evolved_sc, forward(0.5)])
experiment uses { arena a  fitness f  compare sup }
experiment goes_on { arena a  fitness f  start from experiment renamed  compare c as plain }
)", "as.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const auto& x = r.experiments.at(1);
  ASSERT_EQ(x.name, "renamed");
  EXPECT_EQ(x.controllers[0].name, "plain");
  EXPECT_EQ(x.controllers[1].name, "SC");
  EXPECT_EQ(x.controllers[1].genome_size(), r.experiments.at(0).controllers[1].genome_size());
  EXPECT_EQ(x.resolved_settings.at("compare"), "plain, SC");
  const auto& uses = r.experiments.at(2);
  ASSERT_EQ(uses.dependencies.size(), 1u);
  EXPECT_EQ(uses.dependencies[0].experiment, "renamed");
  EXPECT_EQ(uses.dependencies[0].controller, "SC");

  // A name the experiment does not compare any more is refused, with the names it does.
  const CompileResult wrong = compile_source(kBase + R"(
experiment renamed { arena a  fitness f  compare sym as SC }
behavior b = evolved from experiment renamed controller sym
controller sup = supervisor(mlp(ir[0..7]), behaviors [b])
experiment uses { arena a  fitness f  compare sup }
)", "as.esc", options());
  EXPECT_FALSE(wrong.ok());
  EXPECT_NE(rendered(wrong).find("experiment `renamed` does not compare a controller `sym`"), std::string::npos)
      << rendered(wrong);
  EXPECT_NE(rendered(wrong).find("help: `renamed` compares `SC`"), std::string::npos) << rendered(wrong);
}

TEST(Study, SetSettingValuesAreReadLikeTheScriptsOwn) {
  // The same value read in a study and by --set gives the same experiment.
  const CompileResult r = compile(R"(study s { condition x = e { robot.max_accel 0.5 m/s^2  sigma 0.2 } })");
  ASSERT_TRUE(r.ok()) << rendered(r);
  eval::ExperimentSpec by_set = r.experiments.at(0);
  by_set.seed = 1;
  ASSERT_EQ(apply_setting(by_set, "robot.max_accel", "0.5 m/s^2"), "");
  ASSERT_EQ(apply_setting(by_set, "sigma", "0.2"), "");
  ASSERT_EQ(apply_setting(by_set, "seed", "1"), "");
  EXPECT_EQ(study(r, "s").conditions[0].experiment.resolved_settings, by_set.resolved_settings);
  EXPECT_EQ(study(r, "s").conditions[0].name, "x");
  EXPECT_EQ(study(r, "s").conditions[0].settings[0].value, "0.5m/s^2");
  EXPECT_EQ(study(r, "s").conditions[0].directory, "x");
}

// `energy.generations 60`: a setting of an experiment the condition's depends on, recorded
// with its path and checked on that experiment with the condition's other settings of it
// (lambda >= mu once both hold); its seed may change; further down by naming each; a sweep
// point keeps the experiment in its name.
TEST(Study, AConditionSetsAnExperimentItDependsOn) {
  const std::string text = R"(
arena a { size 1m x 1m }
fitness f { step: speed }
controller c = mlp(ir[0..7] -> wheels)
controller s = supervisor(mlp(ir[0..7]), behaviors [lib])
library lib { behavior b = evolved from experiment base controller c }
experiment base { arena a  fitness f  evolve es(mu 5, lambda 30, comma) for 4 generations  compare c }
experiment middle { arena a  fitness f  compare s }
experiment top { arena a  fitness f  start from experiment middle  compare s }
study st {
  condition both = top { middle.lambda 60  middle.mu 40  middle.seed 7 }
  condition deeper = top { middle.base.generations 2 }
  sweep top { middle.generations [2, 3] }
}
)";
  const CompileResult r = compile_source(text, "deps.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::StudySpec& st = study(r, "st");
  EXPECT_EQ(names(st), (std::vector<std::string>{"both", "deeper", "middle.generations=2", "middle.generations=3"}));
  const auto& both = st.conditions[0].experiment.dependency_settings;
  ASSERT_EQ(both.size(), 3u);
  EXPECT_EQ(both[0].path, std::vector<std::string>{"middle"});
  EXPECT_EQ(both[0].key, "lambda");
  EXPECT_EQ(both[0].value, "60");
  EXPECT_EQ(both[2].key, "seed");
  EXPECT_EQ(st.conditions[0].experiment.resolved_settings.at("middle.mu"), "40");
  // The condition's own experiment is as declared.
  EXPECT_EQ(es_of(st.conditions[0].experiment).mu, es_of(r.all_experiments.back()).mu);
  const auto& deeper = st.conditions[1].experiment.dependency_settings;
  ASSERT_EQ(deeper.size(), 1u);
  EXPECT_EQ(deeper[0].path, (std::vector<std::string>{"middle", "base"}));
  EXPECT_EQ(deeper[0].key, "generations");
  EXPECT_EQ(st.conditions[3].experiment.dependency_settings.at(0).value, "3");

  // Checked together: mu 25 with lambda 20 fails on the experiment, reported at the last value.
  const CompileResult wrong = compile_source(
      text.substr(0, text.find("study st")) + "study w { condition x = top { middle.mu 25  middle.lambda 20 } }\n",
      "deps.esc", options());
  EXPECT_FALSE(wrong.ok());
  EXPECT_NE(rendered(wrong).find("experiment `middle` with the settings this condition gives it: comma selection "
                                 "needs `lambda` >= `mu`"),
            std::string::npos)
      << rendered(wrong);
}

// A wrong key in a sweep is one error, at the key, however many values it lists; a wrong
// value is one error per value.
long errors(const CompileResult& r) {
  return std::count_if(r.diagnostics.begin(), r.diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

TEST(Study, ASweepsWrongKeyIsReportedOnce) {
  const CompileResult key = compile(R"(study s { sweep e { robot.time_constat [25ms, 50ms, 75ms] } })");
  EXPECT_EQ(errors(key), 1) << rendered(key);
  const CompileResult values = compile(R"(study s { sweep e { robot.time_constant [25kg, 50kg] } })");
  EXPECT_EQ(errors(values), 2) << rendered(values);
}

// One mistake inside an experiment is one error: the studies that use it do not add "has no
// conditions" (docs/language.md), whichever way they name it.
TEST(Study, AWrongExperimentIsReportedOnceNotOncePerStudy) {
  const std::string wrong = R"(
experiment broken { arena a  fitness f  evolve es(mu 10, lambda 20)  compare nowhere }
)";
  for (const std::string study : {"study s { conditions broken }", "study s { condition x = broken { mu 5 } }",
                                  "study s { sweep broken { mu [5, 6] } }",
                                  "study s { conditions broken }\nstudy t { conditions broken, e }"}) {
    const CompileResult r = compile(wrong + study);
    EXPECT_EQ(errors(r), 1) << study << "\n" << rendered(r);
    EXPECT_EQ(rendered(r).find("has no conditions"), std::string::npos) << rendered(r);
  }
}

}  // namespace
}  // namespace esc::compiler
