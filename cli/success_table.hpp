#pragma once
// The part of `esc run`'s end table that an experiment's `success when` test adds: per
// controller (a study: per condition and controller) how many runs succeeded and the median
// of their evaluations to success, and per pair of the comparisons' family Fisher's exact
// test of the success counts and the censored Mann-Whitney test of the evaluations to
// success (runtime/report/success_comparisons.hpp). Experiments without a test print none of it.
#include <string>
#include <vector>

#include "app/campaign_results.hpp"
#include "cli/end_table.hpp"
#include "cli/table_text.hpp"
#include "runtime/report/success_comparisons.hpp"

namespace esc::cli {

// An experiment's: its test, then a line per controller.
void print_success(const eval::CampaignResult& result);

// A study's: a table of conditions by controllers, "-" where a condition declares no test.
void print_study_success(const std::vector<ConditionResult>& conditions, const std::vector<std::string>& controllers);

// The comparisons, then a note naming the family (`family`: what it holds, or "").
void print_success_comparisons(const std::vector<report::SuccessComparison>& rows, const PairLabel& label,
                               const std::string& family);

}  // namespace esc::cli
