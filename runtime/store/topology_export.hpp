#pragma once
// `esc export DIR... --table topology`: the networks NEAT evolved (a `neat(...)`
// controller's graph genomes, docs/neat.md), each run's best and its final front's or
// archive's members, node by node and link by link, as one tidy table (a row per
// experiment, condition, controller, run, member and gene), ready for R, pandas or networkx
// to draw or count.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/store/results_db.hpp"

namespace esc::store {

// The columns, in order: `condition` is a study's condition and empty for a plain
// experiment; `member` is `best` (the run's best), `front` or `archive` (a member of the
// run's final front or archive, its position or cell in `cell`); `element` is `node` or
// `link`. A node row has its id, kind (input, bias, hidden, output) and activation; a link
// row its innovation number as `id`, its in and out nodes, weight and enabled flag (1 or
// 0). Cells a row has no use for are empty.
inline constexpr const char* kTopologyColumns =
    "experiment,condition,controller,run,member,cell,element,id,kind,activation,in,out,weight,enabled";

// The graph genomes a finished run kept beside its best (its optimizer's final front or
// archive: NSGA-II, novelty search, MAP-Elites over a `neat(...)` controller).
struct RunMembers {
  std::string experiment;
  std::string condition;
  std::string controller;
  int run = 0;             // from 1
  std::string kind;        // "front" or "archive"
  std::vector<std::pair<std::int64_t, std::vector<double>>> genomes;   // cell, genome
};

// Header then rows (runs from 1; weights with 17 significant digits): each finished run's
// best, then `members` in their order, each network's nodes in id order then its links in
// innovation order; controllers that are not NEAT networks have none.
[[nodiscard]] std::string topology_csv(const std::vector<StoredDirectory>& directories,
                                       const std::vector<RunMembers>& members = {});
// The same rows as an array of objects keyed by the column names (a cell without use: null).
[[nodiscard]] nlohmann::ordered_json topology_json(const std::vector<StoredDirectory>& directories,
                                                   const std::vector<RunMembers>& members = {});

}  // namespace esc::store
