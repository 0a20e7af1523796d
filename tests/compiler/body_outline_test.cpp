// Bodies of any convex outline: `body_outline` read in SI (the Thymio II of the standard
// library), shown in the resolved settings, settable with --set, the disc by default; an
// outline that is no body is refused where it is written.
#include <gtest/gtest.h>

#include <array>
#include <numbers>
#include <string>
#include <utility>

#include "helpers.hpp"
#include "runtime/core/rng.hpp"
#include "runtime/expr/observables.hpp"
#include "runtime/sim/world.hpp"

namespace esc::compiler {
namespace {

std::string script(const std::string& robot_settings) {
  return "arena a { size 1m x 1m }\n"
         "robot r {\n" + robot_settings + "\n}\n"
         "fitness f { step: speed }\n"
         "controller c = mlp(ir[0..7] -> wheels)\n"
         "experiment e { arena a  robot r  fitness f  compare c }\n";
}

TEST(BodyOutline, ReadInSiAndShownAsWritten) {
  const eval::ExperimentSpec x =
      test::first_experiment(script("  body_outline [(-3cm, -2cm), (40mm, 0cm), (-3cm, 2cm)]\n  body_radius 4cm"),
                             "outline.esc");
  ASSERT_EQ(x.robot.outline.size(), 3u);
  EXPECT_DOUBLE_EQ(x.robot.outline[0].x, -0.03);
  EXPECT_DOUBLE_EQ(x.robot.outline[1].x, 0.04);
  EXPECT_DOUBLE_EQ(x.robot.outline[2].y, 0.02);
  EXPECT_EQ(x.resolved_settings.at("robot.body_outline"), "[(-0.03 m, -0.02 m), (0.04 m, 0 m), (-0.03 m, 0.02 m)]");
  // The disc by default, as before the setting existed.
  EXPECT_EQ(test::paper().resolved_settings.at("robot.body_outline"), "[]");
  EXPECT_TRUE(test::paper().robot.outline.empty());
}

TEST(BodyOutline, TheThymioOfTheStandardLibrary) {
  const eval::ExperimentSpec x = test::first_experiment(
      "import \"lib/thymio2.esc\"\n"
      "arena a { size 1m x 1m }\n"
      "fitness f { step: speed * (1 - prox_horizontal[2]) }\n"
      "controller c = mlp(prox_horizontal[0..6] -> wheels)\n"
      "experiment e { arena a  robot thymio2  fitness f  compare c }\n",
      "thymio.esc");
  ASSERT_EQ(x.robot.outline.size(), 13u);
  EXPECT_DOUBLE_EQ(x.robot.outline[0].x, -0.03);   // the flat back, 3 cm behind the axle
  EXPECT_DOUBLE_EQ(x.robot.outline[6].x, 0.08);    // the front of the arc
  EXPECT_DOUBLE_EQ(x.robot.body_radius_m, 0.08);
  EXPECT_EQ(x.robot.ir.mounts.size(), 7u);
  EXPECT_EQ(x.robot.ir.name, "prox_horizontal");
  EXPECT_EQ(x.controllers.at(0).mlp.inputs.size(), 7u);
}

// Its front middle sensor (prox.horizontal[2], 79.5 mm ahead of the axle) facing a wall reads
// Enki's curve over its peak (docs/robot-model.md's table for the Thymio II), the table's
// points and halfway between them, and 0 from its 14 cm range on.
TEST(BodyOutline, TheThymiosFrontSensorReadsEnkisCurve) {
  const eval::ExperimentSpec x = test::first_experiment(
      "import \"lib/thymio2.esc\"\narena a { size 1m x 1m }\nfitness f { step: speed }\n"
      "controller c = mlp(prox_horizontal[0..6] -> wheels)\n"
      "experiment e { arena a  robot thymio2  fitness f  compare c }\n",
      "thymio.esc");
  sim::World world(x.arena, x.robot);
  Rng rng(1);
  const auto enki = [](double d_cm) { return (73 - 0.0009) / (d_cm * d_cm - 0.06 * d_cm + 73); };
  for (const auto& [d_cm, expected] : {std::pair{0.5, (1 + enki(1)) / 2}, {2.0, enki(2)}, {7.0, enki(7)},
                                       {10.0, enki(10)}, {13.5, (enki(13) + enki(14)) / 2}, {14.2, 0.0}}) {
    world.reset({1.0 - 0.0795 - d_cm / 100, 0.5, 0.0});
    std::array<double, sim::kIrSensors> out{};
    world.read_ir(out, rng);
    EXPECT_NEAR(out[2], expected, 1e-4) << d_cm << " cm";
  }
}

TEST(BodyOutline, SetFromTheCommandLine) {
  eval::ExperimentSpec x = test::first_experiment(script("  body_radius 4cm"), "outline.esc");
  EXPECT_EQ(apply_setting(x, "robot.body_outline", "[(-2cm, -2cm), (2cm, -2cm), (2cm, 2cm), (-2cm, 2cm)]"), "");
  ASSERT_EQ(x.robot.outline.size(), 4u);
  EXPECT_DOUBLE_EQ(x.robot.outline[2].y, 0.02);
  EXPECT_NE(apply_setting(x, "robot.body_outline", "[(-2cm, -2cm), (5cm, -2cm), (2cm, 2cm)]")
                .find("outline vertex 1 lies"),
            std::string::npos);
}

TEST(BodyOutline, MistakesAreLocated) {
  std::string out = test::refusal(script("  body_outline [(1cm, -1cm), (3cm, -1cm), (3cm, 1cm), (1cm, 1cm)]"),
                                  "outline.esc");
  EXPECT_NE(out.find("outline.esc:3:16: error: the outline does not hold the point the wheels turn about: that point "
                     "lies 1cm outside an edge"),
            std::string::npos)
      << out;
  out = test::refusal(script("  body_outline [(1cm, 0cm), (0cm, 1cm)]"), "outline.esc");
  EXPECT_NE(out.find("error: an outline needs at least 3 vertices, found 2"), std::string::npos) << out;
  out = test::refusal(script("  body_outline [(1cm, 0cm), (0cm, 1cm, 2cm), (-1cm, 0cm)]"), "outline.esc");
  EXPECT_NE(out.find("outline.esc:3:29: error: each tuple of `body_outline` holds 2 values, this one 3"),
            std::string::npos)
      << out;
  out = test::refusal(script("  body_outline [(1cm, 0deg), (0cm, 1cm), (-1cm, 0cm)]"), "outline.esc");
  EXPECT_NE(out.find("outline.esc:3:24: error: expected a length, found an angle (`deg`)"), std::string::npos) << out;
  out = test::refusal(script("  drive acceleration\n  body_outline [(-1cm, -1cm), (1cm, 0cm), (-1cm, 1cm)]"),
                      "outline.esc");
  EXPECT_NE(out.find("error: an outline needs the differential drive: the acceleration drive moves a disc"),
            std::string::npos)
      << out;
}

// Bumpers: sectors read in SI and shown as written; `bumper[i]` a network input and a fitness
// term, beyond the robot's bumpers an error at the read.
TEST(Bumpers, DeclaredReadAndCheckedAtTheRead) {
  const std::string text =
      "arena a { size 1m x 1m }\n"
      "robot r { bumpers [(-45deg, 45deg), (135deg, 225deg)] }\n"
      "fitness f { step: speed * (1 - bumper[0]) }\n"
      "controller c = mlp(ir[0..7], bumper[0..1] -> wheels)\n"
      "experiment e { arena a  robot r  fitness f  compare c }\n";
  const eval::ExperimentSpec x = test::first_experiment(text, "bumpers.esc");
  ASSERT_EQ(x.robot.bumpers.size(), 2u);
  EXPECT_DOUBLE_EQ(x.robot.bumpers[1].to_rad, 225 * std::numbers::pi / 180);
  EXPECT_EQ(x.controllers.at(0).mlp.inputs.at(9), expr::slot::bumper + 1);
  EXPECT_EQ(test::paper().resolved_settings.at("robot.bumpers"), "[]");
  std::string wide = text;
  wide.replace(wide.find("bumper[0..1]"), 12, "bumper[0..2]");
  const std::string out = test::refusal(wide, "bumpers.esc");
  EXPECT_NE(out.find("bumpers.esc:4:30: error: `bumper[2]` reads bumper 2, but the robot of experiment `e` has 2 "
                     "(`bumper[0]` .. `bumper[1]`)"),
            std::string::npos)
      << out;
}

}  // namespace
}  // namespace esc::compiler
