#pragma once
// NEAT's species and what decides how many offspring each gets (the paper, section 3.3;
// NEAT C++'s Species::adjust_fitness and count_offspring, Population::epoch), apart from
// the breeding itself so that each step is checked on a small hand-built population.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "runtime/evo/neat/neat_settings.hpp"
#include "runtime/genome/graph/distance.hpp"

namespace esc::evo {

// A record before any fitness was seen (NEAT C++ starts its records at 0, which a fitness
// that may be negative would never beat).
inline constexpr double kNoRecord = -std::numeric_limits<double>::infinity();

struct Species {
  std::int64_t id = 0;
  int age = 1;
  int last_improved = 0;      // its age when its best fitness last rose (age_of_last_improvement)
  double best_ever = kNoRecord;   // max_fitness_ever, as measured
  bool novel = false;         // founded in the last breeding: not aged at its end
  std::vector<std::size_t> members;   // population indices; once ranked, the champion first
  friend bool operator==(const Species&, const Species&) = default;
};

// The first of `representatives` closer to `g` than `threshold`, or representatives.size()
// (Population::speciate, Species::reproduce: the first fit, in the species' order).
[[nodiscard]] std::size_t find_species(const genome::graph::Graph& g,
                                       std::span<const genome::graph::Graph* const> representatives,
                                       const genome::graph::Coefficients& c, double threshold);

struct Shares {
  std::vector<double> shared;          // per population index: shifted fitness / species size, x 0.01 if stagnant
  std::vector<std::size_t> parents;    // per species: how many of its best breed
};

// Species::adjust_fitness for every species: ranks its members by `fitness` (best first,
// ties in population order), penalises a species that has not improved for dropoff_age
// generations (age - last_improved + 1 >= dropoff_age), divides by its size (explicit
// fitness sharing), records an improvement, and keeps floor(survival_thresh x size + 1)
// parents. NEAT needs fitness >= 0: when the lowest of `fitness` (all finite) is negative,
// every value is shifted up by it before sharing; records and ranks use the values as
// measured, so that a shift that changes from one generation to the next moves no record.
[[nodiscard]] Shares share_fitness(std::vector<Species>& species, std::span<const double> fitness,
                                   const NeatSettings& s);

// Offspring per species (Population::epoch): each member expects shared / mean shared; a
// species gets the whole parts of its members' expectations and the fractions carried
// from species to species (count_offspring's skim); a shortfall goes to the species
// expecting most (the last of equals), and if that is not enough all go to it. Every member
// expects 1 when all shared fitness is 0 (where NEAT C++ divides by zero).
[[nodiscard]] std::vector<int> allocate_offspring(const std::vector<Species>& species, std::span<const double> shared,
                                                  std::size_t population);

}  // namespace esc::evo
