#include "runtime/store/optimizer_tables.hpp"

#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"
#include "runtime/store/row_checksum.hpp"

namespace esc::store {

void save_state(sql::Database& db, std::int64_t controller_id, int run, const eval::OptimizerState& state) {
  db.prepare("INSERT OR REPLACE INTO optimizer_state(controller_id, run, algorithm, format, state) VALUES (?, ?, ?, ?, ?)")
      .bind(1, controller_id).bind(2, run).bind(3, state.algorithm).bind(4, static_cast<std::int64_t>(state.format))
      .bind_blob(5, std::span<const std::uint8_t>(state.bytes))
      .run();
  seal_row(db, "optimizer_state", db.last_insert_rowid());
}

std::optional<eval::OptimizerState> load_optimizer_state(sql::Database& db, std::int64_t controller_id, int run) {
  auto st = db.prepare("SELECT algorithm, format, state FROM optimizer_state WHERE controller_id = ? AND run = ?");
  st.bind(1, controller_id).bind(2, run);
  if (!st.step()) return std::nullopt;
  const std::string_view bytes = st.bytes(2);
  return eval::OptimizerState{st.text(0), static_cast<std::uint32_t>(st.int64(1)),
                              evo::StateBytes(bytes.begin(), bytes.end())};
}

void save_metrics(sql::Database& db, std::int64_t controller_id, int run, const eval::GenerationStats& g) {
  auto row = db.prepare("INSERT INTO metrics(controller_id, run, generation, idx, name, value) VALUES (?, ?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < g.metrics.size(); ++i) {
    // SQLite keeps NaN as NULL; it reads back as NaN.
    row.bind(1, controller_id).bind(2, run).bind(3, g.generation).bind(4, static_cast<std::int64_t>(i))
        .bind(5, g.metrics[i].name).bind(6, g.metrics[i].value)
        .run();
    seal_row(db, "metrics", db.last_insert_rowid());
  }
}

void load_metrics(sql::Database& db, std::int64_t controller_id, int run, std::vector<eval::GenerationStats>& gens,
                  std::string_view damaged) {
  auto q = db.prepare("SELECT generation, name, value FROM metrics WHERE controller_id = ? AND run = ? "
                      "ORDER BY generation, idx");
  q.bind(1, controller_id).bind(2, run);
  while (q.step()) {
    const auto g = static_cast<std::size_t>(q.int64(0));
    if (g >= gens.size())
      throw StoreError(fmt::format("{}: metrics of generation {}, which the run has not finished", damaged, g));
    gens[g].metrics.push_back({q.text(1), q.is_null(2) ? std::numeric_limits<double>::quiet_NaN() : q.real(2)});
  }
}

}  // namespace esc::store
