#pragma once
// The paper's evolution strategy (es.hpp) as an Optimizer: generation 0 is bred from the
// initial parents (drawn from Rng(seed, Init), or mu copies of the start genome), every
// generation g from Rng(seed, Breed, g); tell() selects the next parents. Its state is the
// parents, genes, step sizes and fitness.
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "runtime/evo/es/es.hpp"
#include "runtime/evo/es/es_options.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

[[nodiscard]] std::unique_ptr<Optimizer> make_es(const EsSettings& settings, const Problem& problem);

// Offspring per generation: lambda.
[[nodiscard]] std::size_t es_population(const EsSettings& settings, std::size_t genome_size);
// What one run's ES holds at its peak: parents, offspring and the parents selected from
// them, with their genes and step sizes; the offspring's genes handed out to be evaluated;
// the saved parents, old and new.
[[nodiscard]] MemoryPeak es_memory_peak(const EsSettings& settings, std::size_t genome_size);

// The ES's saved state for `parents`: what a store that kept the parents in a table of its
// own (results schema 5 and older) hands a resumed run.
[[nodiscard]] StateBytes es_state(std::span<const Individual> parents);

// The paper's evolution strategy as the registry holds it (registry.hpp): its name, the
// genomes it evolves, how its settings make an optimizer, size a generation and weigh in
// memory, and its options (es_options.hpp). Every experiment holds its settings, and scripts
// write its keys bare (`--set mu=30`), as the paper's always did.
struct EsAlgorithm {
  using Settings = EsSettings;
  std::string_view name = "es";
  std::string_view what = "ES";
  genome::GenomeKinds kinds{genome::GenomeKind::Vector};
  std::uint32_t state_format = 1;
  SettingsScope scope = SettingsScope::Always;
  bool bare_keys = true;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const { return make_es(s, p); }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const {
    return es_population(s, p.genome_size);
  }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int /*generations*/) const {
    return es_memory_peak(s, p.genome_size);
  }
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const { return es_options(); }
  [[nodiscard]] OptionRefusal conflict(const Settings& s) const { return es_conflict(s); }
};

}  // namespace esc::evo
