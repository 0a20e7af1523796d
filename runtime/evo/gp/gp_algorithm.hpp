#pragma once
// Generational GP as the registry holds it (registry.hpp): its name, the genomes it evolves
// (trees), and how its settings make an optimizer, size a generation and weigh in memory.
// Its options are still the compiler's own table with their historic keys (`gp.population`,
// compiler/gp_settings.hpp), so it has no options() here.
#include <cstdint>
#include <memory>
#include <string_view>

#include "runtime/evo/gp/gp_optimizer.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo::gp {

struct GpAlgorithm {
  using Settings = GpSettings;
  std::string_view name = "gp";
  std::string_view what = "GP";
  genome::GenomeKinds kinds{genome::GenomeKind::Tree};
  std::uint32_t state_format = 1;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const { return make_gp(s, p); }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const {
    return gp_population(s, p.genome_size);
  }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int /*generations*/) const {
    return gp_memory_peak(s, p.genome_size);
  }
};

}  // namespace esc::evo::gp
