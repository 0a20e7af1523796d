#pragma once
// Novelty search as the registry holds it (registry.hpp): its name, the genomes it evolves,
// and how its settings make an optimizer, size a generation, weigh in memory and read in
// scripts.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/novelty/novelty_optimizer.hpp"
#include "runtime/evo/novelty/novelty_options.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

struct NoveltyAlgorithm {
  using Settings = NoveltyRunSettings;
  std::string_view name = "novelty";
  std::string_view what = "novelty search";
  genome::GenomeKinds kinds{genome::GenomeKind::Vector, genome::GenomeKind::Tree};
  std::uint32_t state_format = 1;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const { return make_novelty(s, p); }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const { return novelty_population(s, p); }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int /*generations*/) const {
    return novelty_memory_peak(s, p);
  }
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const { return novelty_options(); }
  [[nodiscard]] std::string problem(const Settings& s, const Problem& p) const { return novelty_problem(s, p); }
};

}  // namespace esc::evo
