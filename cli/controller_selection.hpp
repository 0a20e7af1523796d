#pragma once
// `esc run --controllers C1,C2`: run only some of an experiment's compared controllers.
// Every controller of a run draws from the same streams (common random numbers), so a
// controller's results do not depend on which others run beside it: one Table 1 row can be
// re-run, or a failed controller redone, without the cost of the whole experiment.
#include <string>
#include <string_view>
#include <vector>

#include "runtime/eval/experiment.hpp"

namespace esc::cli {

// Keeps the controllers of `spec` named in `names`, in that order, with the dependencies
// that fill their behaviors; no-op for an empty list. Prints each unknown or repeated name
// (after `where`, with the closest compared name) and returns false if any.
[[nodiscard]] bool select_controllers(const std::vector<std::string>& names, eval::ExperimentSpec& spec,
                                      std::string_view where = {});

}  // namespace esc::cli
