// Lights, zones, energy, Elman networks and supervisors compile to the runtime's specs.
#include <gtest/gtest.h>

#include <variant>

#include "helpers.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;

const char* kScript = R"(
arena a {
  size 60cm x 40cm
  zone base circle radius 5cm at (10cm, 10cm) visible
  zone recharge rect 10cm x 8cm at random invisible recharge
  light lamp at (30cm, 20cm) height 3cm intensity 0.5
  light beacon above recharge
  sweep_cell 5cm
  reach_radius 6cm
}
robot r { energy on  energy_discharge 200  energy_recharge 50  light_half_distance 10cm  light_noise 0.05 }
behavior forward(p) { wheels(p, p) }
behavior turn(l, r) { wheels(l, r) }
behavior halt() { wheels(0, 0) }
behavior home() { wheels(1 - in(recharge), reached(beacon)) }
fitness f { step: if in(recharge) then 0 else max(forward_speed, 0) + reached(lamp) }
controller CC = elman(ir[0..7], light[0..7], energy -> hidden 5 -> wheels)
controller SC = symbolic(elman(ir[0..7] -> hidden 4), actions [forward, home])
controller SV = supervisor(elman(ir[0..7], light[0..7], energy -> hidden 5),
                           behaviors [forward(0.5), turn(-0.3, 0.3), halt, home])
experiment e { arena a  robot r  fitness f  compare CC, SC, SV }
)";

const control::ControllerSpec& find(const eval::ExperimentSpec& x, const std::string& name) {
  for (const auto& c : x.controllers)
    if (c.name == name) return c;
  throw std::runtime_error("no controller " + name);
}

TEST(ArenaFeatures, LightsZonesAndEnergyInSi) {
  const auto r = compile_source(kScript, "features.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  ASSERT_EQ(r.experiments.size(), 1u);
  const eval::ExperimentSpec& x = r.experiments[0];
  ASSERT_EQ(x.arena.zones.size(), 2u);
  EXPECT_EQ(x.arena.zones[0].shape, sim::ZoneShape::Circle);
  EXPECT_DOUBLE_EQ(x.arena.zones[0].radius_m, 0.05);
  EXPECT_DOUBLE_EQ(x.arena.zones[0].center_m.x, 0.1);
  EXPECT_TRUE(x.arena.zones[0].visible);
  EXPECT_FALSE(x.arena.zones[0].random_position);
  EXPECT_FALSE(x.arena.zones[0].recharge);
  EXPECT_EQ(x.arena.zones[1].shape, sim::ZoneShape::Rectangle);
  EXPECT_DOUBLE_EQ(x.arena.zones[1].size_m.x, 0.1);
  EXPECT_DOUBLE_EQ(x.arena.zones[1].size_m.y, 0.08);
  EXPECT_FALSE(x.arena.zones[1].visible);
  EXPECT_TRUE(x.arena.zones[1].random_position);
  EXPECT_TRUE(x.arena.zones[1].recharge);
  ASSERT_EQ(x.arena.lights.size(), 2u);
  EXPECT_DOUBLE_EQ(x.arena.lights[0].position_m.x, 0.3);
  EXPECT_DOUBLE_EQ(x.arena.lights[0].position_m.y, 0.2);
  EXPECT_DOUBLE_EQ(x.arena.lights[0].height_m, 0.03);
  EXPECT_DOUBLE_EQ(x.arena.lights[0].intensity, 0.5);
  EXPECT_EQ(x.arena.lights[0].above_zone, -1);
  EXPECT_EQ(x.arena.lights[1].above_zone, 1);
  EXPECT_DOUBLE_EQ(x.arena.sweep_cell_m, 0.05);
  EXPECT_DOUBLE_EQ(x.arena.reach_radius_m, 0.06);

  EXPECT_TRUE(x.robot.energy.enabled);
  EXPECT_EQ(x.robot.energy.discharge_steps, 200);
  EXPECT_EQ(x.robot.energy.recharge_steps, 50);
  EXPECT_DOUBLE_EQ(x.robot.light.half_distance_m, 0.1);
  EXPECT_DOUBLE_EQ(x.robot.light.noise_sd, 0.05);
  EXPECT_EQ(x.resolved_settings.at("robot.energy"), "on");
  EXPECT_EQ(x.resolved_settings.at("robot.energy_discharge"), "200");
  EXPECT_EQ(x.resolved_settings.at("arena.zones"), "2");
  EXPECT_EQ(x.resolved_settings.at("arena.lights"), "2");

  eval::ExperimentSpec y = x;
  EXPECT_EQ(apply_setting(y, "robot.energy", "off"), "");
  EXPECT_FALSE(y.robot.energy.enabled);
  EXPECT_EQ(apply_setting(y, "robot.energy_recharge", "80"), "");
  EXPECT_EQ(y.robot.energy.recharge_steps, 80);
  EXPECT_EQ(y.resolved_settings.at("robot.energy"), "off");
}

TEST(ArenaFeatures, InAndReachedReadTheSlotOfTheirZoneAndLight) {
  const auto r = compile_source(kScript, "features.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::ExperimentSpec& x = r.experiments[0];
  expr::Frame f{};
  f[expr::slot::forward_speed] = 0.5;
  EXPECT_DOUBLE_EQ(x.fitness.step.eval(f), 0.5);
  f[expr::slot::in_zone + 1] = 1.0;   // in(recharge): the second zone
  EXPECT_DOUBLE_EQ(x.fitness.step.eval(f), 0.0);
  f[expr::slot::in_zone + 1] = 0.0;
  f[expr::slot::in_zone + 0] = 1.0;   // in(base) does not matter
  f[expr::slot::reached + 0] = 1.0;   // reached(lamp): the first light
  EXPECT_DOUBLE_EQ(x.fitness.step.eval(f), 1.5);

  // Behaviors resolve in the experiment's arena too.
  const auto& sc = find(x, "SC");
  ASSERT_EQ(sc.actions.size(), 2u);
  expr::Frame g{};
  g[expr::slot::reached + 1] = 1.0;   // reached(beacon)
  g[expr::slot::in_zone + 1] = 1.0;
  EXPECT_DOUBLE_EQ(sc.actions[1].left.eval(g), 0.0);
  EXPECT_DOUBLE_EQ(sc.actions[1].right.eval(g), 1.0);
}

TEST(ArenaFeatures, ElmanAndSupervisorControllers) {
  const auto r = compile_source(kScript, "features.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  const eval::ExperimentSpec& x = r.experiments[0];
  const auto& cc = find(x, "CC");
  EXPECT_EQ(cc.mlp.kind, control::NetworkKind::Elman);
  EXPECT_EQ(cc.head, control::Head::Classical);
  EXPECT_EQ(cc.mlp.inputs.size(), 17u);
  EXPECT_EQ(cc.mlp.inputs[8], expr::slot::light);
  EXPECT_EQ(cc.mlp.inputs[16], expr::slot::energy);
  ASSERT_EQ(cc.mlp.hidden.size(), 1u);
  EXPECT_EQ(cc.genome_size(), 127u);   // 5 * (1 + 17 + 5) + 2 * (1 + 5)

  const auto& sc = find(x, "SC");
  EXPECT_EQ(sc.head, control::Head::Symbolic);
  EXPECT_EQ(sc.mlp.kind, control::NetworkKind::Elman);

  const auto& sv = find(x, "SV");
  EXPECT_EQ(sv.head, control::Head::Supervisor);
  EXPECT_EQ(sv.mlp.kind, control::NetworkKind::Elman);
  ASSERT_EQ(sv.behaviors.size(), 4u);
  EXPECT_EQ(sv.behaviors[0].name, "forward(0.5)");
  const auto* fwd = std::get_if<control::BehaviorCall>(&sv.behaviors[0].what);
  ASSERT_NE(fwd, nullptr);
  EXPECT_EQ(fwd->behavior.name, "forward");
  EXPECT_EQ(fwd->args, std::vector<double>{0.5});
  const auto* turn = std::get_if<control::BehaviorCall>(&sv.behaviors[1].what);
  ASSERT_NE(turn, nullptr);
  EXPECT_EQ(turn->args, (std::vector<double>{-0.3, 0.3}));
  EXPECT_EQ(sv.behaviors[2].name, "halt");
  EXPECT_TRUE(std::get<control::BehaviorCall>(sv.behaviors[2].what).args.empty());
  EXPECT_EQ(sv.output_count(), 4);
  EXPECT_EQ(sv.genome_size(), 5u * (1 + 17 + 5) + 4u * (1 + 5));
}

TEST(ArenaFeatures, ZoneNamesAreLocalToTheArena) {
  // The same fitness is fine with one arena and an error with another.
  const std::string script =
      "arena a { size 60cm x 60cm  zone home circle radius 5cm at (30cm, 30cm) }\n"
      "arena b { size 60cm x 60cm }\n"
      "fitness f { step: in(home) }\n"
      "controller c = mlp(ir[0..7] -> wheels)\n"
      "experiment ea { arena a  fitness f  compare c }\n"
      "experiment eb { arena b  fitness f  compare c }\n";
  const auto r = compile_source(script, "local.esc", options());
  EXPECT_FALSE(r.ok());
  const std::string out = rendered(r);
  EXPECT_NE(out.find("local.esc:3:22: error: unknown zone `home` in arena `b`"), std::string::npos) << out;
  EXPECT_EQ(r.diagnostics.size(), 1u) << out;
}

}  // namespace
}  // namespace esc::compiler
