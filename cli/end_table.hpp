#pragma once
// The table `esc run` prints at the end. An experiment: per controller its architecture,
// genes and the runs' best fitness (mean ± sd, median, best), behavior usage, best trees,
// and the pairwise comparisons with Holm's correction. A study: the same figures as a table
// of conditions by controllers, usage and trees per condition, and one family of
// comparisons: within each condition every pair of controllers, and for each controller
// every pair of conditions.
#include <string>
#include <vector>

#include "app/campaign_results.hpp"

namespace esc::cli {

void print_table(const eval::ExperimentSpec& spec, const eval::CampaignResult& result);

// One condition of a study, as the end table shows it.
struct ConditionResult {
  std::string name;
  const eval::ExperimentSpec* spec;
  eval::CampaignResult result;
};

void print_study_table(const std::string& study, const std::vector<ConditionResult>& conditions);

}  // namespace esc::cli
