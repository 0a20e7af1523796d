#pragma once
// A campaign's results as the application layer hands them to its clients (Events::
// experiment_done, a study's conditions): the runtime's values (eval::CampaignResult, what
// it holds, and the eval::ExperimentSpec that ran) and what the end tables count from them.
// The clients include this, not the runtime's headers.
#include "runtime/eval/campaign.hpp"
#include "runtime/eval/experiment.hpp"
#include "runtime/eval/success.hpp"

namespace esc::app {

// How many of a controller's runs met the experiment's success test, and the median of the
// evaluations they took.
using eval::count_successes;

}  // namespace esc::app
