// apply_setting: the `esc run --set KEY=VALUE` overrides.
#include <gtest/gtest.h>

#include "helpers.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;
using test::source_dir;

eval::ExperimentSpec paper() {
  const auto r = compile_file(source_dir() / "experiments/paper/obstacle_avoidance.esc", options());
  EXPECT_TRUE(r.ok()) << rendered(r);
  return r.experiments.at(0);
}

TEST(ApplySetting, GoodKeysChangeTheSpecAndResolvedSettings) {
  eval::ExperimentSpec x = paper();
  EXPECT_EQ(apply_setting(x, "epochs", "2"), "");
  EXPECT_EQ(x.epochs, 2);
  EXPECT_EQ(x.resolved_settings.at("epochs"), "2");
  EXPECT_EQ(apply_setting(x, "steps", "50"), "");
  EXPECT_EQ(x.steps, 50);
  EXPECT_EQ(apply_setting(x, "generations", "3"), "");
  EXPECT_EQ(x.es.generations, 3);
  EXPECT_EQ(apply_setting(x, "runs", "1"), "");
  EXPECT_EQ(apply_setting(x, "seed", "42"), "");
  EXPECT_EQ(x.seed, 42u);
  EXPECT_EQ(apply_setting(x, "mu", "10"), "");
  EXPECT_EQ(apply_setting(x, "lambda", "20"), "");
  EXPECT_EQ(x.es.lambda, 20);
  EXPECT_EQ(apply_setting(x, "selection", "plus"), "");
  EXPECT_EQ(x.es.selection, evo::Selection::Plus);
  EXPECT_EQ(x.resolved_settings.at("selection"), "plus");
  EXPECT_EQ(apply_setting(x, "sigma", "0.3"), "");
  EXPECT_DOUBLE_EQ(x.es.initial_sigma, 0.3);
  EXPECT_EQ(apply_setting(x, "bounds", "[-10, 10]"), "");
  EXPECT_DOUBLE_EQ(x.es.upper, 10.0);
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

TEST(ApplySetting, BadKeysAndValuesAreRefusedWithoutChange) {
  eval::ExperimentSpec x = paper();
  const eval::ExperimentSpec before = x;
  std::string m = apply_setting(x, "mu_", "3");
  EXPECT_NE(m.find("did you mean `mu`?"), std::string::npos) << m;
  EXPECT_NE(m.find("epochs"), std::string::npos) << m;   // lists the keys
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
  EXPECT_EQ(x.es.mu, before.es.mu);
  EXPECT_EQ(x.robot.motor.inertia, before.robot.motor.inertia);
  EXPECT_EQ(x.resolved_settings, before.resolved_settings);
}

}  // namespace
}  // namespace esc::compiler
