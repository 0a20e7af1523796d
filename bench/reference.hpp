#pragma once
// What `esc bench` compares, and how: esc's evaluation of a workload against the plain
// reference of the same workload (bench/plain_*.hpp), and the simulator pressed against a
// wall against the same simulator in free space. Each pair is timed in alternation on one
// core, so that both halves of a fraction see the same machine: on a shared machine, rates
// of runs minutes apart differ by more than the changes they would measure.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "bench/plain_world.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::bench {

// One unit of work (an evaluation, or a fixed number of simulator steps) for item `i`;
// returns the control steps it simulated.
using StepLoop = std::function<std::int64_t(std::uint64_t i)>;

struct Fraction {
  double steps_per_s = 0.0;        // the loop measured
  double reference_per_s = 0.0;    // the loop it is a fraction of
  double lowest = 0.0, highest = 0.0;   // the fraction in the single rounds
  [[nodiscard]] double value() const noexcept { return steps_per_s / reference_per_s; }
};

// Runs `loop` and `reference` in turn, `rounds` times, each for about seconds / rounds of
// this thread's CPU time, and divides the two rates (control steps per CPU second).
[[nodiscard]] Fraction interleave(const StepLoop& loop, const StepLoop& reference, double seconds, int rounds = 10);

// Genomes drawn uniformly in [lower, upper]: the controllers of an early generation.
[[nodiscard]] std::vector<std::vector<double>> random_genomes(std::size_t size, std::size_t count, double lower,
                                                              double upper);

// esc's evaluation of `controller` in `experiment`, item i evaluating genomes[i % size] with
// seed i. The experiment, controller and genomes must outlive the loop.
[[nodiscard]] StepLoop esc_loop(const eval::ExperimentSpec& experiment, const control::ControllerSpec& controller,
                                const std::vector<std::vector<double>>& genomes);

// Every number of the experiment the plain loops read: arena, robot, epochs and steps, the
// first zone's radius and the first light's height.
[[nodiscard]] plain::Setup plain_setup(const eval::ExperimentSpec& experiment);

// The simulator alone: 8 IR readings and one World::step per control step, 1000 steps per
// item, in `experiment`'s arena with its robot. Free: circling at the arena's centre, clear
// of every surface. Pressed: straight into the middle of the left wall at half speed (a
// symbolic behavior's FORWARD at p = 0.5, what zero weights choose), touching it from the
// first step.
enum class Situation { Free, Pressed };
[[nodiscard]] StepLoop simulator_loop(const eval::ExperimentSpec& experiment, Situation situation);

}  // namespace esc::bench
