// `success when NAME CMP NUMBER`: what the compiler makes of it (the objective or descriptor
// it tests, the comparison, the threshold in SI) and its located diagnostics.
#include <gtest/gtest.h>

#include "tests/compiler/helpers.hpp"

namespace esc::compiler::test {
namespace {

using Of = eval::SuccessSpec::Of;
using Check = eval::SuccessSpec::Test;

// The experiment block opens on line 6; `items` start on line 7.
std::string script(const std::string& items) {
  return "arena a { size 1m x 1m }\n"
         "fitness f { step: forward_speed }\n"
         "fitness count_steps { step: 1 }\n"
         "fitness bonus { step: 0  evaluation: 5 }\n"
         "controller c = mlp(ir[0..7] -> wheels)\n"
         "experiment e { arena a  epochs 3 x 20 steps  compare c\n" + items + "\n}\n";
}

CompileResult compiled(const std::string& items) { return compile_source(script(items), "success.esc", options()); }

eval::ExperimentSpec experiment(const std::string& items) {
  const CompileResult r = compiled(items);
  EXPECT_TRUE(r.ok()) << rendered(r);
  return r.ok() ? r.experiments.at(0) : eval::ExperimentSpec{};
}

std::string errors(const std::string& items) {
  const CompileResult r = compiled(items);
  EXPECT_FALSE(r.ok()) << "compiled: " << items;
  return rendered(r);
}

TEST(Success, AnExperimentWithoutATestResolvesAsBefore) {
  const eval::ExperimentSpec x = experiment("fitness f");
  EXPECT_FALSE(x.success.has_value());
  EXPECT_EQ(x.resolved_settings.count("success"), 0u);
}

TEST(Success, TheFitnessInTheUnitOfItsRange) {
  const eval::ExperimentSpec x = experiment("fitness f in [-1.2m, 0]\n success when f > -17.1875mm");
  ASSERT_TRUE(x.success.has_value());
  EXPECT_EQ(x.success->of, Of::Objective);
  EXPECT_EQ(x.success->index, 0u);
  EXPECT_EQ(x.success->test, Check::Above);
  EXPECT_DOUBLE_EQ(x.success->threshold, -0.0171875);
  EXPECT_EQ(x.resolved_settings.at("success"), "f > -0.0171875");
  // A fitness without a range: the number is read as a range's bound would be.
  EXPECT_DOUBLE_EQ(experiment("fitness f\n success when f >= 2cm").success->threshold, 0.02);
  EXPECT_DOUBLE_EQ(experiment("fitness f\n success when f < -3").success->threshold, -3.0);
  // A bare 0 needs no unit.
  EXPECT_EQ(experiment("fitness f in [-1.2m, 0]\n success when f >= 0").success->test, Check::AtLeast);
}

TEST(Success, AFurtherObjectiveOrADescriptor) {
  const eval::ExperimentSpec o =
      experiment("fitness f\n objective bonus\n objective count_steps minimize in [0, 60]\n"
                 " success when count_steps <= 30");
  ASSERT_TRUE(o.success.has_value());
  EXPECT_EQ(o.success->of, Of::Objective);
  EXPECT_EQ(o.success->index, 2u);   // after the fitness and `bonus`, as evo::Outcome holds them
  EXPECT_EQ(o.success->test, Check::AtMost);
  EXPECT_EQ(o.resolved_settings.at("success"), "count_steps <= 30");

  const eval::ExperimentSpec d = experiment(
      "fitness f\n descriptor clock: time in [0, 10s]\n descriptor late: epoch in [0, 2] by last\n"
      " success when late < 1");
  ASSERT_TRUE(d.success.has_value());
  EXPECT_EQ(d.success->of, Of::Descriptor);
  EXPECT_EQ(d.success->index, 1u);
  EXPECT_EQ(d.success->test, Check::Below);
  EXPECT_DOUBLE_EQ(experiment("fitness f\n descriptor clock: time in [0, 10s]\n success when clock > 1500ms")
                       .success->threshold,
                   1.5);
}

TEST(Success, TheTestReadsTheValueAsDeclared) {
  eval::SuccessSpec s{"d", Of::Objective, 0, Check::Above, -0.5};
  EXPECT_TRUE(s.passes(-0.4));
  EXPECT_FALSE(s.passes(-0.5));
  s.test = Check::AtLeast;
  EXPECT_TRUE(s.passes(-0.5));
  s.test = Check::Below;
  EXPECT_TRUE(s.passes(-0.6));
  EXPECT_FALSE(s.passes(std::nan("")));   // a broken value succeeds at nothing
}

TEST(Success, MistakesAreLocatedAndExplained) {
  // Line 7 holds `fitness ...`, line 8 the success test.
  const std::string unknown = errors("fitness f\n success when bonsu > 1");
  EXPECT_NE(unknown.find("success.esc:8:15: error: `bonsu` is neither an objective nor a descriptor of this "
                         "experiment"),
            std::string::npos)
      << unknown;
  EXPECT_NE(unknown.find("help: a success test reads the fitness, a further objective or a descriptor: `f`"),
            std::string::npos)
      << unknown;
  const std::string near = errors("fitness f\n objective bonus\n success when bonsu > 1");
  EXPECT_NE(near.find("did you mean `bonus`?"), std::string::npos) << near;

  const std::string unit = errors("fitness f in [-1.2m, 0]\n success when f > -17s");
  EXPECT_NE(unit.find("success.esc:8:22: error: expected a length, found a time (`s`)"), std::string::npos) << unit;
  EXPECT_NE(unit.find("note: the range of `f` is a length"), std::string::npos) << unit;
  const std::string bare = errors("fitness f in [-1.2m, 0]\n success when f > -17.1875");
  EXPECT_NE(bare.find("success.esc:8:19: error: missing unit: expected a length"), std::string::npos) << bare;
  EXPECT_NE(errors("fitness f\n success when f > 2parsecs").find("unknown unit `parsecs`"), std::string::npos);

  const std::string twice = errors("fitness f\n success when f > 1\n success when f > 2");
  EXPECT_NE(twice.find("success.esc:9:2: error: `success` is already given in this experiment"), std::string::npos)
      << twice;
  EXPECT_NE(twice.find("first given here"), std::string::npos) << twice;

  const std::string both = errors("fitness f\n descriptor f: epoch in [0, 2]\n success when f > 1");
  EXPECT_NE(both.find("descriptor `f` has the name of an objective of this experiment"), std::string::npos) << both;
  EXPECT_EQ(both.find("success.esc:9"), std::string::npos) << "the test itself is fine: " << both;

  // Only the four comparisons: `==` is a syntax error at the operator.
  const std::string equal = errors("fitness f\n success when f == 1");
  EXPECT_NE(equal.find("success.esc:8:17: error:"), std::string::npos) << equal;
}

TEST(Success, StopAtSuccessNeedsTheTestAndIsASetting) {
  const eval::ExperimentSpec stops = experiment("fitness f\n success when f > 1\n stop at success");
  EXPECT_TRUE(stops.stop_at_success);
  EXPECT_EQ(stops.resolved_settings.at("stop_at_success"), "on");
  // Written before the test it needs, the same.
  EXPECT_TRUE(experiment("fitness f\n stop at success\n success when f > 1").stop_at_success);
  // Off: not resolved, so that experiments from before it keep their settings.
  eval::ExperimentSpec goes_on = experiment("fitness f\n success when f > 1");
  EXPECT_FALSE(goes_on.stop_at_success);
  EXPECT_EQ(goes_on.resolved_settings.count("stop_at_success"), 0u);
  EXPECT_EQ(apply_setting(goes_on, "stop_at_success", "on"), "");
  EXPECT_TRUE(goes_on.stop_at_success);
  EXPECT_EQ(goes_on.resolved_settings.at("stop_at_success"), "on");
  eval::ExperimentSpec off = stops;
  EXPECT_EQ(apply_setting(off, "stop_at_success", "off"), "");
  EXPECT_FALSE(off.stop_at_success);
  EXPECT_EQ(off.resolved_settings.count("stop_at_success"), 0u);

  // Line 7 holds `fitness f`, line 8 `stop at success`.
  const std::string missing = errors("fitness f\n stop at success");
  EXPECT_NE(missing.find("success.esc:8:2: error: `stop at success` needs the experiment's success test"),
            std::string::npos)
      << missing;
  EXPECT_NE(missing.find("help: declare it: `success when"), std::string::npos) << missing;
  const std::string twice = errors("fitness f\n success when f > 1\n stop at success\n stop at success");
  EXPECT_NE(twice.find("success.esc:10:2: error: `stop at success` is already given in this experiment"),
            std::string::npos)
      << twice;
  eval::ExperimentSpec untested = experiment("fitness f");
  const std::string set = apply_setting(untested, "stop_at_success", "on");
  EXPECT_NE(set.find("`stop_at_success` needs the experiment's success test"), std::string::npos) << set;
  EXPECT_FALSE(untested.stop_at_success);
  EXPECT_NE(apply_setting(untested, "stop_at_success", "3").find("stop_at_success"), std::string::npos);
}

TEST(Success, SuccessStaysAName) {
  // A keyword only at the start of an experiment's item: a fitness, a descriptor and a
  // controller may still be called `success`.
  const CompileResult r = compile_source(
      "arena a { size 1m x 1m }\n"
      "fitness success { step: forward_speed }\n"
      "controller c = mlp(ir[0..7] -> wheels)\n"
      "experiment e { arena a  fitness success  compare c  success when success > 0.5 }\n",
      "name.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  EXPECT_EQ(r.experiments.at(0).resolved_settings.at("success"), "success > 0.5");
}

}  // namespace
}  // namespace esc::compiler::test
