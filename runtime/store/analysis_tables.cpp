#include "runtime/store/analysis_tables.hpp"

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"
#include "runtime/store/row_checksum.hpp"

namespace esc::store {

const char* analysis_schema() {
  return R"sql(
CREATE TABLE generation_usage (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  generation    INTEGER NOT NULL,
  choice_idx    INTEGER NOT NULL,
  best_steps    INTEGER NOT NULL,
  mean_steps    REAL NOT NULL,
  steps_total   INTEGER NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run, generation, choice_idx)
);
CREATE TABLE choices (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  idx           INTEGER NOT NULL,
  name          TEXT NOT NULL,
  behavior      TEXT NOT NULL,
  library       TEXT NOT NULL,
  useless       INTEGER NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, idx)
);
CREATE TABLE transfers (
  controller_id     INTEGER NOT NULL REFERENCES controllers(id),
  run               INTEGER NOT NULL,
  origin_experiment TEXT NOT NULL,
  origin_run        INTEGER NOT NULL,
  origin_fitness    REAL NOT NULL,
  evaluate_only     INTEGER NOT NULL,
  fitness_here      REAL,
  checksum          INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run)
);
)sql";
}

void save_choices(sql::Database& db, std::int64_t controller_id, const std::vector<control::Choice>& choices) {
  auto row = db.prepare(
      "INSERT INTO choices(controller_id, idx, name, behavior, library, useless) VALUES (?, ?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < choices.size(); ++i) {
    const control::Choice& c = choices[i];
    row.bind(1, controller_id).bind(2, static_cast<std::int64_t>(i)).bind(3, c.name).bind(4, c.behavior)
        .bind(5, c.library).bind(6, c.useless ? 1 : 0)
        .run();
    seal_row(db, "choices", db.last_insert_rowid());
  }
}

std::vector<control::Choice> load_choices(sql::Database& db, std::int64_t controller_id) {
  std::vector<control::Choice> out;
  auto q = db.prepare("SELECT name, behavior, library, useless FROM choices WHERE controller_id = ? ORDER BY idx");
  q.bind(1, controller_id);
  while (q.step()) out.push_back({q.text(0), q.text(1), q.text(2), q.int64(3) != 0, -1});
  return out;
}

void save_usage(sql::Database& db, std::int64_t controller_id, int run, const eval::GenerationStats& g) {
  const eval::GenerationUsage& u = g.usage;
  auto row = db.prepare(
      "INSERT OR REPLACE INTO generation_usage(controller_id, run, generation, choice_idx, best_steps, mean_steps, "
      "steps_total) VALUES (?, ?, ?, ?, ?, ?, ?)");
  for (std::size_t c = 0; c < u.best.size() && c < u.mean.size(); ++c) {
    row.bind(1, controller_id).bind(2, run).bind(3, g.generation).bind(4, static_cast<std::int64_t>(c))
        .bind(5, u.best[c]).bind(6, u.mean[c]).bind(7, u.steps_total)
        .run();
    seal_row(db, "generation_usage", db.last_insert_rowid());
  }
}

void load_usage(sql::Database& db, std::int64_t controller_id, int run, std::vector<eval::GenerationStats>& generations,
                std::string_view damaged) {
  auto q = db.prepare(
      "SELECT generation, choice_idx, best_steps, mean_steps, steps_total FROM generation_usage "
      "WHERE controller_id = ? AND run = ? ORDER BY generation, choice_idx");
  q.bind(1, controller_id).bind(2, run);
  while (q.step()) {
    const std::int64_t g = q.int64(0);
    if (g < 0 || static_cast<std::size_t>(g) >= generations.size() ||
        static_cast<std::size_t>(q.int64(1)) != generations[static_cast<std::size_t>(g)].usage.best.size())
      throw StoreError(fmt::format("{}: behavior usage stored for generation {} does not match its generations",
                                   damaged, g));
    eval::GenerationUsage& u = generations[static_cast<std::size_t>(g)].usage;
    u.best.push_back(q.int64(2));
    u.mean.push_back(q.real(3));
    u.steps_total = q.int64(4);
  }
}

void save_transfer(sql::Database& db, std::int64_t controller_id, int run, const eval::Transfer& t) {
  auto row = db.prepare(
      "INSERT OR REPLACE INTO transfers(controller_id, run, origin_experiment, origin_run, origin_fitness, "
      "evaluate_only, fitness_here) VALUES (?, ?, ?, ?, ?, ?, ?)");
  row.bind(1, controller_id).bind(2, run).bind(3, t.experiment).bind(4, t.origin_run).bind(5, t.origin_fitness)
      .bind(6, t.evaluate_only ? 1 : 0);
  if (t.fitness_here) row.bind(7, *t.fitness_here);
  row.run();
  seal_row(db, "transfers", db.last_insert_rowid());
}

std::optional<eval::Transfer> load_transfer(sql::Database& db, std::int64_t controller_id, int run) {
  auto q = db.prepare(
      "SELECT origin_experiment, origin_run, origin_fitness, evaluate_only, fitness_here FROM transfers "
      "WHERE controller_id = ? AND run = ?");
  q.bind(1, controller_id).bind(2, run);
  if (!q.step()) return std::nullopt;
  eval::Transfer t{q.text(0), q.integer(1), q.real(2), q.int64(3) != 0, std::nullopt};
  if (!q.is_null(4)) t.fitness_here = q.real(4);
  return t;
}

}  // namespace esc::store
