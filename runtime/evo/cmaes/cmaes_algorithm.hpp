#pragma once
// CMA-ES as the registry holds it (registry.hpp): its name, the genomes it evolves, and how
// its settings make an optimizer, size a generation, weigh in memory and read in scripts.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/cmaes/cmaes_optimizer.hpp"
#include "runtime/evo/cmaes/cmaes_options.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

struct CmaesAlgorithm {
  using Settings = CmaesSettings;
  std::string_view name = "cmaes";
  std::string_view what = "CMA-ES";
  genome::GenomeKinds kinds{genome::GenomeKind::Vector};
  std::uint32_t state_format = 1;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const { return make_cmaes(s, p); }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const {
    return cmaes_population(s, p.genome_size);
  }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int /*generations*/) const {
    return cmaes_memory_peak(s, p.genome_size);
  }
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const { return cmaes_options(); }
  [[nodiscard]] std::string problem(const Settings& s, const Problem& p) const { return cmaes_problem(s, p.genome_size); }
};

}  // namespace esc::evo
