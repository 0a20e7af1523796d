#include "runtime/evo/neat/speciation.hpp"

#include <algorithm>
#include <cmath>

namespace esc::evo {

std::size_t find_species(const genome::graph::Graph& g, std::span<const genome::graph::Graph* const> representatives,
                         const genome::graph::Coefficients& c, double threshold) {
  for (std::size_t k = 0; k < representatives.size(); ++k)
    if (genome::graph::compatibility(g, *representatives[k], c) < threshold) return k;
  return representatives.size();
}

Shares share_fitness(std::vector<Species>& species, std::span<const double> fitness, const NeatSettings& s) {
  Shares out;
  out.shared.assign(fitness.size(), 0.0);
  const double lowest = fitness.empty() ? 0.0 : *std::min_element(fitness.begin(), fitness.end());
  const double shift = lowest < 0.0 ? -lowest : 0.0;
  for (Species& sp : species) {
    std::stable_sort(sp.members.begin(), sp.members.end(),
                     [&](std::size_t a, std::size_t b) { return fitness[a] > fitness[b]; });
    int debt = (sp.age - sp.last_improved + 1) - s.dropoff_age;
    if (debt == 0) debt = 1;
    const auto size = static_cast<double>(sp.members.size());
    for (const std::size_t m : sp.members) {
      double f = fitness[m] + shift;
      if (debt >= 1) f *= kStagnantFactor;
      out.shared[m] = f / size;
    }
    if (const double best = fitness[sp.members.front()]; best > sp.best_ever) {
      sp.best_ever = best;
      sp.last_improved = sp.age;
    }
    const auto parents = static_cast<std::size_t>(std::floor(s.survival_thresh * size + 1.0));
    out.parents.push_back(std::min(parents, sp.members.size()));
  }
  return out;
}

std::vector<int> allocate_offspring(const std::vector<Species>& species, std::span<const double> shared,
                                    std::size_t population) {
  double total = 0.0;
  for (const double f : shared) total += f;
  const double mean = total / static_cast<double>(shared.size());
  std::vector<int> offspring(species.size(), 0);
  double skim = 0.0;
  std::size_t expected = 0;
  for (std::size_t k = 0; k < species.size(); ++k) {
    for (const std::size_t m : species[k].members) {
      const double e = mean > 0.0 ? shared[m] / mean : 1.0;
      offspring[k] += static_cast<int>(std::floor(e));
      skim += std::fmod(e, 1.0);
      if (skim > 1.0) {
        const double whole = std::floor(skim);
        offspring[k] += static_cast<int>(whole);
        skim -= whole;
      }
    }
    expected += static_cast<std::size_t>(offspring[k]);
  }
  if (expected < population && !species.empty()) {
    std::size_t best = 0;
    int most = 0;
    for (std::size_t k = 0; k < species.size(); ++k)
      if (offspring[k] >= most) {
        most = offspring[k];
        best = k;
      }
    ++offspring[best];
    if (expected + 1 < population) {
      std::fill(offspring.begin(), offspring.end(), 0);
      offspring[best] = static_cast<int>(population);
    }
  }
  return offspring;
}

}  // namespace esc::evo
