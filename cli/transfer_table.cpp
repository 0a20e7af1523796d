#include "cli/transfer_table.hpp"

#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "runtime/report/generalization.hpp"

namespace esc::cli {

namespace {

std::string or_na(double x, std::string_view format) {
  return std::isnan(x) ? "n/a" : fmt::format(fmt::runtime(format), x);
}

}  // namespace

void print_transfers(const eval::CampaignResult& result) {
  bool header = false;
  for (const eval::ControllerResult& c : result.controllers) {
    const auto s = report::summarise_transfers(c.runs);
    if (!s) continue;
    if (!header) {
      constexpr std::string_view evolving_on =
          "; evolving on: the best here, the share of the loss made up (pooled), runs back at the level there";
      fmt::print("\nfrom experiment {} (mean over runs: each run's genome there, then here{})\n", s->origin,
                 s->evaluate_only ? "" : evolving_on);
      fmt::print("{:<12} {:>14} {:>14} {:>9}", "controller", "fitness there", "fitness here", "change");
      if (!s->evaluate_only) fmt::print(" {:>14} {:>14}  regained", "best here", "loss made up");
      fmt::print("\n");
    }
    header = true;
    fmt::print("{:<12} {:>14} {:>14} {:>9}", c.name, or_na(s->origin_mean, "{:.1f}"), or_na(s->here_mean, "{:.1f}"),
               or_na(s->change_mean, "{:+.1f}%"));
    if (!s->evaluate_only)
      fmt::print(" {:>14} {:>14}  {}", or_na(s->best_here_mean, "{:.1f}"), or_na(s->loss_regained_pooled, "{:.0f}%"),
                 s->regained == 0 ? fmt::format("0 of {} runs", s->runs.size())
                                  : fmt::format("{} of {} runs, median generation {}", s->regained, s->runs.size(),
                                                or_na(s->regained_median, "{:.0f}")));
    fmt::print("\n");
  }
}

}  // namespace esc::cli
