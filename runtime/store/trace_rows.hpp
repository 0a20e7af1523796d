#pragma once
// How a replay trace is stored: one row of doubles per control step (the columns of
// trace_columns), all rows in one blob of the replays table, and read back in the
// layout it was written in, whatever columns an older esc wrote.
#include <span>
#include <string>
#include <vector>

#include "runtime/eval/campaign.hpp"

namespace esc::store {

// The column names of `trace`'s rows, in the layout of its first step: kTraceColumns fixed ones
// (results_db.hpp), the accumulator, x, y of each of the arena's zones in that epoch, the light
// sensors light0..light7, then the robot's rangefinders (range0...), goal radars (radar0...),
// ground sensors (ground_sensor0...) and bumpers (bumper0...).
[[nodiscard]] std::vector<std::string> trace_columns(std::span<const eval::TraceStep> trace);
// The steps of `trace` as one row each, in the layout of its first step.
[[nodiscard]] std::vector<double> pack_trace(std::span<const eval::TraceStep> trace);
// The steps stored as `v` with the stored column names `columns`. Throws StoreError when
// the two disagree.
[[nodiscard]] std::vector<eval::TraceStep> unpack_trace(const std::vector<double>& v,
                                                        const std::vector<std::string>& columns);

}  // namespace esc::store
