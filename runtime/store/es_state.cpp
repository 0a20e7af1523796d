#include "runtime/store/es_state.hpp"

#include <fmt/format.h>

#include "runtime/store/results_db.hpp"
#include "runtime/store/row_checksum.hpp"

namespace esc::store {

void save_state(sql::Database& db, std::int64_t controller_id, int run, const eval::EsState& state) {
  const std::size_t genome_size = state.parents.empty() ? 0 : state.parents.front().genes.size();
  const std::size_t sigma_count = state.parents.empty() ? 0 : state.parents.front().sigmas.size();
  db.prepare(
        "INSERT OR REPLACE INTO run_state(controller_id, run, parents, genome_size, sigma_count, population) "
        "VALUES (?, ?, ?, ?, ?, ?)")
      .bind(1, controller_id).bind(2, run).bind(3, static_cast<std::int64_t>(state.parents.size()))
      .bind(4, static_cast<std::int64_t>(genome_size)).bind(5, static_cast<std::int64_t>(sigma_count))
      .bind_blob(6, pack_parents(state.parents))
      .run();
  seal_row(db, "run_state", db.last_insert_rowid());
}

std::optional<eval::EsState> load_es_state(sql::Database& db, std::int64_t controller_id, int run,
                                           std::size_t genome_size, std::string_view damaged) {
  auto st = db.prepare("SELECT parents, genome_size, sigma_count, population FROM run_state "
                       "WHERE controller_id = ? AND run = ?");
  st.bind(1, controller_id).bind(2, run);
  if (!st.step()) return std::nullopt;
  const auto genes = static_cast<std::size_t>(st.int64(1));
  auto parents = unpack_parents(st.doubles(3), static_cast<std::size_t>(st.int64(0)), genes,
                                static_cast<std::size_t>(st.int64(2)));
  if (genes != genome_size || !parents)
    throw StoreError(fmt::format("{}: the stored population has the wrong size", damaged));
  return eval::EsState{std::move(*parents)};
}

std::vector<double> pack_parents(const std::vector<evo::Individual>& parents) {
  std::vector<double> v;
  for (const evo::Individual& ind : parents) {
    v.push_back(ind.fitness);
    v.insert(v.end(), ind.genes.begin(), ind.genes.end());
    v.insert(v.end(), ind.sigmas.begin(), ind.sigmas.end());
  }
  return v;
}

std::optional<std::vector<evo::Individual>> unpack_parents(const std::vector<double>& blob, std::size_t parents,
                                                           std::size_t genes, std::size_t sigmas) {
  const std::size_t width = 1 + genes + sigmas;
  if (blob.size() / width != parents || blob.size() % width != 0) return std::nullopt;
  std::vector<evo::Individual> out(parents);
  for (std::size_t p = 0; p < parents; ++p) {
    const double* row = blob.data() + p * width;
    out[p].fitness = row[0];
    out[p].genes.assign(row + 1, row + 1 + genes);
    out[p].sigmas.assign(row + 1 + genes, row + width);
  }
  return out;
}

}  // namespace esc::store
