#pragma once
// NSGA-II as the registry holds it (registry.hpp): its name, the genomes it evolves (a
// network's weights in a box, or trees varied by the tree kind's operators), and how its
// settings make an optimizer, size a generation, weigh in memory and read in scripts.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/nsga2/nsga2_optimizer.hpp"
#include "runtime/evo/nsga2/nsga2_options.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

struct Nsga2Algorithm {
  using Settings = Nsga2Settings;
  std::string_view name = "nsga2";
  std::string_view what = "NSGA-II";
  genome::GenomeKinds kinds{genome::GenomeKind::Vector, genome::GenomeKind::Tree};
  std::uint32_t state_format = 1;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const { return make_nsga2(s, p); }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const { return nsga2_population(s, p); }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int /*generations*/) const {
    return nsga2_memory_peak(s, p);
  }
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const { return nsga2_options(); }
  [[nodiscard]] std::string problem(const Settings& s, const Problem& p) const { return nsga2_problem(s, p); }
};

}  // namespace esc::evo
