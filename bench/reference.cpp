#include "bench/reference.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <numbers>

#include "bench/cpu_time.hpp"
#include "runtime/core/rng.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/sim/world.hpp"

namespace esc::bench {

namespace {

struct Tally {
  std::int64_t steps = 0;
  double seconds = 0.0;
  std::uint64_t next = 0;   // the next item
};

// Runs items of `loop` until `seconds` of CPU time have passed; returns this round's rate.
double run_for(const StepLoop& loop, double seconds, Tally& tally) {
  const double start = thread_cpu_seconds();
  std::int64_t steps = 0;
  double elapsed = 0.0;
  while (elapsed < seconds || steps == 0) {
    steps += loop(tally.next++);
    elapsed = thread_cpu_seconds() - start;
  }
  tally.steps += steps;
  tally.seconds += elapsed;
  return static_cast<double>(steps) / elapsed;
}

}  // namespace

Fraction interleave(const StepLoop& loop, const StepLoop& reference, double seconds, int rounds) {
  rounds = std::max(rounds, 1);
  const double slice = seconds / rounds;
  Tally a, b;
  Fraction f;
  f.lowest = std::numeric_limits<double>::infinity();
  f.highest = 0.0;
  for (int r = 0; r < rounds; ++r) {
    // Alternate which goes first, so neither always runs on a cache the other warmed.
    const bool loop_first = r % 2 == 0;
    const double first = run_for(loop_first ? loop : reference, slice, loop_first ? a : b);
    const double second = run_for(loop_first ? reference : loop, slice, loop_first ? b : a);
    const double round = loop_first ? first / second : second / first;
    f.lowest = std::min(f.lowest, round);
    f.highest = std::max(f.highest, round);
  }
  f.steps_per_s = static_cast<double>(a.steps) / a.seconds;
  f.reference_per_s = static_cast<double>(b.steps) / b.seconds;
  return f;
}

std::vector<std::vector<double>> random_genomes(std::size_t size, std::size_t count, double lower, double upper) {
  Rng rng(12345);
  std::vector<std::vector<double>> g(count, std::vector<double>(size));
  for (auto& genome : g)
    for (double& x : genome) x = rng.uniform(lower, upper);
  return g;
}

StepLoop esc_loop(const eval::ExperimentSpec& experiment, const control::ControllerSpec& controller,
                  const std::vector<std::vector<double>>& genomes) {
  auto evaluator = std::make_shared<eval::Evaluator>(experiment);
  return [evaluator, &controller, &genomes](std::uint64_t i) {
    return evaluator->evaluate(controller, genomes[i % genomes.size()], i).steps;
  };
}

plain::Setup plain_setup(const eval::ExperimentSpec& e) {
  plain::Setup s;
  s.width_m = e.arena.width_m;
  s.height_m = e.arena.height_m;
  for (const sim::CylinderObstacle& c : e.arena.cylinders) s.cylinders.push_back({c.center_m.x, c.center_m.y, c.radius_m});
  const sim::RobotParams& r = e.robot;
  s.radius_m = r.body_radius_m;
  s.wheel_base_m = r.wheel_base_m;
  s.max_speed_mps = r.motor.max_speed_mps;
  s.time_constant_s = r.motor.time_constant_s;
  s.max_accel_mps2 = r.motor.max_accel_mps2;
  s.control_step_s = r.control_step_s;
  s.substeps = r.physics_substeps;
  s.ir_range_m = r.ir.range_m;
  s.ir_aperture_rad = r.ir.aperture_rad;
  s.ir_rays = r.ir.rays;
  s.light_half_distance_m = r.light.half_distance_m;
  if (!e.arena.lights.empty()) s.light_height_m = e.arena.lights.front().height_m;
  if (!e.arena.zones.empty()) s.zone_radius_m = e.arena.zones.front().radius_m;
  s.discharge_steps = r.energy.discharge_steps;
  s.recharge_steps = r.energy.recharge_steps;
  s.epochs = e.epochs;
  s.steps = e.steps;
  return s;
}

StepLoop simulator_loop(const eval::ExperimentSpec& experiment, Situation situation) {
  constexpr int kStepsPerItem = 1000;
  // Circling: the wheels' speeds 1 and 0.6 of the top speed turn the centre on a circle of
  // 0.8 / 0.4 half wheel bases (10.6 cm for the Khepera) around the arena's centre.
  constexpr double kOuter = 1.0;
  constexpr double kInner = 0.6;
  constexpr double kPressing = 0.5;
  const sim::ArenaSpec& arena = experiment.arena;
  const sim::RobotParams& robot = experiment.robot;
  const double circle_m = 0.5 * robot.wheel_base_m * (kOuter + kInner) / (kOuter - kInner);
  const sim::Pose start = situation == Situation::Free
                              ? sim::Pose{arena.width_m / 2, arena.height_m / 2 - circle_m, 0.0}
                              : sim::Pose{robot.body_radius_m, arena.height_m / 2, std::numbers::pi};
  const double left = situation == Situation::Free ? kInner : kPressing;
  const double right = situation == Situation::Free ? kOuter : kPressing;
  auto world = std::make_shared<sim::World>(arena, robot);
  return [world, start, left, right](std::uint64_t i) {
    Rng noise(i);
    std::array<double, sim::kIrSensors> ir{};
    world->reset(start);
    for (int s = 0; s < kStepsPerItem; ++s) {
      world->read_ir(ir, noise);
      world->step(left, right);
    }
    return std::int64_t{kStepsPerItem};
  };
}

}  // namespace esc::bench
