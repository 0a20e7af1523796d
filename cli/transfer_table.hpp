#pragma once
// The end of `esc run`'s table for an experiment that evaluates or starts from another's
// controllers: per controller, the fitness its genomes had in the origin experiment, their
// fitness here and the change in percent (means over runs), and for `start from` how many
// runs regained the origin's level and when (runtime/report/generalization.hpp).
#include "app/campaign_results.hpp"

namespace esc::cli {

// Prints nothing when no run started from a stored genome.
void print_transfers(const eval::CampaignResult& result);

}  // namespace esc::cli
