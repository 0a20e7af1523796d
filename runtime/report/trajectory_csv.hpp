#pragma once
// One evaluation's trajectory as CSV (`esc replay`): a row per control step, with what the
// robot sensed, commanded and did, in the units of the names. Values are written with 17
// significant digits, so they read back as the very doubles the simulation produced (and
// compare equal to a stored replay). Epochs and steps are numbered from 1, like runs; the
// time is that of the end of the step, in seconds from the start of the epoch.
#include <span>
#include <string>
#include <vector>

#include "runtime/eval/evaluator.hpp"

namespace esc::report {

// The header line, without its newline: the robot's `ranges` rangefinders (range0, ...) and
// `radars` goal radars (radar0, ...) follow the light sensors; a robot without either has no
// such columns.
[[nodiscard]] std::string trajectory_csv_header(std::size_t ranges, std::size_t radars);

// `choices`: the controller's action or behavior names (empty for a classical head, whose
// `behavior` column stays empty).
[[nodiscard]] std::string trajectory_csv(std::span<const eval::TraceStep> steps, const std::vector<std::string>& choices,
                                         double control_step_s);

}  // namespace esc::report
