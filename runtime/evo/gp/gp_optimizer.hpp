#pragma once
// Generational GP (gp.hpp) as an Optimizer over encoded trees (codec.hpp): generation 0 is
// the initial population drawn from Rng(seed, Init) (a run that starts from a stored tree:
// bred from copies of it with that stream, the tree itself kept as individual 0), every
// generation g > 0 is bred from generation g - 1 with Rng(seed, Breed, g). Every individual
// is evaluated, elites too: fitness is measured from random start poses, so an elite is
// judged on this generation's streams like everyone else. Its state is the last evaluated
// population with its fitness.
#include <memory>
#include <span>

#include "runtime/evo/gp/gp.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/optimizer.hpp"

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

}  // namespace esc::evo::gp
