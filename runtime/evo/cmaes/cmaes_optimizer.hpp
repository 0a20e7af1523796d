#pragma once
// CMA-ES (cmaes.hpp) as an Optimizer of a network's weights: it starts from a mean drawn
// from Rng(seed, Init) (or the start genome, then candidate 0 of generation 0), samples
// generation g from Rng(seed, Breed, g), and minimises the negated fitness. Its metrics are
// the step size, the covariance's condition number and the population size (IPOP doubles
// it); a stop that fires with no restart left ends the run's search there.
#include <cstddef>
#include <memory>

#include "runtime/evo/cmaes/cmaes.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/optimizer.hpp"

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

}  // namespace esc::evo
