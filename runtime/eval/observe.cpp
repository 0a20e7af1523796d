#include "runtime/eval/observe.hpp"

#include "runtime/core/rng.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <variant>

namespace esc::eval {

static_assert(expr::kMaxZones == sim::kMaxZones, "in(zone) slots: one per zone an arena may hold");
static_assert(expr::kMaxLights == sim::kMaxLights, "reached(light) slots: one per light");
static_assert(expr::kLightCount == sim::kLightSensors);
static_assert(expr::kIrCount == sim::kIrSensors);
static_assert(expr::kRangeCount == sim::kMaxRangefinders, "range[i] slots: one per rangefinder a robot may have");
static_assert(expr::kRadarCount == sim::kMaxRadars, "radar[i] slots: one per radar slice");
static_assert(expr::kGroundSensorCount == sim::kMaxGroundSensors, "ground_sensor[i] slots: one per ground sensor");
static_assert(expr::kBumperCount == sim::kMaxBumpers, "bumper[i] slots: one per bumper");

namespace {

// Where the robot is, where the goal lies from it and what the rangefinders read. Slots of
// rangefinders and radars the robot does not have, and of a goal the arena does not have,
// are left as they are.
void observe_navigation(const sim::World& world, std::size_t robot, expr::Frame& frame) noexcept {
  const sim::Pose& pose = world.state(robot).pose;
  frame[expr::slot::x] = pose.x_m;
  frame[expr::slot::y] = pose.y_m;
  frame[expr::slot::heading] = pose.heading_rad;
  world.read_rangefinders(std::span<double>(frame).subspan(expr::slot::range, expr::kRangeCount), robot);
  world.read_ground(std::span<double>(frame).subspan(expr::slot::ground_sensor, expr::kGroundSensorCount), robot);
  const std::optional<sim::Vec2>& goal = world.arena().goal;
  if (!goal) return;
  frame[expr::slot::goal_distance] = std::hypot(goal->x - pose.x_m, goal->y - pose.y_m);
  const int slices = world.robot(robot).radars;
  if (slices == 0) return;
  const int hit = world.goal_slice(robot);
  for (int i = 0; i < slices; ++i) frame[expr::slot::radar + static_cast<expr::Slot>(i)] = i == hit ? 1.0 : 0.0;
}

}  // namespace

void observe_robot(const sim::World& world, std::size_t robot, const std::array<double, sim::kIrSensors>& ir,
                   expr::Frame& frame) noexcept {
  const sim::RobotState& s = world.state(robot);
  const sim::RobotParams& p = world.robot(robot);
  const double full_step_m = p.motor.max_speed_mps * p.control_step_s;
  // The acceleration drive's actuators are its turn rate and its speed, each over its top.
  const bool wheeled = p.drive == sim::DriveKind::Differential;
  const double left = s.wheel_speed_mps[0] / (wheeled ? p.motor.max_speed_mps : p.turn.max_rate_radps);
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
  for (expr::Slot i = 0; i < expr::kBumperCount; ++i) frame[expr::slot::bumper + i] = (s.bumped >> i) & 1U ? 1.0 : 0.0;
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
  observe_navigation(world, robot, frame);
}

sim::Vec2 centroid(const sim::World& world) noexcept {
  sim::Vec2 sum;
  for (std::size_t i = 0; i < world.robots(); ++i) {
    const sim::Pose& p = world.state(i).pose;
    sum = {sum.x + p.x_m, sum.y + p.y_m};
  }
  const auto n = static_cast<double>(world.robots());
  return {sum.x / n, sum.y / n};
}

void observe_group(const sim::World& world, sim::Vec2 start, bool pairs, std::span<expr::Frame> frames) noexcept {
  const std::size_t n = world.robots();
  const sim::Vec2 c = centroid(world);
  const auto at = [&](std::size_t i) { return sim::Vec2{world.state(i).pose.x_m, world.state(i).pose.y_m}; };
  const double diagonal = std::hypot(world.arena().width_m, world.arena().height_m);
  double spread = 0.0;
  double pair_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const sim::Vec2 p = at(i);
    const double to_centroid = std::hypot(p.x - c.x, p.y - c.y);
    spread = std::max(spread, to_centroid);
    frames[i][expr::slot::centroid_distance] = to_centroid;
    if (!pairs) continue;
    double nearest2 = diagonal * diagonal;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const double d2 = (p.x - at(j).x) * (p.x - at(j).x) + (p.y - at(j).y) * (p.y - at(j).y);
      nearest2 = std::min(nearest2, d2);
      if (j > i) pair_sum += std::sqrt(d2);
    }
    frames[i][expr::slot::nearest_robot] = std::sqrt(nearest2);
  }
  const double pair_count = static_cast<double>(n * (n - 1) / 2);
  for (std::size_t i = 0; i < n; ++i) {
    expr::Frame& f = frames[i];
    f[expr::slot::robots] = static_cast<double>(n);
    f[expr::slot::centroid_x] = c.x;
    f[expr::slot::centroid_y] = c.y;
    f[expr::slot::centroid_moved] = std::hypot(c.x - start.x, c.y - start.y);
    if (pairs) f[expr::slot::robot_distance] = n > 1 ? pair_sum / pair_count : 0.0;
    f[expr::slot::spread] = spread;
  }
}

void observe_clusters(const sim::World& world, std::span<const double> radii, std::span<expr::Frame> frames,
                      std::span<std::size_t> parent, std::span<std::size_t> size) noexcept {
  const std::size_t n = world.robots();
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t k = 0; k < radii.size(); ++k) {
    const double r2 = radii[k] * radii[k];
    for (std::size_t i = 0; i < n; ++i) {
      parent[i] = i;
      size[i] = 1;
    }
    std::size_t clusters = n;
    for (std::size_t i = 0; i < n; ++i) {
      const sim::Pose& a = world.state(i).pose;
      for (std::size_t j = i + 1; j < n; ++j) {
        const sim::Pose& b = world.state(j).pose;
        const double dx = a.x_m - b.x_m, dy = a.y_m - b.y_m;
        if (dx * dx + dy * dy > r2) continue;
        std::size_t ri = root(i), rj = root(j);
        if (ri == rj) continue;
        if (size[ri] < size[rj]) std::swap(ri, rj);
        parent[rj] = ri;
        size[ri] += size[rj];
        --clusters;
      }
    }
    std::size_t largest = 0;
    for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, size[root(i)]);
    for (std::size_t i = 0; i < n; ++i) {
      expr::Frame& f = frames[i];
      f[expr::slot::clusters + k] = static_cast<double>(clusters);
      f[expr::slot::largest_cluster + k] = static_cast<double>(largest);
      f[expr::slot::cluster_size + k] = static_cast<double>(size[root(i)]);
    }
  }
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

namespace {

bool program_reads(const expr::Program& p, expr::Slot slot) noexcept {
  const auto code = p.code();
  return std::any_of(code.begin(), code.end(),
                     [slot](const expr::Instr& in) { return in.op == expr::Op::Load && in.slot == slot; });
}

// Step aggregates read every step's frame.
bool aggregates_read(const std::vector<expr::StepAggregate>& list, expr::Slot slot) noexcept {
  return std::any_of(list.begin(), list.end(), [slot](const expr::StepAggregate& a) { return program_reads(a.of, slot); });
}

bool behavior_reads(const control::Behavior& b, expr::Slot slot) noexcept {
  return program_reads(b.left, slot) || program_reads(b.right, slot);
}

bool controller_reads(const control::ControllerSpec& c, expr::Slot slot) noexcept {
  if (c.is_tree()) return true;
  for (const control::ControllerSpec& n : c.networks)
    if (controller_reads(n, slot)) return true;
  const auto& inputs = c.mlp.inputs;
  if (std::find(inputs.begin(), inputs.end(), slot) != inputs.end()) return true;
  for (const control::Behavior& a : c.actions)
    if (behavior_reads(a, slot)) return true;
  for (const control::SupervisedBehavior& b : c.behaviors) {
    if (const auto* call = std::get_if<control::BehaviorCall>(&b.what)) {
      if (behavior_reads(call->behavior, slot)) return true;
    } else if (const auto& fixed = std::get<control::FixedController>(b.what);
               fixed.spec == nullptr || controller_reads(*fixed.spec, slot)) {
      return true;
    }
  }
  return false;
}

bool fitness_reads(const FitnessSpec& fitness, expr::Slot slot) noexcept {
  if (program_reads(fitness.step, slot)) return true;
  for (const expr::Program& p : fitness.stop_when)
    if (program_reads(p, slot)) return true;
  // An end term reads the last step's frame.
  for (const auto* end : {&fitness.epoch_end, &fitness.evaluation_end})
    if (*end && program_reads(**end, slot)) return true;
  return aggregates_read(fitness.epoch_aggregates, slot) || aggregates_read(fitness.evaluation_aggregates, slot);
}

}  // namespace

bool reads_slot(const FitnessSpec& fitness, const control::ControllerSpec& controller, expr::Slot slot) noexcept {
  return fitness_reads(fitness, slot) || controller_reads(controller, slot);
}

bool reads_slot(const ExperimentSpec& spec, const control::ControllerSpec& controller, expr::Slot slot) noexcept {
  for (const FitnessSpec& f : spec.further)
    if (fitness_reads(f, slot)) return true;
  for (const DescriptorSpec& d : spec.descriptors)
    if (program_reads(d.program, slot) || aggregates_read(d.aggregates, slot)) return true;
  return reads_slot(spec.fitness, controller, slot);
}

StepperReads stepper_reads(const ExperimentSpec& spec, const control::ControllerSpec& controller) noexcept {
  StepperReads r;
  r.noise = reads_slot(spec, controller, expr::slot::noise);
  r.pairs = reads_slot(spec, controller, expr::slot::nearest_robot) || reads_slot(spec, controller, expr::slot::robot_distance);
  r.group = r.pairs;
  for (expr::Slot s = expr::slot::robots; s < expr::kFrameSize && !r.group; ++s) r.group = reads_slot(spec, controller, s);
  return r;
}

}  // namespace esc::eval
