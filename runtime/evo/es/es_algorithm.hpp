#pragma once
// The paper's evolution strategy as the registry holds it (registry.hpp): its name, the
// genomes it evolves, and how its settings make an optimizer, size a generation and weigh in
// memory. Its options are still the compiler's own table with their historic keys (`mu`,
// compiler/es_options.hpp), so it has no options() here.
#include <cstdint>
#include <memory>
#include <string_view>

#include "runtime/evo/es/es_optimizer.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

struct EsAlgorithm {
  using Settings = EsSettings;
  std::string_view name = "es";
  std::string_view what = "the ES";
  genome::GenomeKinds kinds{genome::GenomeKind::Vector};
  std::uint32_t state_format = 1;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const { return make_es(s, p); }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const {
    return es_population(s, p.genome_size);
  }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int /*generations*/) const {
    return es_memory_peak(s, p.genome_size);
  }
};

}  // namespace esc::evo
