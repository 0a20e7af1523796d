#pragma once
// Generational GP (gp.hpp) as an Optimizer over encoded trees (codec.hpp): generation 0 is
// the initial population drawn from Rng(seed, Init) (a run that starts from a stored tree:
// bred from copies of it with that stream, the tree itself kept as individual 0), every
// generation g > 0 is bred from generation g - 1 with Rng(seed, Breed, g). Every individual
// is evaluated, elites too: fitness is measured from random start poses, so an elite is
// judged on this generation's streams like everyone else. Its state is the last evaluated
// population with its fitness.
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

#include "runtime/evo/gp/gp.hpp"
#include "runtime/evo/gp/gp_options.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo::gp {

// Throws std::invalid_argument on impossible settings (GeneticProgramming's checks).
[[nodiscard]] std::unique_ptr<Optimizer> make_gp(const GpSettings& settings, const Problem& problem);

// Trees per generation: the population.
[[nodiscard]] std::size_t gp_population(const GpSettings& settings, std::size_t genome_size);
// What one run's GP holds at its peak: the evaluated generation and the one bred from it,
// the bred trees handed out encoded and the saved population (old and new), every tree at
// most max_size nodes.
[[nodiscard]] MemoryPeak gp_memory_peak(const GpSettings& settings, std::size_t genome_size);

// GP's saved state for `population`: what a store that kept the population in a table of
// its own (results schema 5 and older) hands a resumed run.
[[nodiscard]] StateBytes gp_state(std::span<const Individual> population);

// Generational GP as the registry holds it (registry.hpp): its name, the genomes it evolves
// (trees), how its settings make an optimizer, size a generation and weigh in memory, its
// options (gp_options.hpp) and whether they suit a tree's primitives. An experiment holds
// its settings where the script gives them (`evolve gp`): they hold the tree operators that
// every algorithm varies trees with, and the trees' generations.
struct GpAlgorithm {
  using Settings = GpSettings;
  std::string_view name = "gp";
  std::string_view what = "GP";
  genome::GenomeKinds kinds{genome::GenomeKind::Tree};
  std::uint32_t state_format = 1;
  SettingsScope scope = SettingsScope::Given;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const { return make_gp(s, p); }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const {
    return gp_population(s, p.genome_size);
  }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int /*generations*/) const {
    return gp_memory_peak(s, p.genome_size);
  }
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const { return gp_options(); }
  [[nodiscard]] std::string problem(const Settings& s, const Problem& p) const {
    return gp_problem(s, p.tree.primitives);
  }
};

}  // namespace esc::evo::gp
