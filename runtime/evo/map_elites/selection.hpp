#pragma once
// MAP-Elites' selection (Mouret & Clune 2015, as pymap_elites and pyribs do it): a parent is
// an elite drawn uniformly from the filled cells, whatever its fitness. A function over the
// archive, so any variation can use it: iso+line-dd for a network's weights
// (iso_line_dd.hpp), the GP's own mutation for a tree.
#include "runtime/core/rng.hpp"
#include "runtime/evo/map_elites/archive.hpp"

namespace esc::evo::qd {

// One draw, rng.below(filled()), the filled cells in increasing order. Throws
// std::logic_error on an empty archive.
[[nodiscard]] const Elite& select_uniform(const Archive& archive, Rng& rng);

}  // namespace esc::evo::qd
