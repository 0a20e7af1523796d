#include "runtime/evo/registry.hpp"

#include <algorithm>

#include "runtime/evo/cmaes/cmaes_optimizer.hpp"
#include "runtime/evo/es/es_optimizer.hpp"
#include "runtime/evo/gp/gp_optimizer.hpp"
#include "runtime/evo/map_elites/map_elites_optimizer.hpp"
#include "runtime/evo/neat/neat_optimizer.hpp"
#include "runtime/evo/novelty/novelty_optimizer.hpp"
#include "runtime/evo/nsga2/nsga2_optimizer.hpp"

namespace esc::evo {

// In the order scripts' messages list them (`networks are evolved by ...`).
const std::vector<Algorithm>& algorithms() {
  static const std::vector<Algorithm> table = {
      Algorithm(EsAlgorithm{}),
      Algorithm(gp::GpAlgorithm{}),
      Algorithm(CmaesAlgorithm{}),
      Algorithm(Nsga2Algorithm{}),
      Algorithm(MapElitesAlgorithm{}),
      Algorithm(MapElitesAlgorithm::centroidal()),
      Algorithm(NoveltyAlgorithm{}),
      Algorithm(NeatAlgorithm{}),
  };
  return table;
}

const Algorithm* find_algorithm(std::string_view name) noexcept {
  const auto& all = algorithms();
  const auto it = std::find_if(all.begin(), all.end(), [&](const Algorithm& a) { return a.name == name; });
  return it == all.end() ? nullptr : &*it;
}

}  // namespace esc::evo
