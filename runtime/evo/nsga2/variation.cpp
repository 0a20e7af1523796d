#include "runtime/evo/nsga2/variation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace esc::evo {

namespace {

std::vector<std::size_t> shuffled(std::size_t n, Rng& rng) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  for (std::size_t i = 0; i + 1 < n; ++i) std::swap(order[i], order[i + rng.below(n - i)]);
  return order;
}

// SBX's spread factor for the uniform u, bounded by beta (Deb's code, DEAP).
double spread(double u, double beta, double eta) {
  const double alpha = 2.0 - std::pow(beta, -(eta + 1.0));
  const double e = 1.0 / (eta + 1.0);
  return u <= 1.0 / alpha ? std::pow(u * alpha, e) : std::pow(1.0 / (2.0 - u * alpha), e);
}

}  // namespace

std::vector<std::size_t> crowded_tournament_winners(const Ranking& r, Rng& rng) {
  const std::size_t n = r.rank.size();
  std::vector<std::size_t> players = shuffled(n, rng);
  const std::vector<std::size_t> second = shuffled(n, rng);
  players.insert(players.end(), second.begin(), second.end());
  std::vector<std::size_t> winners(n);
  for (std::size_t t = 0; t < n; ++t) winners[t] = crowded_tournament(r, players[2 * t], players[2 * t + 1]);
  return winners;
}

void simulated_binary_crossover(std::span<double> a, std::span<double> b, double eta, double lower, double upper,
                                Rng& rng) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (rng.uniform() >= 0.5) continue;
    const double y1 = std::min(a[i], b[i]);
    const double y2 = std::max(a[i], b[i]);
    const double gap = y2 - y1;
    if (!(gap > kSbxMinGap * (upper - lower))) continue;
    const double u = rng.uniform();
    const double low = 0.5 * (y1 + y2 - spread(u, 1.0 + 2.0 * (y1 - lower) / gap, eta) * gap);
    const double high = 0.5 * (y1 + y2 + spread(u, 1.0 + 2.0 * (upper - y2) / gap, eta) * gap);
    const double c1 = std::clamp(low, lower, upper);
    const double c2 = std::clamp(high, lower, upper);
    const bool swap = rng.uniform() < 0.5;
    a[i] = swap ? c2 : c1;
    b[i] = swap ? c1 : c2;
  }
}

void polynomial_mutation(std::span<double> x, double eta, double probability, double lower, double upper, Rng& rng) {
  const double width = upper - lower;
  const double e = eta + 1.0;
  for (double& gene : x) {
    if (rng.uniform() >= probability) continue;
    const double u = rng.uniform();
    double step = 0.0;
    if (u < 0.5) {
      const double reach = 1.0 - (gene - lower) / width;  // 1 - delta_1
      step = std::pow(2.0 * u + (1.0 - 2.0 * u) * std::pow(reach, e), 1.0 / e) - 1.0;
    } else {
      const double reach = 1.0 - (upper - gene) / width;  // 1 - delta_2
      step = 1.0 - std::pow(2.0 * (1.0 - u) + 2.0 * (u - 0.5) * std::pow(reach, e), 1.0 / e);
    }
    gene = std::clamp(gene + step * width, lower, upper);
  }
}

}  // namespace esc::evo
