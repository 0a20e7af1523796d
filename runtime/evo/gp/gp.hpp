#pragma once
// Generational strongly typed genetic programming as a value type, in the style of
// evo::EvolutionStrategy: it holds settings and the primitive set only, every call that
// draws numbers takes the Rng, fitness is maximised.
//
// A run (the evaluation loop owns it):
//   GeneticProgramming gp(settings, set);
//   Rng init(seed, {run, Stream::Init});
//   auto pop = gp.initial(init);                       // fitness unset
//   for (g = 0; g < settings.generations; ++g) {
//     evaluate every pop[i].fitness (any threads: a tree's fitness depends on its own streams)
//     Rng breed(seed, {run, g, Stream::Breed});
//     pop = gp.breed(pop, breed);                     // next generation, fitness unset
//   }
// breed() draws one number from the Rng and derives every offspring's stream from it and
// the offspring's index (offspring()), so breeding may also run in parallel with the same
// result.
#include <cstdint>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/evo/gp/selection.hpp"
#include "runtime/genome/tree/tree_operators.hpp"

namespace esc::evo::gp {

// GP's own settings, and the tree operators it breeds with (the tree kind's: tree_operators.hpp).
struct GpSettings : genome::tree::TreeOperators {
  int population = 150;
  int generations = 250;
  int tournament = 7;
  int elitism = 1;                 // best individuals copied unchanged to the next generation
};

class GeneticProgramming {
 public:
  // Throws std::invalid_argument on impossible settings, naming the setting (population < 1,
  // elitism > population, probabilities outside [0, 1] or summing above 1, max_depth below
  // the shallowest tree of the root type or above kMaxDepthLimit, max_size below the
  // smallest tree, init depths out of order, ...).
  GeneticProgramming(const GpSettings& settings, genome::tree::PrimitiveSet set);

  // `population` trees by ramped half-and-half, fitness 0 (not yet evaluated).
  [[nodiscard]] std::vector<Individual> initial(Rng& rng) const;

  // The next generation, same size: the `elitism` best of `population` (by fitness, then
  // size) first, unchanged, then offspring(population, base, i) for the other indices,
  // where base = rng.next(). Fitness of the result is that of the elites and 0 for the
  // rest; a loop may re-evaluate the elites (noisy fitness) or keep theirs.
  [[nodiscard]] std::vector<Individual> breed(std::span<const Individual> population, Rng& rng) const;

  // Offspring number i of a generation, drawn from the stream (base, i) alone: tournament
  // winners through crossover, a mutation or a copy. Thread safe (const).
  [[nodiscard]] Individual offspring(std::span<const Individual> population, std::uint64_t base,
                                     std::size_t i) const;

  // Tournament selection with parsimony ties (selection.hpp).
  [[nodiscard]] std::size_t select(std::span<const Individual> population, Rng& rng) const;

  [[nodiscard]] const GpSettings& settings() const noexcept { return s_; }
  [[nodiscard]] const genome::tree::PrimitiveSet& primitives() const noexcept { return set_; }
  [[nodiscard]] genome::tree::Limits limits() const noexcept { return s_.limits(); }

 private:
  GpSettings s_;
  genome::tree::PrimitiveSet set_;
};

}  // namespace esc::evo::gp
