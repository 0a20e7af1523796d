// Control steps per second of one simulated Khepera on one core: 8 IR readings and one
// World::step (motors with inertia, Bullet substeps, contacts), in a 60 cm x 60 cm arena
// with two cylinders; the robot is put back at a random free pose when it collides. Then
// the ambient-light reading alone, and the energy experiment's step (lights, a random
// recharge zone, the accumulator).
#include <benchmark/benchmark.h>

#include <array>

#include "runtime/sim/world.hpp"

namespace {

esc::sim::ArenaSpec bench_arena() {
  esc::sim::ArenaSpec a;
  a.width_m = 0.6;
  a.height_m = 0.6;
  a.cylinders.push_back({{0.2, 0.4}, 0.03});
  a.cylinders.push_back({{0.42, 0.22}, 0.025});
  return a;
}

esc::sim::ArenaSpec free_arena() {
  esc::sim::ArenaSpec a;
  a.width_m = 0.6;
  a.height_m = 0.6;
  return a;
}

// Commands alternate every 20 steps between straight, two arcs and a turn in place.
constexpr std::array<std::array<double, 2>, 4> kCommands = {
    {{1.0, 1.0}, {1.0, 0.4}, {0.4, 1.0}, {-1.0, 1.0}}};

void run_steps(benchmark::State& state, esc::sim::RobotParams robot, bool reset_on_collision) {
  esc::sim::World world(bench_arena(), robot);
  esc::Rng rng(1);
  esc::Rng noise(2);
  world.reset(world.random_free_pose(rng));
  std::array<double, esc::sim::kIrSensors> ir{};
  long step = 0;
  long collisions = 0;
  for (auto _ : state) {
    world.read_ir(ir, noise);
    const auto& c = kCommands[static_cast<std::size_t>((step / 20) % 4)];
    world.step(c[0], c[1]);
    benchmark::DoNotOptimize(ir.data());
    if (world.state().collided) {
      ++collisions;
      if (reset_on_collision) world.reset(world.random_free_pose(rng));
    }
    ++step;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["collided_frac"] =
      static_cast<double>(collisions) / static_cast<double>(state.iterations());
}

// Arguments: physics substeps, inertia (0/1).
void BM_SimStep(benchmark::State& state) {
  esc::sim::RobotParams robot;
  robot.physics_substeps = static_cast<int>(state.range(0));
  robot.motor.inertia = state.range(1) != 0;
  run_steps(state, robot, true);
}
BENCHMARK(BM_SimStep)->Args({2, 1})->Args({1, 1})->Args({5, 1})->Args({10, 1})->Args({2, 0});

// Never reset: the robot spends much of its time pressed against walls and cylinders.
void BM_SimStepInContact(benchmark::State& state) {
  esc::sim::RobotParams robot;
  robot.physics_substeps = static_cast<int>(state.range(0));
  run_steps(state, robot, false);
}
BENCHMARK(BM_SimStepInContact)->Arg(2);

void BM_SimReadIr(benchmark::State& state) {
  esc::sim::RobotParams robot;
  robot.ir.noise_sd = state.range(0) != 0 ? 0.05 : 0.0;
  esc::sim::World world(bench_arena(), robot);
  world.reset({0.1, 0.35, 0.3});  // near a wall and a cylinder
  esc::Rng noise(2);
  std::array<double, esc::sim::kIrSensors> ir{};
  for (auto _ : state) {
    world.read_ir(ir, noise);
    benchmark::DoNotOptimize(ir.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SimReadIr)->Arg(0)->Arg(1);

// The homing arena of the paper's energy experiment: no obstacles, a recharge zone placed
// at random at each start with a light above it.
esc::sim::ArenaSpec homing_arena(int lights) {
  esc::sim::ArenaSpec a;
  a.width_m = 0.6;
  a.height_m = 0.6;
  esc::sim::Zone z;
  z.radius_m = 0.08;
  z.random_position = true;
  z.recharge = true;
  a.zones.push_back(z);
  esc::sim::LightSource l;
  l.above_zone = 0;
  a.lights.push_back(l);
  for (int i = 1; i < lights; ++i) {
    esc::sim::LightSource extra;
    extra.position_m = {0.05 + 0.1 * i, 0.55};
    a.lights.push_back(extra);
  }
  return a;
}

// Ambient light alone, 1 or 2 lights: range(0) lights, range(1) 1 = two cylinders in the
// arena (some sensors' rays occluded), range(2) 1 = noise.
void BM_SimReadLight(benchmark::State& state) {
  esc::sim::RobotParams robot;
  robot.light.noise_sd = state.range(2) != 0 ? 0.05 : 0.0;
  esc::sim::ArenaSpec arena = state.range(1) != 0 ? bench_arena() : free_arena();
  arena.lights.push_back({{0.3, 0.5}, 0.0, 1.0, -1});
  if (state.range(0) > 1) arena.lights.push_back({{0.1, 0.1}, 0.05, 1.0, -1});
  esc::sim::World world(arena, robot);
  world.reset({0.1, 0.35, 0.3});
  esc::Rng noise(2);
  std::array<double, esc::sim::kLightSensors> light{};
  for (auto _ : state) {
    world.read_light(light, noise);
    benchmark::DoNotOptimize(light.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SimReadLight)->Args({1, 0, 0})->Args({1, 1, 0})->Args({2, 1, 0})->Args({1, 0, 1});

// The energy experiment's step: IR and light readings, one World::step with energy on
// (recharge zone tested at every substep), zones, reach and sweep bookkeeping; a new epoch
// (random zone, random pose) when the accumulator is empty or every 1000 steps.
void BM_SimStepHoming(benchmark::State& state) {
  esc::sim::RobotParams robot;
  robot.energy.enabled = true;
  esc::sim::World world(homing_arena(static_cast<int>(state.range(0))), robot);
  esc::Rng rng(1);
  esc::Rng noise(2);
  world.begin_epoch(rng);
  std::array<double, esc::sim::kIrSensors> ir{};
  std::array<double, esc::sim::kLightSensors> light{};
  long step = 0;
  long epochs = 1;
  for (auto _ : state) {
    world.read_ir(ir, noise);
    world.read_light(light, noise);
    const auto& c = kCommands[static_cast<std::size_t>((step / 20) % 4)];
    world.step(c[0], c[1]);
    benchmark::DoNotOptimize(ir.data());
    benchmark::DoNotOptimize(light.data());
    ++step;
    if (world.state().floor.energy_empty || world.state().collided || step % 1000 == 0) {
      world.begin_epoch(rng);
      ++epochs;
    }
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["steps_per_epoch"] =
      static_cast<double>(state.iterations()) / static_cast<double>(epochs);
}
BENCHMARK(BM_SimStepHoming)->Arg(1)->Arg(2);

}  // namespace

// Standalone runner for the local build (tests/sim); `esc bench` links these benchmarks
// into its own main.
#ifdef ESC_SIM_BENCH_MAIN
BENCHMARK_MAIN();
#endif
