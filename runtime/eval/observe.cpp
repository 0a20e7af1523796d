#include "runtime/eval/observe.hpp"

#include "runtime/core/rng.hpp"

#include <cmath>
#include <cstddef>

namespace esc::eval {

static_assert(expr::kMaxZones == sim::kMaxZones, "in(zone) slots: one per zone an arena may hold");
static_assert(expr::kMaxLights == sim::kMaxLights, "reached(light) slots: one per light");
static_assert(expr::kLightCount == sim::kLightSensors);
static_assert(expr::kIrCount == sim::kIrSensors);

void observe_robot(const sim::World& world, const std::array<double, sim::kIrSensors>& ir,
                   expr::Frame& frame) noexcept {
  const sim::RobotState& s = world.state();
  const sim::KheperaParams& p = world.robot();
  const double full_step_m = p.motor.max_speed_mps * p.control_step_s;
  const double left = s.wheel_speed_mps[0] / p.motor.max_speed_mps;
  const double right = s.wheel_speed_mps[1] / p.motor.max_speed_mps;
  // The body's origin is its centre of mass (a uniform cylinder), so the centre-of-mass
  // speed is `speed`.
  const double speed = s.displacement_m / full_step_m;
  frame[expr::slot::speed] = speed;
  frame[expr::slot::com_speed] = speed;
  frame[expr::slot::forward_speed] = s.forward_displacement_m / full_step_m;
  frame[expr::slot::wheel_diff] = std::abs(left - right) / 2.0;
  frame[expr::slot::wheels] = left;
  frame[expr::slot::wheels + 1] = right;
  frame[expr::slot::collision] = s.collided ? 1.0 : 0.0;
  for (std::size_t i = 0; i < ir.size(); ++i) frame[expr::slot::ir + i] = ir[i];
  const sim::FloorState& floor = s.floor;
  frame[expr::slot::energy] = floor.energy;
  frame[expr::slot::ground] = floor.ground ? 1.0 : 0.0;
  frame[expr::slot::new_cell] = floor.new_cell ? 1.0 : 0.0;
  frame[expr::slot::cells_visited] = floor.cells_visited;
  // The slots of zones and lights the arena does not have stay 0: their bits are never set.
  const sim::ArenaSpec& arena = world.arena();
  for (expr::Slot z = 0; z < arena.zones.size(); ++z) frame[expr::slot::in_zone + z] = (floor.in_zone >> z) & 1U;
  for (expr::Slot l = 0; l < arena.lights.size(); ++l) frame[expr::slot::reached + l] = (floor.reached >> l) & 1U;
}

void observe_light(const std::array<double, sim::kLightSensors>& light,
                   expr::Frame& frame) noexcept {
  for (std::size_t i = 0; i < light.size(); ++i) frame[expr::slot::light + i] = light[i];
}

void observe_clock(int epoch, int step, double control_step_s, expr::Frame& frame) noexcept {
  frame[expr::slot::epoch] = epoch;
  frame[expr::slot::step] = step;
  frame[expr::slot::time] = step * control_step_s;
}

void observe_noise(std::uint64_t seed, int epoch, int step, expr::Frame& frame) noexcept {
  const std::uint64_t h = derive_seed(seed, {static_cast<std::uint64_t>(epoch), static_cast<std::uint64_t>(step)});
  frame[expr::slot::noise] = static_cast<double>(h >> 11) * 0x1.0p-53;
}

}  // namespace esc::eval
