#pragma once
// `esc export DIR... --table front|archive`: what the optimizers kept beside each run's best,
// generation by generation (member_tables.hpp), as one table ready for R or pandas:
// - front: NSGA-II's first front after every generation, whole (a row per member);
// - archive: each generation's changes to an archive, a row per cell that got a new elite
//   (MAP-Elites) or behavior added (novelty search), so that the archive after generation g
//   is each cell's last row up to g (pandas: `df[df.generation <= g].groupby(["run",
//   "cell"]).last()`).
// Columns: experiment,condition,controller,algorithm,run,generation,cell, then one per value
// the members keep, named as the script names it (objectives, fitness first, as measured;
// then descriptors), the union over the runs exported in the order first met; a member
// without that value leaves it empty (CSV) or null (JSON).
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/store/results_db.hpp"

namespace esc::store {

// `kind` is "front" or "archive". Runs from 1, generations from 0, values with 17
// significant digits.
[[nodiscard]] std::string members_csv(const std::vector<StoredDirectory>& directories, std::string_view kind);
// The same rows as an array of objects keyed by the column names.
[[nodiscard]] nlohmann::ordered_json members_json(const std::vector<StoredDirectory>& directories,
                                                  std::string_view kind);

}  // namespace esc::store
