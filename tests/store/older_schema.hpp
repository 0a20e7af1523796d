#pragma once
// Databases as an older esc wrote them (results schemas 1 to 8), made from a current one: the tests
// of upgrades and of reading old results start from these.
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "runtime/evo/es/es.hpp"
#include "runtime/evo/state_bytes.hpp"
#include "runtime/store/es_state.hpp"
#include "runtime/store/metric_tables.hpp"
#include "runtime/store/optimizer_tables.hpp"
#include "runtime/store/row_checksum.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store::test {

// As schema 8 kept metrics, states and members: one row per metric and generation in table
// metrics (NaN as NULL), not in the generation's row, every state uncompressed, and one row
// per member in table members; the tables sealed again.
inline void as_schema8(sql::Database& raw) {
  raw.exec(R"sql(
CREATE TABLE metrics (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  generation    INTEGER NOT NULL,
  idx           INTEGER NOT NULL,
  name          TEXT NOT NULL,
  value         REAL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run, generation, idx)
);)sql");
  {   // finished before the columns are dropped
    auto q = raw.prepare("SELECT controller_id, run, generation, metric_names, metrics FROM generations "
                         "WHERE metric_names IS NOT NULL");
    auto row = raw.prepare("INSERT INTO metrics(controller_id, run, generation, idx, name, value) "
                           "VALUES (?, ?, ?, ?, ?, ?)");
    while (q.step()) {
      const MetricNames names(raw, q.int64(0));
      const std::vector<evo::Metric> metrics = names.decode(q.text(3), q.doubles(4), "test");
      for (std::size_t i = 0; i < metrics.size(); ++i)
        row.bind(1, q.int64(0)).bind(2, q.int64(1)).bind(3, q.int64(2)).bind(4, static_cast<std::int64_t>(i))
            .bind(5, metrics[i].name).bind(6, metrics[i].value)
            .run();
    }
  }
  std::vector<std::pair<std::int64_t, evo::StateBytes>> states;
  {
    auto q = raw.prepare("SELECT rowid, state, raw_size FROM optimizer_state WHERE raw_size IS NOT NULL");
    while (q.step()) {
      std::optional<evo::StateBytes> bytes = uncompress_state(q.bytes(1), q.int64(2));
      if (!bytes) throw std::runtime_error("test: a state that does not uncompress");
      states.emplace_back(q.int64(0), std::move(*bytes));
    }
  }
  for (const auto& [rowid, bytes] : states)
    raw.prepare("UPDATE optimizer_state SET state = ? WHERE rowid = ?")
        .bind_blob(1, std::span<const std::uint8_t>(bytes)).bind(2, rowid)
        .run();
  // Members a row each (schemas 8 and 9), from the generations' rows of schema 10.
  raw.exec(R"sql(
CREATE TABLE members (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  generation    INTEGER NOT NULL,
  idx           INTEGER NOT NULL,
  cell          INTEGER NOT NULL,
  objectives    BLOB NOT NULL,
  descriptors   BLOB NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run, generation, idx)
);)sql");
  {
    auto q = raw.prepare("SELECT controller_id, run, generation, members, cells, objectives, descriptors "
                         "FROM member_generations");
    auto row = raw.prepare("INSERT INTO members(controller_id, run, generation, idx, cell, objectives, descriptors) "
                           "VALUES (?, ?, ?, ?, ?, ?, ?)");
    while (q.step()) {
      const auto n = static_cast<std::size_t>(q.int64(3));
      const std::string_view cells = q.bytes(4);
      const std::vector<double> objectives = q.doubles(5), descriptors = q.doubles(6);
      const std::size_t k = objectives.size() / n, d = descriptors.size() / n;
      for (std::size_t i = 0; i < n; ++i) {
        std::int64_t cell = 0;
        std::memcpy(&cell, cells.data() + i * sizeof cell, sizeof cell);
        row.bind(1, q.int64(0)).bind(2, q.int64(1)).bind(3, q.int64(2)).bind(4, static_cast<std::int64_t>(i))
            .bind(5, cell)
            .bind_blob(6, std::span<const double>(objectives).subspan(i * k, k))
            .bind_blob(7, std::span<const double>(descriptors).subspan(i * d, d))
            .run();
      }
    }
  }
  raw.exec("DROP TABLE member_generations;");
  seal_table(raw, "members");
  raw.exec("ALTER TABLE generations DROP COLUMN metric_names; ALTER TABLE generations DROP COLUMN metrics; "
           "DROP TABLE metric_names; ALTER TABLE optimizer_state DROP COLUMN raw_size; PRAGMA user_version=8;");
  for (const char* t : {"generations", "metrics", "optimizer_state"}) seal_table(raw, t);
}

// Moves every ES run's state into table run_state, as schema 5 kept it, and drops what
// schemas 6 to 8 added (tables optimizer_state, metrics, member_layouts and members, columns
// controllers.algorithm, runs.stopped and runs.success_evaluation).
inline void keep_state_as_schema5(sql::Database& raw) {
  as_schema8(raw);
  std::vector<std::tuple<std::int64_t, std::int64_t, std::vector<evo::Individual>>> rows;
  auto q = raw.prepare("SELECT controller_id, run, state FROM optimizer_state WHERE algorithm = 'es'");
  while (q.step()) {
    const std::string_view b = q.bytes(2);
    evo::StateReader r(std::span(reinterpret_cast<const std::uint8_t*>(b.data()), b.size()));
    std::vector<evo::Individual> parents(r.get<std::uint64_t>());
    for (evo::Individual& p : parents) {
      p.fitness = r.get<double>();
      p.genes = r.doubles();
      p.sigmas = r.doubles();
    }
    rows.emplace_back(q.int64(0), q.int64(1), std::move(parents));
  }
  for (const auto& [controller, run, parents] : rows)
    raw.prepare("INSERT INTO run_state(controller_id, run, parents, genome_size, sigma_count, population) "
                "VALUES (?, ?, ?, ?, ?, ?)")
        .bind(1, controller).bind(2, run).bind(3, static_cast<std::int64_t>(parents.size()))
        .bind(4, static_cast<std::int64_t>(parents.front().genes.size()))
        .bind(5, static_cast<std::int64_t>(parents.front().sigmas.size())).bind_blob(6, pack_parents(parents))
        .run();
  raw.exec("DROP TABLE optimizer_state; DROP TABLE metrics; DROP TABLE member_layouts; DROP TABLE members; "
           "ALTER TABLE controllers DROP COLUMN algorithm; "
           "ALTER TABLE runs DROP COLUMN stopped; ALTER TABLE runs DROP COLUMN success_evaluation;");
}

// As schema 7 wrote it: without schema 8's column runs.success_evaluation (the runs sealed
// again without it) and tables member_layouts and members.
inline void as_schema7(sql::Database& raw) {
  as_schema8(raw);
  raw.exec("ALTER TABLE runs DROP COLUMN success_evaluation; DROP TABLE member_layouts; DROP TABLE members; "
           "PRAGMA user_version=7;");
  seal_table(raw, "runs");
}

// Drops the checksums of every sealed table the database has, as before schema 5 (call
// keep_state_as_schema5 first: the tables of schema 6 and later are gone then).
inline void drop_checksums(sql::Database& raw) {
  for (const std::string_view t : sealed_tables()) {
    if (raw.has_table(t)) raw.exec(fmt::format("ALTER TABLE {} DROP COLUMN checksum;", t));
  }
}

}  // namespace esc::store::test
