#pragma once
// An optimizer's own numbers per generation (CMA-ES's step size, NEAT's species, ...), kept
// in the generation's row since schema 9: the indexes of their names ("0,1,2", each name
// stored once per controller in table metric_names) and their values, doubles stored bit
// for bit (NaN and the infinities too). Schemas 6 to 8 kept one row per metric and
// generation in table metrics, about 56 bytes each against 8 now: a database they wrote is
// read as it is, and its metrics move into its generations when it is opened for writing.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/eval/run_state.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store {

inline constexpr int kMetricSchemaVersion = 9;

// CREATE TABLE metric_names, as this schema writes it.
[[nodiscard]] const char* metric_schema();

// A generation row's two metric columns; both NULL when `names` is empty (no metrics).
struct MetricColumns {
  std::string names;
  std::vector<double> values;
};

// The columns of metrics `metrics` of the controller with id `controller_id`, adding each
// name it has not reported before to metric_names.
[[nodiscard]] MetricColumns metric_columns(sql::Database& db, std::int64_t controller_id,
                                           std::span<const evo::Metric> metrics);

// The metric names of one controller, to read its generation rows' metrics back.
class MetricNames {
 public:
  MetricNames() = default;   // none: a database older than schema 9
  MetricNames(sql::Database& db, std::int64_t controller_id);
  // The metrics of a row whose columns are `names` and `values` (NULL: empty). Throws
  // StoreError, its message starting with `damaged`, for columns that do not fit together.
  [[nodiscard]] std::vector<evo::Metric> decode(std::string_view names, std::span<const double> values,
                                                std::string_view damaged) const;

 private:
  std::vector<std::string> names_;
};

// Schemas 6 to 8: fills each generation's metrics of that run from table metrics, in the
// order they were written. Throws StoreError, its message starting with `damaged`, for a
// generation beyond `gens`.
void load_legacy_metrics(sql::Database& db, std::int64_t controller_id, int run,
                         std::vector<eval::GenerationStats>& gens, std::string_view damaged);

// Upgrading to schema 9: adds the generation rows' metric columns and table metric_names,
// and moves what a table metrics (schemas 6 to 8) holds there, sealing the rows again.
void move_metrics_into_generations(sql::Database& db, bool has_metrics_table);

}  // namespace esc::store
