#pragma once
// `esc replay DIR --evaluations`: a stored run made again from its seed (app::run_evaluations),
// every evaluation's objectives and descriptors written as CSV, and where they fall over
// the first two descriptors as an SVG (over the arena with --arena).
#include <filesystem>
#include <string>

#include "app/stored_run.hpp"
#include "cli/commands.hpp"

namespace esc::cli {

// Run `run` (from 0) of `controller`; files into `out`. Returns the exit status; throws
// app::Error when the run cannot be made again as it was.
int replay_evaluations(const app::StoredRun& stored, const eval::ExperimentSpec& ran, const std::string& controller,
                       int run, const ReplayOptions& options, const std::filesystem::path& out);

}  // namespace esc::cli
