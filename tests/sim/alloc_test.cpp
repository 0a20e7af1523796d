// step(), read_ir(), read_light() and begin_epoch() do not allocate once Bullet's internal
// arrays have reached their working size. Counts both the global operator new and Bullet's
// own allocator, so it is a binary of its own.
#include <gtest/gtest.h>

#include <LinearMath/btAlignedAllocator.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <cmath>
#include <new>
#include <vector>

#include "runtime/sim/world.hpp"
#include "sim_test_util.hpp"

namespace {
std::atomic<long> g_allocations{0};

void* bt_counting_alloc(size_t size) {
  ++g_allocations;
  return std::malloc(size);
}
void bt_counting_free(void* p) { std::free(p); }
}  // namespace

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace esc::sim {
namespace {

long run(World& world, std::uint64_t seed, int steps) {
  Rng commands(seed);
  Rng noise(seed + 1);
  std::array<double, kIrSensors> ir{};
  std::array<double, kLightSensors> light{};
  Rng start(seed + 2);
  const long before_epoch = g_allocations.load();
  world.begin_epoch(start);  // places the random zone, then the robot
  EXPECT_EQ(g_allocations.load() - before_epoch, 0);
  const long before = g_allocations.load();
  double l = 0.0, r = 0.0;
  for (int i = 0; i < steps; ++i) {
    if (i % 10 == 0) {
      l = commands.uniform(-0.5, 1.0);
      r = commands.uniform(-0.5, 1.0);
    }
    world.read_ir(ir, noise);
    world.read_light(light, noise);
    world.step(l, r);
  }
  return g_allocations.load() - before;
}

ArenaSpec cluttered(int obstacles) {
  ArenaSpec arena;
  Rng rng(5);
  for (int i = 0; i < obstacles; ++i) {
    const Vec2 c{rng.uniform(0.05, 0.55), rng.uniform(0.05, 0.55)};
    if (i % 2 == 0) {
      arena.cylinders.push_back({c, rng.uniform(0.01, 0.04)});
    } else {
      arena.boxes.push_back({c, {rng.uniform(0.02, 0.1), rng.uniform(0.02, 0.1)}, rng.uniform(-3.0, 3.0)});
    }
  }
  // Lights (one above a random recharge zone) and zones: read_light, energy, zones,
  // reach and sweep bookkeeping allocate nothing either.
  test::add_homing_features(arena, {.recharge_radius_m = 0.03,
                                    .mark_center_m = {0.3, 0.3},
                                    .mark_size_m = {0.2, 0.1},
                                    .light_height_m = 0.0,
                                    .free_light = {{0.5, 0.1}, 0.02, 0.7, -1}});
  return arena;
}

TEST(SimAlloc, StepAndReadingsDoNotAllocate) {
  btAlignedAllocSetCustom(&bt_counting_alloc, &bt_counting_free);
  // The disc, and a convex outline (its hull's contacts and its own contact test).
  for (RobotParams robot : {RobotParams{}, test::thymio_like()}) {
    robot.ir.noise_sd = 0.05;
    robot.light.noise_sd = 0.05;
    robot.energy.enabled = true;
    for (int obstacles : {0, 3, 12, 30}) {
      World world(cluttered(obstacles), robot);
      // Free space right after construction, then long trajectories full of contacts
      // (walls, corners, obstacles, robot wedged between them): nothing is allocated, not
      // even the first time a contact appears (the constructor sized Bullet's arrays).
      {
        Rng noise(1);
        std::array<double, kIrSensors> ir{};
        std::array<double, kLightSensors> light{};
        const long before = g_allocations.load();
        for (int i = 0; i < 100; ++i) {
          world.read_ir(ir, noise);
          world.read_light(light, noise);
          world.step(0.0, 0.0);
        }
        EXPECT_EQ(g_allocations.load() - before, 0) << obstacles << " obstacles";
      }
      for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        EXPECT_EQ(run(world, seed, 3000), 0) << obstacles << " obstacles, seed " << seed;
      }
    }
  }
}

// A crowd (robots pressed against each other and the walls, one per 15 cm x 15 cm): from the
// first step of the first epoch on, stepping and reading allocate nothing (the constructor
// grew Bullet's arrays for every robot touching every other).
TEST(SimAlloc, ACrowdsStepsAndReadingsDoNotAllocate) {
  for (const std::size_t n : {2U, 5U, 20U, 50U, 256U}) {
    const double side = 0.15 * std::sqrt(static_cast<double>(n));
    // Every eighth robot gives off light, which the others read as a light where it is.
    std::vector<RobotParams> robots(n);
    for (std::size_t i = 0; i < n; i += 8) robots[i].emission = {0.5, 0.01};
    World world(test::empty_arena(side, side), robots);
    std::vector<DriveCommand> commands(n);
    std::array<double, kIrSensors> ir{};
    std::array<double, kLightSensors> light{};
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Rng rng(seed);
      const long before = g_allocations.load();
      world.begin_epoch(rng);
      for (int step = 0; step < 400; ++step) {
        for (std::size_t i = 0; i < n; ++i) {
          world.read_ir(ir, rng, i);
          world.read_light(light, rng, i);
          const double phase = 0.05 * step + static_cast<double>(i);
          commands[i] = {std::sin(phase), std::cos(1.3 * phase)};
        }
        world.step(commands, rng);
      }
      EXPECT_EQ(g_allocations.load() - before, 0) << n << " robots, epoch " << seed;
    }
  }
}

}  // namespace
}  // namespace esc::sim
