#pragma once
// One evaluation's trajectory as CSV (`esc replay`): a row per control step, with what the
// robot sensed, commanded and did, in the units of the names. Values are written with 17
// significant digits, so they read back as the very doubles the simulation produced (and
// compare equal to a stored replay). Epochs and steps are numbered from 1, like runs; the
// time is that of the end of the step, in seconds from the start of the epoch.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/eval/evaluator.hpp"

namespace esc::report {

// The robot's sensors as its scripts read them: the IR sensors' name and count (the
// Khepera's eight `ir`, the e-puck's eight `prox`, none on the navigator; as many light
// sensors), and the ground sensors' name (the Thymio II's `prox_ground`).
struct SensorColumns {
  std::string_view ir = "ir";
  std::size_t ir_count = sim::kIrSensors;
  std::string_view ground = "ground_sensor";
};

// The header line, without its newline: the IR sensors (ir0, ...; prox0, ... on the e-puck)
// and as many light sensors, then the robot's `ranges` rangefinders (range0, ...), `radars`
// goal radars (radar0, ...), `grounds` ground sensors (ground_sensor0, ...; prox_ground0, ...
// on the Thymio II) and `bumpers` bumpers (bumper0, ...); a robot without some has no such
// columns. A `group`'s rows (a row per robot per step) have a `robot` column after `step`,
// numbered from 1, and end with the group's observables as that robot's frame held them
// after the step (centroid_x_m to spread_m, docs/language.md "Groups").
[[nodiscard]] std::string trajectory_csv_header(const SensorColumns& sensors, std::size_t ranges, std::size_t radars,
                                                std::size_t grounds = 0, std::size_t bumpers = 0, bool group = false);

// `choices`: the controller's action or behavior names (empty for a classical head, whose
// `behavior` column stays empty).
[[nodiscard]] std::string trajectory_csv(std::span<const eval::TraceStep> steps, const std::vector<std::string>& choices,
                                         double control_step_s, const SensorColumns& sensors = {});

}  // namespace esc::report
