// A group's control step against one robot's (issue 45, docs/groups.md): N Kheperas (motor
// inertia, 8 IR each) in one world, each reading its IR (which meets the other robots found
// through the grid) and then the group stepping once. `free`: a robot in the middle of each
// square metre of the arena driving a circle of 11 cm radius, meeting nothing; `crowd`: one
// robot per 15 cm x 15 cm at random, driving straight, in arcs and turning, pressed against each
// other and the walls. Items are robot control steps: robot_steps_per_s at N against N = 1 is
// the scaling (issue 45 asks N robots to cost at most 1.2 N times one, up to N = 20).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <vector>

#include "runtime/sim/world.hpp"

namespace {

// Commands alternate every 20 steps between straight, two arcs and a turn in place, each
// robot a few steps out of phase with the one before.
constexpr std::array<std::array<double, 2>, 4> kCommands = {{{1.0, 1.0}, {1.0, 0.4}, {0.4, 1.0}, {-1.0, 1.0}}};

void BM_SimGroup(benchmark::State& state) {
  const auto robots = static_cast<std::size_t>(state.range(0));
  const bool crowd = state.range(1) != 0;
  // `free` rounds the side up to whole metres: a robot in the middle of each.
  const double side = crowd ? std::sqrt(static_cast<double>(robots)) * 0.15 : std::ceil(std::sqrt(static_cast<double>(robots)));
  esc::sim::ArenaSpec arena;
  arena.width_m = side;
  arena.height_m = side;
  esc::sim::RobotParams khepera;
  khepera.motor.inertia = true;
  esc::sim::World world(arena, std::vector<esc::sim::RobotParams>(robots, khepera));
  esc::Rng rng(1);
  if (crowd) {
    world.reset(world.random_free_poses(rng));
  } else {
    std::vector<esc::sim::Pose> lattice;
    const auto columns = static_cast<std::size_t>(std::ceil(side));
    for (std::size_t i = 0; i < robots; ++i)
      lattice.push_back({0.5 + static_cast<double>(i % columns), 0.5 + static_cast<double>(i / columns), 0.0});
    world.reset(lattice);
  }
  std::vector<esc::sim::DriveCommand> commands(robots);
  std::array<double, esc::sim::kIrSensors> ir{};
  long step = 0;
  long collisions = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < robots; ++i) {
      world.read_ir(ir, rng, i);
      benchmark::DoNotOptimize(ir.data());
      const auto& c = kCommands[static_cast<std::size_t>((step + 7 * static_cast<long>(i)) / 20 % 4)];
      commands[i] = crowd ? esc::sim::DriveCommand{c[0], c[1]} : esc::sim::DriveCommand{1.0, 0.6};
    }
    world.step(commands, rng);
    for (std::size_t i = 0; i < robots; ++i) collisions += world.state(i).collided ? 1 : 0;
    ++step;
  }
  const auto robot_steps = static_cast<double>(state.iterations()) * static_cast<double>(robots);
  state.SetItemsProcessed(static_cast<std::int64_t>(robot_steps));
  state.counters["robot_steps_per_s"] = benchmark::Counter(robot_steps, benchmark::Counter::kIsRate);
  state.counters["collided_frac"] = static_cast<double>(collisions) / robot_steps;
}
BENCHMARK(BM_SimGroup)
    ->ArgNames({"robots", "crowd"})
    ->ArgsProduct({{1, 2, 5, 10, 20, 50}, {0, 1}});

}  // namespace
