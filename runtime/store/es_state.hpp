#pragma once
// The state an unfinished network run continues from (eval::EsState) in the results
// database, table run_state: how many parents, genes and step sizes each has, and one BLOB
// of doubles with, per parent, its fitness, genes and step sizes. Doubles are stored as they
// are, so a resumed run is bit-identical to the run that was not interrupted.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "runtime/eval/run_state.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store {

// Writes (or replaces) the state of run `run` of the controller with id `controller_id`.
// Every parent must have as many genes and as many step sizes as the first.
void save_state(sql::Database& db, std::int64_t controller_id, int run, const eval::EsState& state);

// The state stored for that run; nullopt when there is none. Throws StoreError, its message
// starting with `damaged`, when the stored parents do not have `genome_size` genes each or
// the BLOB does not hold what the row says.
[[nodiscard]] std::optional<eval::EsState> load_es_state(sql::Database& db, std::int64_t controller_id, int run,
                                                         std::size_t genome_size, std::string_view damaged);

// The BLOB, and back: `parents` parents of `genes` genes and `sigmas` step sizes; nullopt
// when `blob` does not hold exactly that.
[[nodiscard]] std::vector<double> pack_parents(const std::vector<evo::Individual>& parents);
[[nodiscard]] std::optional<std::vector<evo::Individual>> unpack_parents(const std::vector<double>& blob,
                                                                         std::size_t parents, std::size_t genes,
                                                                         std::size_t sigmas);

}  // namespace esc::store
