#pragma once
// Re-simulating stored controllers: what `esc replay` does. A subject (a run's best, a member
// of its final front or archive, or a genome file's genome) is evaluated through the
// evaluator with the seed and settings of the run, so a replay of the stored best evaluation
// is bit-identical to the one in esc.db and is checked to be; its trajectories are written
// as an SVG and its steps as a CSV (runtime/report/trajectory_*.hpp). With `evaluations`, a
// run is made again whole and every evaluation written (app/replay_evaluations.hpp). Each
// subject is told to the listener as it is done; a request that cannot be served is an
// Error, ErrorKind::Request where what was asked for does not fit what is there.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/events.hpp"
#include "app/replay_evaluations.hpp"
#include "compiler/compiler.hpp"
#include "runtime/report/trajectory_svg.hpp"

namespace esc::app {

struct ReplayRequest {
  std::filesystem::path source;              // a run directory or a run-NN.best.json file
  std::string controller;                    // empty: every controller
  std::optional<int> run;                    // from 1; none: each controller's best run
  std::string epochs;                        // "1,3-5", from 1; empty: all
  std::filesystem::path out;                 // empty: the run directory
  std::filesystem::path script;              // evaluate in this script's experiment instead
  std::string experiment;                    // of `script`; empty: its first
  std::optional<std::uint64_t> seed;         // none: the stored best evaluation's seed
  // A member of the run's final front (its position, from 0) or archive (its cell) instead
  // of the run's best.
  std::optional<std::int64_t> member;
  bool animate = false;                      // the client animates each subject (refused with `evaluations`)
  // Make the whole run again and write every evaluation's objectives and descriptors,
  // drawn over the arena with `over_arena`.
  bool evaluations = false;
  bool over_arena = false;
  int threads = 0;                           // for `evaluations`; 0: all cores
};

// One subject replayed, or refused by the experiment it was to be replayed in.
struct ReplayedSubject {
  std::string controller;
  int run = 0;                               // from 0
  std::string member;                        // "cell 17", "member 2"; empty: the run's best
  std::string experiment;                    // the experiment it was replayed in
  // Sentences (without "esc: error: "): why it was refused (nothing written then), or where
  // the replay differs from the stored run (a faithful replay's fitness, descriptors, steps).
  std::vector<std::string> problems;
  bool replayed = false;                     // false: refused, nothing written
  double fitness = 0;
  // A member replayed with its run's best's seed (a state saved before origins were kept):
  // the fitness stored in its own evaluation, to show beside.
  std::optional<double> own_fitness;
  // Neither another script nor another seed: the replay was checked against what is stored.
  bool faithful = false;
  bool identical_to_stored_replay = false;   // faithful, and equal to esc.db's stored replay
  bool as_in_own_evaluation = false;         // faithful, a member equal to its own evaluation
  std::vector<std::pair<std::string, double>> descriptors;   // name and value
  bool descriptors_as_stored = false;        // checked against the member's stored descriptors
  std::filesystem::path out;                 // the directory written
  std::string stem;                          // the files' name: out/stem.svg and out/stem.csv
  std::vector<eval::TraceStep> drawn;        // the steps of the epochs drawn
  report::TrajectoryFigure frame;            // the SVG's title, arena and robot; its steps empty

  // What the SVG draws (for an animation): `frame` over `drawn`, valid while this lives.
  [[nodiscard]] report::TrajectoryFigure figure() const {
    report::TrajectoryFigure f = frame;
    f.steps = drawn;
    return f;
  }
};

// "name value, ..." of a subject's descriptors, as errors and `esc` show them.
[[nodiscard]] std::string descriptors_text(const std::vector<std::pair<std::string, double>>& descriptors);

// Hears each subject as it is done, before the next begins.
class ReplayListener {
 public:
  virtual ~ReplayListener() = default;
  virtual void replayed(const ReplayedSubject& /*subject*/) {}
  // `evaluations`: a generation of `who` ("A run 2") made again, `done` of `generations`.
  virtual void generation_made_again(const std::string& /*who*/, int /*done*/, int /*generations*/) {}
  virtual void evaluations_replayed(const ReplayedEvaluations& /*evaluations*/) {}
};

struct ReplayOutcome {
  std::vector<ReplayedSubject> subjects;           // empty with `evaluations`
  std::vector<ReplayedEvaluations> evaluations;    // with `evaluations`
};

ReplayOutcome replay(const ReplayRequest& request, const compiler::CompileOptions& options, Events& events,
                     ReplayListener& listener);

}  // namespace esc::app
