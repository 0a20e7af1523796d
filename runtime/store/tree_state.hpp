#pragma once
// A GP population as the BLOB of doubles the results database keeps to resume a run
// (table tree_state): per individual its fitness, its node count, then per node in
// postfix order the primitive id, arity, type, subtree length and value. Every field of
// every node is kept, so trees come back bit for bit without the script's primitive set
// (the campaign checks them against it when it resumes).
#include <optional>
#include <vector>

#include "runtime/evo/gp/selection.hpp"

namespace esc::store {

[[nodiscard]] std::vector<double> pack_trees(const std::vector<evo::gp::Individual>& population);

// `count` individuals from `blob`; nullopt when the blob does not hold exactly that.
[[nodiscard]] std::optional<std::vector<evo::gp::Individual>> unpack_trees(const std::vector<double>& blob,
                                                                           std::size_t count);

}  // namespace esc::store
