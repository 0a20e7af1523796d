#include "runtime/store/metrics_export.hpp"

#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "runtime/store/export.hpp"

namespace esc::store {

namespace {

struct MetricRow {
  const std::string& experiment;
  const std::string& condition;   // empty for a plain experiment
  const std::string& controller;
  const std::string& algorithm;
  int run;                        // from 1
  int generation;
  const evo::Metric& metric;
};

// Every row, in directory, experiment, controller, run (finished ones first, as stored),
// generation and metric order.
void for_each_row(const std::vector<StoredDirectory>& directories, const std::function<void(const MetricRow&)>& f) {
  for_each_run(directories, [&](const StoredExperiment& e, const std::string& condition, const StoredController& c,
                                int run, const std::vector<eval::GenerationStats>& generations) {
    for (const eval::GenerationStats& g : generations)
      for (const evo::Metric& m : g.metrics) f({e.name, condition, c.name, c.algorithm, run + 1, g.generation, m});
  });
}

}  // namespace

std::string metrics_csv(const std::vector<StoredDirectory>& directories) {
  std::string out = std::string(kMetricsColumns) + "\n";
  for_each_row(directories, [&](const MetricRow& r) {
    out += fmt::format("{},{},{},{},{},{},{},{:.17g}\n", r.experiment, csv_field(r.condition), r.controller,
                       r.algorithm, r.run, r.generation, csv_field(r.metric.name), r.metric.value);
  });
  return out;
}

nlohmann::ordered_json metrics_json(const std::vector<StoredDirectory>& directories) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for_each_row(directories, [&](const MetricRow& r) {
    nlohmann::ordered_json value = std::isnan(r.metric.value) ? nlohmann::ordered_json() : nlohmann::ordered_json(r.metric.value);
    rows.push_back({{"experiment", r.experiment}, {"condition", r.condition}, {"controller", r.controller},
                    {"algorithm", r.algorithm}, {"run", r.run}, {"generation", r.generation},
                    {"metric", r.metric.name}, {"value", value}});
  });
  return rows;
}

}  // namespace esc::store
