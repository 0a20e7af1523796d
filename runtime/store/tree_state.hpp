#pragma once
// The state a GP run kept in results schema 2 to 5 (table tree_state, read only since
// schema 6 keeps every optimizer's in optimizer_tables.hpp), read back as the GP optimizer's
// state: the number of individuals and one BLOB of doubles with,
// per individual, its fitness, its node count, then per node in postfix order the primitive
// id, arity, type, subtree length and value; converted to GP's state (trees encoded), which
// the GP optimizer decodes with the script's primitive set when the run resumes.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "runtime/eval/run_state.hpp"
#include "runtime/evo/gp/selection.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store {

// The state stored for that run, as the GP optimizer saves it; nullopt when there is none.
// Throws StoreError, its message starting with `damaged`, when the BLOB does not hold the
// stored number of trees.
[[nodiscard]] std::optional<eval::OptimizerState> load_tree_state(sql::Database& db, std::int64_t controller_id, int run,
                                                           std::string_view damaged);

// The BLOB (tests write schema-5 rows with it), and back.
[[nodiscard]] std::vector<double> pack_trees(const std::vector<evo::gp::Individual>& population);

// `count` individuals from `blob`; nullopt when the blob does not hold exactly that.
[[nodiscard]] std::optional<std::vector<evo::gp::Individual>> unpack_trees(const std::vector<double>& blob,
                                                                           std::size_t count);

}  // namespace esc::store
