#pragma once
// Databases as an esc before results schema 6 wrote them, made from a current one: the tests
// of upgrades and of reading old results start from these.
#include <cstdint>
#include <span>
#include <string_view>
#include <tuple>
#include <vector>

#include "runtime/evo/es/es.hpp"
#include "runtime/evo/state_bytes.hpp"
#include "runtime/store/es_state.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store::test {

// Moves every ES run's state into table run_state, as schema 5 kept it, and drops what
// schemas 6, 7 and 8 added (tables optimizer_state and metrics, columns controllers.algorithm,
// runs.stopped and runs.success_evaluation).
inline void keep_state_as_schema5(sql::Database& raw) {
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
  raw.exec("DROP TABLE optimizer_state; DROP TABLE metrics; ALTER TABLE controllers DROP COLUMN algorithm; "
           "ALTER TABLE runs DROP COLUMN stopped; ALTER TABLE runs DROP COLUMN success_evaluation;");
}

}  // namespace esc::store::test
