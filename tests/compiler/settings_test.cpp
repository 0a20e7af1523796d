// apply_setting: the `esc run --set KEY=VALUE` overrides.
#include <gtest/gtest.h>

#include "helpers.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::paper;
using test::rendered;
using test::source_dir;

TEST(ApplySetting, GoodKeysChangeTheSpecAndResolvedSettings) {
  eval::ExperimentSpec x = paper();
  EXPECT_EQ(apply_setting(x, "epochs", "2"), "");
  EXPECT_EQ(x.epochs, 2);
  EXPECT_EQ(x.resolved_settings.at("epochs"), "2");
  EXPECT_EQ(apply_setting(x, "steps", "50"), "");
  EXPECT_EQ(x.steps, 50);
  EXPECT_EQ(apply_setting(x, "generations", "3"), "");
  EXPECT_EQ(x.generations, 3);
  EXPECT_EQ(apply_setting(x, "runs", "1"), "");
  EXPECT_EQ(apply_setting(x, "seed", "42"), "");
  EXPECT_EQ(x.seed, 42u);
  EXPECT_EQ(apply_setting(x, "mu", "10"), "");
  EXPECT_EQ(apply_setting(x, "lambda", "20"), "");
  EXPECT_EQ(es_of(x).lambda, 20);
  EXPECT_EQ(apply_setting(x, "selection", "plus"), "");
  EXPECT_EQ(es_of(x).selection, evo::Selection::Plus);
  EXPECT_EQ(x.resolved_settings.at("selection"), "plus");
  EXPECT_EQ(apply_setting(x, "sigma", "0.3"), "");
  EXPECT_DOUBLE_EQ(es_of(x).initial_sigma, 0.3);
  EXPECT_EQ(apply_setting(x, "bounds", "[-10, 10]"), "");
  EXPECT_DOUBLE_EQ(es_of(x).upper, 10.0);
  EXPECT_EQ(apply_setting(x, "robot.inertia", "off"), "");
  EXPECT_FALSE(x.robot.motor.inertia);
  EXPECT_EQ(x.resolved_settings.at("robot.inertia"), "off");
  EXPECT_EQ(apply_setting(x, "robot.time_constant", "50ms"), "");
  EXPECT_DOUBLE_EQ(x.robot.motor.time_constant_s, 0.05);
  EXPECT_EQ(x.resolved_settings.at("robot.time_constant"), "0.05 s");
  EXPECT_EQ(apply_setting(x, "robot.max_accel", "0.5 m/s^2"), "");
  EXPECT_DOUBLE_EQ(x.robot.motor.max_accel_mps2, 0.5);
  EXPECT_EQ(apply_setting(x, "robot.substeps", "4"), "");
  EXPECT_EQ(x.robot.physics_substeps, 4);
}

// `members_every`: resolved (and so in the fingerprint) only when not its default, so that the
// runs from before it keep their settings.
TEST(ApplySetting, MembersEveryIsResolvedOnlyWhenNotTheDefault) {
  eval::ExperimentSpec x = paper();
  EXPECT_EQ(x.members_every, eval::kMembersEvery);
  EXPECT_EQ(x.resolved_settings.count("members_every"), 0u);
  EXPECT_EQ(apply_setting(x, "members_every", "1"), "");
  EXPECT_EQ(x.members_every, 1);
  EXPECT_EQ(x.resolved_settings.at("members_every"), "1");
  EXPECT_EQ(apply_setting(x, "members_every", "10"), "");
  EXPECT_EQ(x.resolved_settings.count("members_every"), 0u);
  for (const char* bad : {"0", "-3", "2.5", "ten"}) {
    const std::string m = apply_setting(x, "members_every", bad);
    EXPECT_NE(m.find("members_every"), std::string::npos) << bad << ": " << m;
    EXPECT_EQ(x.members_every, 10) << bad;
  }
  EXPECT_NE(apply_setting(x, "members_every", "0").find("at least 1"), std::string::npos);
}

TEST(ApplySetting, BadKeysAndValuesAreRefusedWithoutChange) {
  eval::ExperimentSpec x = paper();
  const eval::ExperimentSpec before = x;
  std::string m = apply_setting(x, "mu_", "3");
  EXPECT_NE(m.find("did you mean `mu`?"), std::string::npos) << m;
  EXPECT_EQ(m.find("epochs"), std::string::npos) << m;   // the suggestion alone
  m = apply_setting(x, "zzzz", "3");
  EXPECT_NE(m.find("epochs"), std::string::npos) << m;   // no suggestion: the keys and groups
  EXPECT_NE(m.find("gp.*"), std::string::npos) << m;
  m = apply_setting(x, "robot.inertai", "off");
  EXPECT_NE(m.find("did you mean `robot.inertia`?"), std::string::npos) << m;
  m = apply_setting(x, "mu", "200");   // comma with lambda 150
  EXPECT_NE(m.find("lambda"), std::string::npos) << m;
  m = apply_setting(x, "epochs", "0");
  EXPECT_NE(m.find("at least 1"), std::string::npos) << m;
  m = apply_setting(x, "epochs", "two");
  EXPECT_FALSE(m.empty());
  m = apply_setting(x, "robot.time_constant", "5cm");
  EXPECT_NE(m.find("expected a time, found a length"), std::string::npos) << m;
  m = apply_setting(x, "robot.time_constant", "50");
  EXPECT_NE(m.find("missing unit"), std::string::npos) << m;
  m = apply_setting(x, "robot.inertia", "maybe");
  EXPECT_FALSE(m.empty());
  m = apply_setting(x, "bounds", "[1, -1]");
  EXPECT_NE(m.find("empty bounds"), std::string::npos) << m;
  m = apply_setting(x, "selection", "comma-ish");
  EXPECT_FALSE(m.empty());
  EXPECT_EQ(x.epochs, before.epochs);
  EXPECT_EQ(es_of(x).mu, es_of(before).mu);
  EXPECT_EQ(x.robot.motor.inertia, before.robot.motor.inertia);
  EXPECT_EQ(x.resolved_settings, before.resolved_settings);
}

// Every ES option is settable under the spelling scripts use, and resolved under it.
TEST(ApplySetting, EveryEsOptionUnderTheScriptsSpelling) {
  eval::ExperimentSpec x = paper();
  EXPECT_EQ(apply_setting(x, "min_sigma", "1e-5"), "");
  EXPECT_DOUBLE_EQ(es_of(x).min_sigma, 1e-5);
  EXPECT_EQ(x.resolved_settings.at("min_sigma"), "1e-05");
  EXPECT_EQ(apply_setting(x, "recombination", "no_recombination"), "");
  EXPECT_EQ(es_of(x).recombination, evo::Recombination::None);
  EXPECT_EQ(x.resolved_settings.at("recombination"), "no_recombination");
  EXPECT_EQ(apply_setting(x, "step_sizes", "one_sigma"), "");
  EXPECT_EQ(es_of(x).step_sizes, evo::StepSizes::One);
  EXPECT_EQ(x.resolved_settings.at("step_sizes"), "one_sigma");
  EXPECT_EQ(apply_setting(x, "arena.sweep_cell", "5cm"), "");
  EXPECT_DOUBLE_EQ(x.arena.sweep_cell_m, 0.05);
  EXPECT_EQ(x.resolved_settings.at("arena.sweep_cell"), "0.05 m");
  // Other spellings of the same values are refused, with the one spelling.
  const eval::ExperimentSpec before = x;
  std::string m = apply_setting(x, "recombination", "none");
  EXPECT_NE(m.find("`recombination` is `intermediate`, `discrete` or `no_recombination`, found `none`"),
            std::string::npos)
      << m;
  m = apply_setting(x, "step_sizes", "per_gene");
  EXPECT_NE(m.find("`one_sigma` or `self_adaptive`"), std::string::npos) << m;
  m = apply_setting(x, "selection", "coma");
  EXPECT_NE(m.find("did you mean `comma`?"), std::string::npos) << m;
  m = apply_setting(x, "min_sigma", "-1");
  EXPECT_NE(m.find("`min_sigma` must be at least 0, found -1"), std::string::npos) << m;
  m = apply_setting(x, "arena.sweep_cel", "1cm");
  EXPECT_NE(m.find("did you mean `arena.sweep_cell`?"), std::string::npos) << m;
  EXPECT_EQ(x.resolved_settings, before.resolved_settings);
}

// Each key's value is read as a script reads it: the same messages for the same mistakes.
TEST(ApplySetting, ValuesReadLikeScripts) {
  const char* kScript = "arena a { size 1m x 1m }\nfitness f { step: speed }\ncontroller c = mlp(ir[0..7] -> wheels)\n"
                        "experiment e { arena a  fitness f  compare c  evolve es(sigma 0) }\n";
  const auto r = compile_source(kScript, "same.esc", options());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(rendered(r).find("same.esc:4:63: error: `sigma` must be greater than 0, found 0"), std::string::npos)
      << rendered(r);
  eval::ExperimentSpec x = paper();
  EXPECT_EQ(apply_setting(x, "sigma", "0"), "`sigma` must be greater than 0, found 0");
  EXPECT_EQ(apply_setting(x, "robot.inertia", "3"), "`inertia` is `on` or `off`, found `3` (write `inertia on` or "
                                                     "`inertia off`)");
  EXPECT_EQ(apply_setting(x, "bounds", "[-1, 1"), "`bounds` cannot take `[-1, 1`: a value is a number with its unit "
                                                  "(`50ms`), `on` or `off`, a word, or a range `[-1, 1]`");
  EXPECT_EQ(apply_setting(x, "bounds", "1"), "`bounds` takes a range, as in `[-1, 1]`, found `1` (write `bounds "
                                             "[-1, 1]`)");
  EXPECT_EQ(apply_setting(x, "robot.max_accel", "0.5 m/s^2"), "");
  EXPECT_DOUBLE_EQ(x.robot.motor.max_accel_mps2, 0.5);
}

}  // namespace
}  // namespace esc::compiler
