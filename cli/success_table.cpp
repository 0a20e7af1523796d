#include "cli/success_table.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "app/campaign_results.hpp"
#include "cli/table_text.hpp"

namespace esc::cli {

namespace {

// "3/40 (12345)": successes of runs, and the median evaluations to success ("-": none).
std::string count_text(const eval::SuccessCount& s) {
  return fmt::format("{}/{} ({})", s.successes, s.runs,
                     std::isnan(s.median_evaluations) ? std::string("-") : fmt::format("{}", s.median_evaluations));
}

const eval::ControllerResult* find(const eval::CampaignResult& r, const std::string& controller) {
  const auto it = std::find_if(r.controllers.begin(), r.controllers.end(),
                               [&](const eval::ControllerResult& c) { return c.name == controller; });
  return it == r.controllers.end() ? nullptr : &*it;
}

}  // namespace

void print_success(const eval::CampaignResult& result) {
  if (result.success.empty()) return;
  fmt::print("\nsuccess when {}: runs that succeeded (median of their evaluations up to the first success)\n",
             result.success);
  for (const eval::ControllerResult& c : result.controllers)
    fmt::print("{:<12} {}\n", c.name, count_text(app::count_successes(c.runs)));
}

void print_study_success(const std::vector<ConditionResult>& conditions, const std::vector<std::string>& controllers) {
  std::set<std::string> tests;
  for (const ConditionResult& c : conditions)
    if (!c.result.success.empty()) tests.insert(c.result.success);
  if (tests.empty()) return;
  fmt::print("\nsuccess {}: runs that succeeded (median of their evaluations up to the first success)\n",
             tests.size() == 1 ? "when " + *tests.begin() : std::string("by each condition's test (below)"));
  std::size_t name_width = 12;
  for (const ConditionResult& c : conditions) name_width = std::max(name_width, c.name.size());
  constexpr std::size_t kCell = 24;
  std::string head = fmt::format("{:<{}}", "condition", name_width);
  for (const std::string& k : controllers) head += fmt::format("  {:>{}}", k, kCell);
  fmt::print("{}\n", head);
  for (const ConditionResult& c : conditions) {
    std::string line = fmt::format("{:<{}}", c.name, name_width);
    for (const std::string& k : controllers) {
      const eval::ControllerResult* r = c.result.success.empty() ? nullptr : find(c.result, k);
      line += fmt::format("  {:>{}}", r == nullptr ? "-" : count_text(app::count_successes(r->runs)), kCell);
    }
    fmt::print("{}\n", line);
  }
  if (tests.size() > 1)
    for (const ConditionResult& c : conditions)
      fmt::print("{}: {}\n", c.name, c.result.success.empty() ? "no success test" : "success when " + c.result.success);
}

void print_success_comparisons(const std::vector<report::SuccessComparison>& rows, const PairLabel& label,
                               const std::string& family) {
  if (rows.empty()) return;
  std::size_t width = 26;
  for (const report::SuccessComparison& c : rows) width = std::max(width, label(c.a, c.b).size());
  constexpr const char* kRow = "{:<{}} {:>15} {:>10} {:>10} {:>7}  {:>7} {:>10} {:>10} {:>11}\n";
  fmt::print(fmt::runtime(std::string("\n") + kRow), "success (two-sided)", width, "successes", "Fisher p", "p Holm",
             "odds", "M-W U", "p", "p Holm", "censored at");
  for (const report::SuccessComparison& c : rows)
    fmt::print(fmt::runtime(kRow), label(c.a, c.b), width,
               fmt::format("{}/{} vs {}/{}", c.successes_a, c.runs_a, c.successes_b, c.runs_b),
               p_text(c.fisher.p_value), p_text(c.fisher_p_holm), number_or_na(c.fisher.odds_ratio, 2),
               number_or_na(c.censored.statistic, 1), p_text(c.censored.p_value), p_text(c.censored_p_holm),
               std::isnan(c.censored_at) ? std::string("none") : fmt::format("{:.0f}", c.censored_at));
  fmt::print("Holm: p adjusted over the {} comparison{} shown{}, for each test. Fisher: Fisher's exact test of the "
             "success counts (odds: the odds ratio of success, first over second). M-W U: the evaluations to success, "
             "where {}; `censored at`: the evaluations it counts as, the pair's largest budget + 1 (none: every run succeeded).\n",
             rows.size(), rows.size() == 1 ? "" : "s", family, report::kCensoringNote);
}

}  // namespace esc::cli
