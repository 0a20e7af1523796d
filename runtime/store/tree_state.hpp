#pragma once
// The state an unfinished tree run continues from (eval::GpState, a GP population) in the
// results database, table tree_state: the number of individuals and one BLOB of doubles with,
// per individual, its fitness, its node count, then per node in postfix order the primitive
// id, arity, type, subtree length and value. Every field of every node is kept, so trees come
// back bit for bit without the script's primitive set (the campaign checks them against it
// when it resumes).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "runtime/eval/run_state.hpp"
#include "runtime/store/sqlite.hpp"

namespace esc::store {

// Writes (or replaces) the state of run `run` of the controller with id `controller_id`.
void save_state(sql::Database& db, std::int64_t controller_id, int run, const eval::GpState& state);

// The state stored for that run; nullopt when there is none. Throws StoreError, its message
// starting with `damaged`, when the BLOB does not hold the stored number of trees.
[[nodiscard]] std::optional<eval::GpState> load_tree_state(sql::Database& db, std::int64_t controller_id, int run,
                                                           std::string_view damaged);

[[nodiscard]] std::vector<double> pack_trees(const std::vector<evo::gp::Individual>& population);

// `count` individuals from `blob`; nullopt when the blob does not hold exactly that.
[[nodiscard]] std::optional<std::vector<evo::gp::Individual>> unpack_trees(const std::vector<double>& blob,
                                                                           std::size_t count);

}  // namespace esc::store
