#include "runtime/evo/es/es.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace esc::evo {

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("evolution strategy: " + message);
}

// Folds x back into [lo, hi] as if reflected at the bounds as many times as needed
// (the walk lo -> hi -> lo is periodic with period 2 (hi - lo)), so even a step many
// times the interval lands inside with the density a mirror would give. A non-finite x
// (only from an overflowing step size) goes to the nearest bound, NaN to the middle.
double reflect(double x, double lo, double hi) noexcept {
  if (x >= lo && x <= hi) return x;
  if (std::isnan(x)) return lo + 0.5 * (hi - lo);
  if (std::isinf(x)) return x > 0 ? hi : lo;
  const double w = hi - lo;
  double m = std::fmod(x - lo, 2.0 * w);
  if (m < 0.0) m += 2.0 * w;
  if (m > w) m = 2.0 * w - m;
  return std::clamp(lo + m, lo, hi);  // the clamp only absorbs rounding
}

// NaN fitness sorts last, so the comparison stays a strict weak order.
double sort_key(double f) noexcept {
  return std::isnan(f) ? -std::numeric_limits<double>::infinity() : f;
}

}  // namespace

EvolutionStrategy::EvolutionStrategy(const EsSettings& settings, std::size_t genome_size)
    : s_(settings), n_(genome_size) {
  require(s_.mu >= 1, "mu must be at least 1, got " + std::to_string(s_.mu));
  require(s_.lambda >= 1, "lambda must be at least 1, got " + std::to_string(s_.lambda));
  require(s_.selection != Selection::Comma || s_.lambda >= s_.mu,
          "lambda (" + std::to_string(s_.lambda) + ") must be at least mu (" +
              std::to_string(s_.mu) + ") for comma selection");
  require(std::abs(s_.lower) <= kMaxGeneBound && std::abs(s_.upper) <= kMaxGeneBound && s_.lower < s_.upper,
          "lower (" + std::to_string(s_.lower) + ") must be below upper (" + std::to_string(s_.upper) +
              "), both within +-1e6");
  require(s_.initial_sigma > 0.0 && s_.initial_sigma <= kMaxStepSize,
          "initial_sigma must be in (0, 1000], got " + std::to_string(s_.initial_sigma));
  require(s_.min_sigma >= 0.0 && s_.min_sigma <= s_.upper - s_.lower,
          "min_sigma must be in [0, upper - lower], got " + std::to_string(s_.min_sigma));
  require(n_ >= 1, "genome_size must be at least 1, got 0");
}

std::vector<Individual> EvolutionStrategy::initial(Rng& rng) const {
  const std::size_t n_sigmas = s_.step_sizes == StepSizes::One ? 1 : n_;
  const double sigma = s_.initial_sigma * (s_.upper - s_.lower);
  std::vector<Individual> pop(static_cast<std::size_t>(s_.mu));
  for (Individual& ind : pop) {
    ind.genes.resize(n_);
    for (double& g : ind.genes) g = rng.uniform(s_.lower, s_.upper);
    ind.sigmas.assign(n_sigmas, sigma);
  }
  return pop;
}

std::vector<Individual> EvolutionStrategy::seeded(std::span<const double> genome) const {
  require(genome.size() == n_, "seeded needs a genome of " + std::to_string(n_) + " genes, got " +
                                   std::to_string(genome.size()));
  const std::size_t n_sigmas = s_.step_sizes == StepSizes::One ? 1 : n_;
  const double sigma = s_.initial_sigma * (s_.upper - s_.lower);
  std::vector<Individual> pop(static_cast<std::size_t>(s_.mu));
  for (Individual& ind : pop) {
    ind.genes.assign(genome.begin(), genome.end());
    ind.sigmas.assign(n_sigmas, sigma);
  }
  return pop;
}

std::vector<Individual> EvolutionStrategy::breed(std::span<const Individual> parents,
                                                 Rng& rng) const {
  require(!parents.empty(), "breed needs at least one parent");
  const std::size_t n_sigmas = s_.step_sizes == StepSizes::One ? 1 : n_;
  for (const Individual& p : parents)
    require(p.genes.size() == n_ && p.sigmas.size() == n_sigmas,
            "parent has " + std::to_string(p.genes.size()) + " genes and " +
                std::to_string(p.sigmas.size()) + " step sizes, expected " +
                std::to_string(n_) + " and " + std::to_string(n_sigmas));

  const double n = static_cast<double>(n_);
  const double tau_global = 1.0 / std::sqrt(2.0 * n);         // tau'
  const double tau_local = 1.0 / std::sqrt(2.0 * std::sqrt(n));  // tau
  const double tau_one = 1.0 / std::sqrt(n);                  // tau0, one step size
  const double max_sigma = kMaxStepSize * (s_.upper - s_.lower);

  const std::size_t mu = parents.size();
  std::vector<Individual> kids(static_cast<std::size_t>(s_.lambda));
  // Draw order per offspring, fixed so a seed fixes the result: mate index; discrete
  // choices gene by gene (then the sigma's source for StepSizes::One); the global normal
  // (PerGene); then for each gene its sigma's normal (PerGene) and its step's normal.
  for (std::size_t k = 0; k < kids.size(); ++k) {
    const Individual& a = parents[k % mu];
    Individual& c = kids[k];
    c.fitness = 0.0;
    switch (s_.recombination) {
      case Recombination::None:
        c.genes = a.genes;
        c.sigmas = a.sigmas;
        break;
      case Recombination::Intermediate: {
        const Individual& b = parents[rng.below(mu)];
        c.genes.resize(n_);
        c.sigmas.resize(n_sigmas);
        for (std::size_t i = 0; i < n_; ++i) c.genes[i] = 0.5 * (a.genes[i] + b.genes[i]);
        // Step sizes recombine by geometric mean: they mutate multiplicatively (log-normal),
        // so averaging their logarithms is the unbiased counterpart of averaging genes.
        for (std::size_t i = 0; i < n_sigmas; ++i)
          c.sigmas[i] = std::sqrt(a.sigmas[i] * b.sigmas[i]);
        break;
      }
      case Recombination::Discrete: {
        const Individual& b = parents[rng.below(mu)];
        c.genes.resize(n_);
        c.sigmas.resize(n_sigmas);
        for (std::size_t i = 0; i < n_; ++i) {
          const Individual& src = rng.below(2) == 0 ? a : b;
          c.genes[i] = src.genes[i];
          if (n_sigmas == n_) c.sigmas[i] = src.sigmas[i];  // the gene keeps its own sigma
        }
        if (n_sigmas == 1) c.sigmas[0] = (rng.below(2) == 0 ? a : b).sigmas[0];
        break;
      }
    }

    // Self-adaptive mutation (Schwefel): step sizes first, then the genes with them.
    if (s_.step_sizes == StepSizes::PerGene) {
      const double global = tau_global * rng.normal();
      for (std::size_t i = 0; i < n_; ++i) {
        double& sigma = c.sigmas[i];
        sigma = std::clamp(sigma * std::exp(global + tau_local * rng.normal()), s_.min_sigma, max_sigma);
        c.genes[i] = reflect(c.genes[i] + sigma * rng.normal(), s_.lower, s_.upper);
      }
    } else {
      double& sigma = c.sigmas[0];
      sigma = std::clamp(sigma * std::exp(tau_one * rng.normal()), s_.min_sigma, max_sigma);
      for (double& g : c.genes) g = reflect(g + sigma * rng.normal(), s_.lower, s_.upper);
    }
  }
  return kids;
}

std::vector<Individual> EvolutionStrategy::select(std::span<const Individual> parents,
                                                  std::span<const Individual> offspring) const {
  const bool plus = s_.selection == Selection::Plus;
  const std::size_t from_parents = plus ? parents.size() : 0;
  const std::size_t candidates = from_parents + offspring.size();
  const auto mu = static_cast<std::size_t>(s_.mu);
  require(candidates >= mu, "select needs at least mu (" + std::to_string(mu) +
                                ") candidates, got " + std::to_string(candidates));

  // Merged order: parents first (plus only), then offspring; the stable sort keeps it
  // among equal fitness, so an older individual wins a tie.
  auto at = [&](std::size_t i) -> const Individual& {
    return i < from_parents ? parents[i] : offspring[i - from_parents];
  };
  std::vector<std::size_t> order(candidates);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return sort_key(at(x).fitness) > sort_key(at(y).fitness);
  });
  std::vector<Individual> next;
  next.reserve(mu);
  for (std::size_t i = 0; i < mu; ++i) next.push_back(at(order[i]));
  return next;
}

}  // namespace esc::evo
