#pragma once
// MAP-Elites as the registry holds it (registry.hpp), twice: its grid archive under
// `map_elites`, and CVT-MAP-Elites (Vassiliades et al. 2018) under `cvt_map_elites`, the same
// value with the other name, options and defaults (a CVT archive), so that both share every
// line of code and keep their own names in scripts and stored states.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/map_elites/map_elites_optimizer.hpp"
#include "runtime/evo/map_elites/map_elites_options.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

struct MapElitesAlgorithm {
  using Settings = MapElitesRunSettings;
  std::string_view name = "map_elites";
  std::string_view what = "MAP-Elites";
  genome::GenomeKinds kinds{genome::GenomeKind::Vector, genome::GenomeKind::Tree};
  std::uint32_t state_format = 1;
  bool cvt = false;   // its archive: a grid, or a CVT's cells

  // CVT-MAP-Elites.
  [[nodiscard]] static MapElitesAlgorithm centroidal() {
    return {.name = "cvt_map_elites", .what = "CVT-MAP-Elites", .cvt = true};
  }

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const {
    return make_map_elites(s, p);
  }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const { return map_elites_population(s, p); }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int generations) const {
    return map_elites_memory_peak(s, p, generations);
  }
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const {
    return cvt ? cvt_map_elites_options() : map_elites_options();
  }
  [[nodiscard]] Settings defaults() const {
    Settings s;
    s.cvt = cvt;
    return s;
  }
  [[nodiscard]] std::string problem(const Settings& s, const Problem& p) const { return map_elites_problem(s, p); }
};

}  // namespace esc::evo
