#pragma once
// Self-adaptive evolution strategies: (mu, lambda) and (mu + lambda), with intermediate or
// discrete recombination and Gaussian mutation whose step sizes evolve with the genes
// (one sigma per individual or one per gene; Schwefel's learning rates). Genes stay in
// [lower, upper] by reflection at the bounds. Fitness is maximised.
//
// The strategy is a value type: it holds settings only. Every call that draws numbers
// takes the Rng explicitly, so a run is reproducible from its seeds.
#include <cstddef>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/evo/limits.hpp"

namespace esc::evo {


enum class Selection { Comma, Plus };
enum class Recombination { Intermediate, Discrete, None };
enum class StepSizes { One, PerGene };

struct EsSettings {
  int mu = 30;
  int lambda = 150;
  Selection selection = Selection::Comma;
  Recombination recombination = Recombination::Intermediate;
  StepSizes step_sizes = StepSizes::PerGene;
  double lower = -1.0;
  double upper = 1.0;
  double initial_sigma = 0.1;   // as a fraction of (upper - lower), at most kMaxStepSize
  double min_sigma = 1e-6;      // absolute floor, keeps self-adaptation from collapsing;
                                // at most upper - lower
};

struct Individual {
  std::vector<double> genes;
  std::vector<double> sigmas;   // size 1 or genes.size()
  double fitness = 0.0;
};

class EvolutionStrategy {
 public:
  // Throws std::invalid_argument on impossible settings (mu < 1, lambda < mu for comma,
  // lower >= upper, ...), with a message naming the setting.
  EvolutionStrategy(const EsSettings& settings, std::size_t genome_size);

  // mu individuals, genes uniform in the bounds, sigmas at the initial step size.
  [[nodiscard]] std::vector<Individual> initial(Rng& rng) const;

  // mu copies of `genome` (which must have genome_size() genes), sigmas at the initial
  // step size: evolution that goes on from a known solution.
  [[nodiscard]] std::vector<Individual> seeded(std::span<const double> genome) const;

  // lambda offspring of `parents` (fitness not yet set). Each parent in turn is the first
  // parent of lambda / mu offspring (the paper's "each parent gives birth to 5"); the
  // mate for recombination is drawn uniformly.
  [[nodiscard]] std::vector<Individual> breed(std::span<const Individual> parents, Rng& rng) const;

  // The next mu parents: best of offspring (comma) or of parents and offspring (plus).
  // Ties keep the earlier individual, so selection is deterministic.
  [[nodiscard]] std::vector<Individual> select(std::span<const Individual> parents,
                                               std::span<const Individual> offspring) const;

  [[nodiscard]] const EsSettings& settings() const noexcept { return s_; }
  [[nodiscard]] std::size_t genome_size() const noexcept { return n_; }

 private:
  EsSettings s_;
  std::size_t n_;
};

}  // namespace esc::evo
