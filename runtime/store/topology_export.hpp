#pragma once
// `esc export DIR... --table topology`: the network NEAT evolved as each run's best (a
// `neat(...)` controller's graph genome, docs/neat.md), node by node and link by link, as
// one tidy table (a row per experiment, condition, controller, run and gene), ready for R,
// pandas or networkx to draw or count.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/store/results_db.hpp"

namespace esc::store {

// The columns, in order: `condition` is a study's condition and empty for a plain
// experiment; `element` is `node` or `link`. A node row has its id, kind (input, bias,
// hidden, output) and activation; a link row its innovation number as `id`, its in and
// out nodes, weight and enabled flag (1 or 0). Cells a row has no use for are empty.
inline constexpr const char* kTopologyColumns =
    "experiment,condition,controller,run,element,id,kind,activation,in,out,weight,enabled";

// Header then rows (runs from 1; weights with 17 significant digits), each finished run's
// best, nodes in id order then links in innovation order; controllers that are not NEAT
// networks have none.
[[nodiscard]] std::string topology_csv(const std::vector<StoredDirectory>& directories);
// The same rows as an array of objects keyed by the column names (a cell without use: null).
[[nodiscard]] nlohmann::ordered_json topology_json(const std::vector<StoredDirectory>& directories);

}  // namespace esc::store
