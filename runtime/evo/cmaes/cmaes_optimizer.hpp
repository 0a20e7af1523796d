#pragma once
// CMA-ES (cmaes.hpp) as an Optimizer of a network's weights: it starts from a mean drawn
// from Rng(seed, Init) (or the start genome, then candidate 0 of generation 0), samples
// generation g from Rng(seed, Breed, g), and minimises the negated fitness. Its metrics are
// the step size, the covariance's condition number and the population size (IPOP doubles
// it); a stop that fires with no restart left ends the run's search there.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/cmaes/cmaes.hpp"
#include "runtime/evo/cmaes/cmaes_options.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

// Throws std::invalid_argument on impossible settings (Cmaes's checks).
[[nodiscard]] std::unique_ptr<Optimizer> make_cmaes(const CmaesSettings& settings, const Problem& problem);

// Candidates of the first generation for a genome of `n` weights: lambda, or its default.
[[nodiscard]] std::size_t cmaes_population(const CmaesSettings& settings, std::size_t n);

// What one run's CMA-ES holds at its peak: its covariance and eigenvectors (n x n, or their
// diagonals when separable) with the eigensolver's copy and workspace, and a generation's
// samples (z and y) and candidates at the largest population, lambda x 2^restarts (IPOP
// doubles it at each restart).
[[nodiscard]] MemoryPeak cmaes_memory_peak(const CmaesSettings& settings, std::size_t n);

// CMA-ES as the registry holds it (registry.hpp): its name, the genomes it evolves, and how
// its settings make an optimizer, size a generation, weigh in memory and read in scripts.
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
