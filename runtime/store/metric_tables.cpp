#include "runtime/store/metric_tables.hpp"

#include <charconv>
#include <limits>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"
#include "runtime/store/row_checksum.hpp"

namespace esc::store {

const char* metric_schema() {
  return R"sql(
CREATE TABLE metric_names (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  idx           INTEGER NOT NULL,  -- what a generation's metric_names column lists
  name          TEXT NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, idx),
  UNIQUE (controller_id, name)
);
)sql";
}

namespace {

// A row of schemas 6 to 8's table metrics: its name and value in columns `at` and `at` + 1
// (SQLite kept NaN as NULL).
evo::Metric legacy_metric(const sql::Statement& q, int at) {
  return {q.text(at), q.is_null(at + 1) ? std::numeric_limits<double>::quiet_NaN() : q.real(at + 1)};
}

}  // namespace

MetricColumns metric_columns(sql::Database& db, std::int64_t controller_id, std::span<const evo::Metric> metrics) {
  MetricColumns c;
  if (metrics.empty()) return c;
  auto find = db.prepare("SELECT idx FROM metric_names WHERE controller_id = ? AND name = ?");
  for (const evo::Metric& m : metrics) {
    find.reset();
    std::int64_t idx = 0;
    if (find.bind(1, controller_id).bind(2, m.name).step()) {
      idx = find.int64(0);
    } else {
      auto count = db.prepare("SELECT COUNT(*) FROM metric_names WHERE controller_id = ?");
      count.bind(1, controller_id).step();
      idx = count.int64(0);
      db.prepare("INSERT INTO metric_names(controller_id, idx, name) VALUES (?, ?, ?)")
          .bind(1, controller_id).bind(2, idx).bind(3, m.name)
          .run();
      seal_row(db, "metric_names", db.last_insert_rowid());
    }
    c.names += (c.names.empty() ? "" : ",") + std::to_string(idx);
    c.values.push_back(m.value);
  }
  return c;
}

MetricNames::MetricNames(sql::Database& db, std::int64_t controller_id) {
  auto q = db.prepare("SELECT idx, name FROM metric_names WHERE controller_id = ? ORDER BY idx");
  q.bind(1, controller_id);
  while (q.step()) {
    // A gap in the indexes is damage the rows' checksums do not see (a row deleted whole).
    if (q.int64(0) != static_cast<std::int64_t>(names_.size())) break;
    names_.push_back(q.text(1));
  }
}

std::vector<evo::Metric> MetricNames::decode(std::string_view names, std::span<const double> values,
                                             std::string_view damaged) const {
  std::vector<evo::Metric> out;
  const auto bad = [&](const char* what) {
    return StoreError(fmt::format("{}: {} in a generation's metrics", damaged, what));
  };
  for (std::size_t at = 0; at < names.size();) {
    std::size_t idx = 0;
    const auto [end, ec] = std::from_chars(names.data() + at, names.data() + names.size(), idx);
    if (ec != std::errc() || idx >= names_.size()) throw bad("a metric name that is not stored");
    if (out.size() >= values.size()) throw bad("more names than values");
    out.push_back({names_[idx], values[out.size()]});
    at = static_cast<std::size_t>(end - names.data());
    if (at < names.size() && names[at++] != ',') throw bad("a list of names that is not one");
  }
  if (out.size() != values.size()) throw bad("more values than names");
  return out;
}

void load_legacy_metrics(sql::Database& db, std::int64_t controller_id, int run,
                         std::vector<eval::GenerationStats>& gens, std::string_view damaged) {
  auto q = db.prepare("SELECT generation, name, value FROM metrics WHERE controller_id = ? AND run = ? "
                      "ORDER BY generation, idx");
  q.bind(1, controller_id).bind(2, run);
  while (q.step()) {
    const auto g = static_cast<std::size_t>(q.int64(0));
    if (g >= gens.size())
      throw StoreError(fmt::format("{}: metrics of generation {}, which the run has not finished", damaged, g));
    gens[g].metrics.push_back(legacy_metric(q, 1));
  }
}

void move_metrics_into_generations(sql::Database& db, bool has_metrics_table) {
  db.exec("ALTER TABLE generations ADD COLUMN metric_names TEXT; ALTER TABLE generations ADD COLUMN metrics BLOB;");
  db.exec(metric_schema());
  if (!has_metrics_table) return;
  using Key = std::tuple<std::int64_t, std::int64_t, std::int64_t>;   // controller, run, generation
  std::map<Key, std::vector<evo::Metric>> rows;
  {   // finished before the table is dropped
    auto q = db.prepare("SELECT controller_id, run, generation, name, value FROM metrics "
                        "ORDER BY controller_id, run, generation, idx");
    while (q.step()) rows[{q.int64(0), q.int64(1), q.int64(2)}].push_back(legacy_metric(q, 3));
  }
  for (const auto& [key, metrics] : rows) {
    const MetricColumns c = metric_columns(db, std::get<0>(key), metrics);
    db.prepare("UPDATE generations SET metric_names = ?, metrics = ? WHERE controller_id = ? AND run = ? AND generation = ?")
        .bind(1, c.names).bind_blob(2, std::span<const double>(c.values))
        .bind(3, std::get<0>(key)).bind(4, std::get<1>(key)).bind(5, std::get<2>(key))
        .run();
  }
  db.exec("DROP TABLE metrics;");
}

}  // namespace esc::store
