#include "runtime/store/usage_export.hpp"

#include <functional>

#include <fmt/format.h>

#include "runtime/store/export.hpp"

namespace esc::store {

namespace {

struct UsageRow {
  const std::string& experiment;
  const std::string& condition;   // empty for a plain experiment
  const std::string& controller;
  int run;                        // from 1
  int generation;
  const std::string& behavior;
  std::int64_t best_steps;
  double mean_steps;
  std::int64_t steps_total;
  const std::string& library;     // "" when none (actions, or stored before schema 4)
  bool useless;
};

// Every row, in directory, experiment, controller, run (finished ones first, as stored),
// generation and behavior order.
void for_each_row(const std::vector<StoredDirectory>& directories, const std::function<void(const UsageRow&)>& f) {
  static const std::string kNone;
  for_each_run(directories, [&](const StoredExperiment& e, const std::string& condition, const StoredController& c,
                                int run, const std::vector<eval::GenerationStats>& generations) {
    for (const eval::GenerationStats& g : generations)
      for (std::size_t i = 0; i < g.usage.best.size() && i < g.usage.mean.size() && i < c.actions.size(); ++i) {
        const control::Choice* choice = i < c.choices.size() ? &c.choices[i] : nullptr;
        f({e.name, condition, c.name, run + 1, g.generation, c.actions[i], g.usage.best[i], g.usage.mean[i],
           g.usage.steps_total, choice != nullptr ? choice->library : kNone, choice != nullptr && choice->useless});
      }
  });
}

}  // namespace

std::string usage_csv(const std::vector<StoredDirectory>& directories) {
  std::string out = std::string(kUsageColumns) + "\n";
  for_each_row(directories, [&](const UsageRow& r) {
    out += fmt::format("{},{},{},{},{},{},{},{:.17g},{},{},{}\n", r.experiment, csv_field(r.condition), r.controller,
                       r.run, r.generation, csv_field(r.behavior), r.best_steps, r.mean_steps, r.steps_total,
                       csv_field(r.library), r.useless ? 1 : 0);
  });
  return out;
}

nlohmann::ordered_json usage_json(const std::vector<StoredDirectory>& directories) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for_each_row(directories, [&](const UsageRow& r) {
    rows.push_back({{"experiment", r.experiment}, {"condition", r.condition}, {"controller", r.controller},
                    {"run", r.run}, {"generation", r.generation}, {"behavior", r.behavior},
                    {"best_steps", r.best_steps}, {"mean_steps", r.mean_steps}, {"steps_total", r.steps_total},
                    {"library", r.library}, {"useless", r.useless}});
  });
  return rows;
}

}  // namespace esc::store
