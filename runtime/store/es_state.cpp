#include "runtime/store/es_state.hpp"

#include <fmt/format.h>

#include "runtime/evo/es/es_optimizer.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::store {

std::optional<eval::OptimizerState> load_es_state(sql::Database& db, std::int64_t controller_id, int run,
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
  return eval::OptimizerState{"es", 1, evo::es_state(*parents)};
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
