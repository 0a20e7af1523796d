#pragma once
// The state an ES run kept in results schema 5 and older (table run_state, read only since
// schema 6 keeps every optimizer's in optimizer_tables.hpp): how many parents, genes and step
// sizes each has, and one BLOB of doubles with, per parent, its fitness, genes and step
// sizes. Read back as the ES optimizer's state, so such a run resumes and carries on.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "runtime/eval/run_state.hpp"
#include "runtime/evo/es/es.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store {

// The state stored for that run, as the ES optimizer saves it; nullopt when there is none.
// Throws StoreError, its message starting with `damaged`, when the stored parents do not
// have `genome_size` genes each or the BLOB does not hold what the row says.
[[nodiscard]] std::optional<eval::OptimizerState> load_es_state(sql::Database& db, std::int64_t controller_id, int run,
                                                         std::size_t genome_size, std::string_view damaged);

// The BLOB (tests write schema-5 rows with it), and back: `parents` parents of `genes` genes and `sigmas` step sizes; nullopt
// when `blob` does not hold exactly that.
[[nodiscard]] std::vector<double> pack_parents(const std::vector<evo::Individual>& parents);
[[nodiscard]] std::optional<std::vector<evo::Individual>> unpack_parents(const std::vector<double>& blob,
                                                                         std::size_t parents, std::size_t genes,
                                                                         std::size_t sigmas);

}  // namespace esc::store
