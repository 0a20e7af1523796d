#pragma once
// Sense: turns the simulator's physical state into the observable frame that fitness
// programs, behaviors and controllers read. Observables come from the physical state
// (measured wheel speeds, actual displacement), never from the commands.
#include <array>
#include <cstdint>
#include <span>

#include "runtime/control/controller_spec.hpp"
#include "runtime/eval/experiment.hpp"
#include "runtime/expr/observables.hpp"
#include "runtime/sim/world.hpp"

namespace esc::eval {

// Writes speed, com_speed, forward_speed, wheel_diff, wheels[], collision and ir[], the
// floor and accumulator state: energy, ground, new_cell, cells_visited, in_zone[] (`in(z)`)
// and reached[] (`reached(l)`), and the navigator's observables: x, y, heading, the
// rangefinders' range[] (read here, only for a robot that has some), goal_distance and
// radar[] into `frame`; the slots of zones, lights, rangefinders and radar slices the arena
// or robot does not have, and goal_distance without a goal, are left as they are (0 in a
// frame zeroed at the epoch's start, as the evaluator's is).
// Robot `robot`'s (0 alone).
void observe_robot(const sim::World& world, std::size_t robot, const std::array<double, sim::kIrSensors>& ir,
                   expr::Frame& frame) noexcept;

// The group's centroid (the mean of the robots' centres).
[[nodiscard]] sim::Vec2 centroid(const sim::World& world) noexcept;
// Writes the group's observables into every robot's frame (frames[i] robot i's): robots,
// centroid_x, centroid_y, centroid_moved (from `start`, the centroid at the epoch's start),
// each robot's centroid_distance, and spread; with `pairs` (something reads them), each
// robot's nearest_robot and the robot_distance, from every pair's distance (exact for any
// distance, as a cut of the grid's pairs would not be; a group's size is bounded).
void observe_group(const sim::World& world, sim::Vec2 start, bool pairs, std::span<expr::Frame> frames) noexcept;

// Writes into every robot's frame the group's clusters within each radius radii[k] (robots
// whose centres are within it of each other, directly or through others, make one):
// clusters + k, largest_cluster + k and the robot's cluster_size + k. `parent` and `size`
// are scratch space of a robot each (no allocation).
void observe_clusters(const sim::World& world, std::span<const double> radii, std::span<expr::Frame> frames,
                      std::span<std::size_t> parent, std::span<std::size_t> size) noexcept;

// Writes light[] from an ambient-light reading (World::read_light).
void observe_light(const std::array<double, sim::kLightSensors>& light,
                   expr::Frame& frame) noexcept;

// Writes the clock observables: step (from 0), time in seconds, epoch.
void observe_clock(int epoch, int step, double control_step_s, expr::Frame& frame) noexcept;
// `noise`: a hash of (evaluation seed, epoch, step), so it draws nothing from the
// evaluation's streams: whether a script reads it or not changes no other value.
void observe_noise(std::uint64_t seed, int epoch, int step, expr::Frame& frame) noexcept;

// Whether evaluating `controller` under `fitness` may read frame slot `slot`: a fitness,
// stop or end program, a network input, an action's or behavior's program, a
// sub-controller's; a tree controller is taken to read every slot. The step loop skips
// observables nobody reads.
[[nodiscard]] bool reads_slot(const FitnessSpec& fitness, const control::ControllerSpec& controller,
                              expr::Slot slot) noexcept;
// The same over every objective and descriptor of `spec` too.
[[nodiscard]] bool reads_slot(const ExperimentSpec& spec, const control::ControllerSpec& controller,
                              expr::Slot slot) noexcept;

// What an EpochStepper writes only when something reads it: `noise`, the group's
// observables, and those of them made from every pair (nearest_robot, robot_distance).
struct StepperReads {
  bool noise = false;
  bool group = false;
  bool pairs = false;
};
[[nodiscard]] StepperReads stepper_reads(const ExperimentSpec& spec, const control::ControllerSpec& controller) noexcept;

}  // namespace esc::eval
