#pragma once
// `esc replay DIR --evaluations`: a stored run made again from its seed (app/run_evaluations.hpp),
// every evaluation's objectives and descriptors written as CSV, and where they fall over
// the first two descriptors as an SVG (over the arena with `over_arena`).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

#include "app/stored_run.hpp"

namespace esc::app {

// The files written for one run made again.
struct ReplayedEvaluations {
  std::string controller;
  int run = 0;                       // from 0
  std::size_t evaluations = 0;
  std::filesystem::path out;         // the directory written
  std::string stem;                  // out/stem.csv, and out/stem.svg where `svg`
  bool svg = false;                  // false: fewer than two descriptors to draw
};

// Hears a generation made again: `done` of the `generations` the stored run made.
using GenerationsMade = std::function<void(int done, int generations)>;

// Run `run` (from 0) of `controller` of `stored`, made again on `threads` threads (0: all)
// in `ran`, the experiment it ran; files into `out`. Throws Error when the run cannot be made
// again as it was, or (ErrorKind::Request) `over_arena` where fewer than two descriptors are
// declared.
[[nodiscard]] ReplayedEvaluations replay_evaluations(const StoredRun& stored, const eval::ExperimentSpec& ran,
                                                     const std::string& controller, int run, int threads,
                                                     bool over_arena, const std::filesystem::path& out,
                                                     const GenerationsMade& progress);

}  // namespace esc::app
