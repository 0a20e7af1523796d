#pragma once
// Evaluates one genome of one controller: `epochs` epochs from start poses drawn from the
// evaluation's own random stream, each at most `steps` control steps of
//   sense (IR) -> control -> act + physics -> observe -> fitness term -> stop conditions
// (each epoch stepped by an EpochStepper, epoch_stepper.hpp).
// An Evaluator owns one simulated world and reuses it for every evaluation it runs, so a
// worker thread keeps one Evaluator for a whole campaign.
#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "runtime/eval/experiment.hpp"
#include "runtime/eval/step_aggregates.hpp"
#include "runtime/expr/observables.hpp"
#include "runtime/genome/tree/tree.hpp"
#include "runtime/sim/world.hpp"

namespace esc::eval {

class EpochStepper;

struct Evaluation {
  double fitness = 0.0;
  std::int64_t steps = 0;   // control steps simulated (epochs may end early)
  // Steps on which each action (symbolic head) or behavior (supervisor) acted, in
  // ControllerSpec::choice_names() order; empty for a classical head. They add up to `steps`.
  std::vector<std::int64_t> usage;
  // The experiment's further objectives (ExperimentSpec::further), as measured (a minimised
  // one is not negated), and its descriptors (ExperimentSpec::descriptors); empty when it
  // declares none.
  std::vector<double> objectives;
  std::vector<double> descriptors;
};

// A group's observables a replay records (TraceStep::group): centroid_x to spread, named as
// scripts name them (all in metres).
inline constexpr std::size_t kTracedGroupObservables = expr::slot::spread + 1 - expr::slot::centroid_x;
inline constexpr std::array<std::string_view, kTracedGroupObservables> kTracedGroupNames = {
    "centroid_x", "centroid_y", "centroid_moved", "centroid_distance", "nearest_robot", "robot_distance", "spread"};

// One control step of a traced evaluation (the replay of a controller): the state after
// the step's physics, the IR reading taken there, the command and the action that led to it.
// A group's replay has a TraceStep per robot per step, the robots of a step in robot order.
struct TraceStep {
  int epoch = 0;
  int step = 0;                               // from 0 within the epoch
  int robot = 0;                              // from 0; a robot alone is robot 0
  sim::Pose pose;                             // after the step
  std::array<double, sim::kIrSensors> ir{};   // read after the step (the next step's input)
  std::array<double, sim::kLightSensors> light{};   // ambient light, read with the IR
  // The rangefinders' and goal radars' readings, as the `range` and `radar` observables hold
  // them: the first `range_count` / `radar_count` entries, those the robot declares.
  std::array<double, sim::kMaxRangefinders> range{};
  std::size_t range_count = 0;
  std::array<double, sim::kMaxRadars> radar{};
  std::size_t radar_count = 0;
  // The ground sensors (1 over a visible zone) and bumpers (1 on a step with a contact in
  // their sector) the robot declares, as `ground_sensor` and `bumper` hold them.
  std::array<double, sim::kMaxGroundSensors> ground{};
  std::size_t ground_count = 0;
  std::array<double, sim::kMaxBumpers> bumper{};
  std::size_t bumper_count = 0;
  double left_command = 0.0;                  // commands in [-1, 1] chosen by the controller
  double right_command = 0.0;
  double left_speed_mps = 0.0;                // measured wheel speeds after the step
  double right_speed_mps = 0.0;
  int action = -1;                            // symbolic head: index of the acting action
  // The evaluation's fitness so far, every term counted where it applies: an epoch's last
  // step counts the epoch's end terms, the evaluation's last step its own (it is the
  // evaluation's fitness).
  double fitness = 0.0;
  bool collided = false;
  double energy = 1.0;                        // accumulator level after the step
  // Where the arena's zones are this epoch (random ones move at every epoch start); the
  // first `zone_count` entries, in the arena's order.
  std::array<sim::Vec2, sim::kMaxZones> zones{};
  std::size_t zone_count = 0;
  // A group's observables from centroid_x to spread (expr::slot order), as this robot's frame
  // holds them after the step, every one written; `grouped` false for a robot alone, which
  // has none.
  std::array<double, kTracedGroupObservables> group{};
  bool grouped = false;
};

// The most rows a group's stored replay keeps (a row per robot per step): beyond, its blob
// could pass SQLite's 1 GB limit for a value, and as much would be held in memory. `esc
// replay` makes any evaluation again whole. A robot alone's replay is kept whole, as always.
inline constexpr std::size_t kMaxReplayRows = std::size_t{1} << 19;

// How many of `trace`'s first rows to keep within `limit`: all that fit; else whole epochs
// while they fit; else the first epoch's first whole steps (every robot of a step; none when
// a group's step does not fit).
[[nodiscard]] std::size_t trace_rows_kept(std::span<const TraceStep> trace, std::size_t limit) noexcept;

// The robots a trace's steps hold (a group's trace has a row per robot per step; a robot
// alone's, 1).
[[nodiscard]] inline std::size_t trace_robots(std::span<const TraceStep> trace) noexcept {
  return trace.empty() || !trace.front().grouped ? 1 : static_cast<std::size_t>(trace.back().robot) + 1;
}

// The rows a stored replay of `spec`'s evaluations holds at most: its epochs x steps, and a
// group's x robots, at most kMaxReplayRows.
[[nodiscard]] std::size_t replay_rows(const ExperimentSpec& spec) noexcept;

// Receives every step of a traced evaluation, in order.
class TraceSink {
 public:
  virtual ~TraceSink() = default;
  virtual void on_step(const TraceStep& step) = 0;
};

class Evaluator {
 public:
  // `spec` must outlive the evaluator. Throws std::invalid_argument when an end term of its
  // fitness reads a slot beyond the frame and the experiment's choice counts.
  explicit Evaluator(const ExperimentSpec& spec);

  // Deterministic in (controller, genome, seed) whatever this evaluator ran before.
  // With a `trace`, every step is also reported to it; the result is the same either way
  // (the untraced path pays one predictable branch per step). A tree controller's genome
  // is its encoded tree (runtime/genome/tree/codec.hpp); a network's holds spec.roles
  // networks' weights (spec.genome_length), role r's driving robots r, r + roles, ...; a
  // controller per body's, each body's network's (ControllerSpec::networks).
  [[nodiscard]] Evaluation evaluate(const control::ControllerSpec& controller,
                                    std::span<const double> genome, std::uint64_t seed,
                                    TraceSink* trace = nullptr);
  // A tree controller and its tree: the same evaluation as with the encoded tree.
  [[nodiscard]] Evaluation evaluate(const control::ControllerSpec& controller, const genome::tree::Tree& tree,
                                    std::uint64_t seed, TraceSink* trace = nullptr);

 private:
  // The epochs, with any controller that has reset(), step(frame), last_action() and usage():
  // one per robot (one alone).
  template <class Driver>
  Evaluation run(const control::ControllerSpec& controller, std::span<Driver* const> drivers, std::uint64_t seed,
                 TraceSink* trace);
  // An end term's value: `term` on the last step's `frame` followed by the aggregates of the
  // `steps` steps in which the choices acted `usage` - `before` times, then its step
  // aggregates `folded` as `values` (the robot's) folded them.
  double end_term(const expr::Program& term, const std::vector<expr::StepAggregate>& folded,
                  const StepAggregates& values, const control::ControllerSpec& controller, const expr::Frame& frame,
                  std::int64_t steps, std::span<const std::int64_t> usage, std::span<const std::int64_t> before);
  // An end term on each robot's last frame and usage, counted from its epoch's start
  // (`over_epoch`) or from the evaluation's, reduced over the robots by `over`.
  template <class Driver>
  double end_over_robots(const expr::Program& term, const std::vector<expr::StepAggregate>& folded,
                         const control::ControllerSpec& controller, const EpochStepper& epoch,
                         std::span<Driver* const> drivers, std::int64_t steps, bool over_epoch, Reduction over);
  // A group's usage counts, as one robot's (evaluator.cpp).
  template <class Driver>
  static void share_usage(std::span<Driver* const> drivers, std::vector<std::int64_t>& usage);
  // Each descriptor's per-epoch values reduced so far (Reduction::Mean: their sum), epoch `e`.
  template <class Driver>
  void reduce_descriptors(const control::ControllerSpec& controller, const EpochStepper& epoch,
                          std::span<Driver* const> drivers, std::int64_t steps, int e, std::vector<double>& values);

  const ExperimentSpec* spec_;
  sim::World world_;
  std::vector<StepAggregates> folded_;      // the end terms' step aggregates, each robot's
  std::vector<double> end_frame_;           // an end term's frame: expr::Frame, then expr::aggregate
  // Each robot's usage when the epoch began; its command and choice of the step.
  std::vector<std::vector<std::int64_t>> epoch_starts_;
  std::vector<control::WheelCommand> commands_;
  std::vector<int> acting_;
};

}  // namespace esc::eval
