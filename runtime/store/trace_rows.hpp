#pragma once
// How a replay trace is stored: one row of doubles per control step (the columns of
// trace_column_names), all rows in one blob of the replays table, and read back in the
// layout it was written in, whatever columns an older esc wrote.
#include <span>
#include <string>
#include <vector>

#include "runtime/eval/campaign.hpp"

namespace esc::store {

// The steps of `trace` as one row each, in the layout of its first step.
[[nodiscard]] std::vector<double> pack_trace(std::span<const eval::TraceStep> trace);
// The steps stored as `v` with the stored column names `columns`. Throws StoreError when
// the two disagree.
[[nodiscard]] std::vector<eval::TraceStep> unpack_trace(const std::vector<double>& v,
                                                        const std::vector<std::string>& columns);

}  // namespace esc::store
