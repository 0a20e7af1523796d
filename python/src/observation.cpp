#include "python/src/observation.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace esc::python {

namespace {

std::string indexed(std::string_view name, expr::Slot index) { return std::string(name) + "[" + std::to_string(index) + "]"; }

}  // namespace

std::string slot_name(expr::Slot slot, const sim::RobotParams& robot) {
  if (slot >= expr::slot::ir && slot < expr::slot::ir + expr::kIrCount) return indexed(robot.ir.name, slot - expr::slot::ir);
  if (slot >= expr::slot::ground_sensor && slot < expr::slot::ground_sensor + expr::kGroundSensorCount)
    return indexed(robot.ground.name, slot - expr::slot::ground_sensor);
  for (const expr::Observable& o : expr::kObservables)
    if (slot >= o.first && slot < o.first + o.count) return o.indexed ? indexed(o.name, slot - o.first) : std::string(o.name);
  for (const expr::ParametrisedObservable& o : expr::kParametrised)
    if (slot >= o.first && slot < o.first + o.count) return indexed(o.name, slot - o.first);
  if (slot == expr::slot::acting) return "acting";
  if (slot >= expr::slot::param && slot < expr::kFrameSize) return indexed("param", slot - expr::slot::param);
  return "slot " + std::to_string(slot);
}

SlotRange slot_range(expr::Slot slot, const eval::ExperimentSpec& spec) {
  namespace s = expr::slot;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double last_step = spec.steps > 0 ? spec.steps - 1 : 0;
  if (slot == s::forward_speed || (slot >= s::wheels && slot < s::wheels + expr::kWheelCount)) return {-1.0, 1.0};
  if (slot == s::step) return {0.0, last_step};
  if (slot == s::time) return {0.0, last_step * spec.robot.control_step_s};
  if (slot == s::epoch || slot == s::cells_visited) return {0.0, kInf};
  if (slot == s::acting) return {-1.0, static_cast<double>(spec.choice_ids) - 1.0};
  if (slot >= s::param && slot < s::param + expr::kMaxParams) return {-kInf, kInf};
  // The navigator's: the body's centre stays in the arena, and no point of it is farther
  // from the goal than the arena's diagonal.
  if (slot == s::x || slot == s::centroid_x) return {0.0, spec.arena.width_m};
  if (slot == s::y || slot == s::centroid_y) return {0.0, spec.arena.height_m};
  if (slot == s::robots || (slot >= s::clusters && slot < s::cluster_size + expr::kMaxClusterRadii))
    return {1.0, static_cast<double>(spec.robots)};
  if (slot >= s::centroid_moved && slot <= s::spread) return {0.0, std::hypot(spec.arena.width_m, spec.arena.height_m)};
  if (slot == s::heading) return {-std::numbers::pi, std::numbers::pi};
  if (slot == s::goal_distance) return {0.0, std::hypot(spec.arena.width_m, spec.arena.height_m)};
  return {0.0, 1.0};   // speeds, sensors (rangefinders and radars too), booleans, energy, noise
}

std::vector<expr::Slot> senses(const sim::RobotParams& robot) {
  std::vector<expr::Slot> slots;
  const auto add = [&](expr::Slot first, std::size_t count) {
    for (expr::Slot i = 0; i < count; ++i) slots.push_back(first + i);
  };
  add(expr::slot::ir, robot.ir.mounts.size());
  add(expr::slot::light, robot.ir.mounts.size());
  add(expr::slot::range, robot.rangefinders.angles_rad.size());
  add(expr::slot::radar, static_cast<std::size_t>(robot.radars));
  add(expr::slot::ground_sensor, robot.ground.mounts.size());
  add(expr::slot::bumper, robot.bumpers.size());
  slots.push_back(expr::slot::energy);
  return slots;
}

}  // namespace esc::python
