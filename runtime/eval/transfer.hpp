#pragma once
// A controller carried into a new setting (`start from` / `evaluate from experiment X`, the
// paper's generalization study): where it comes from, its fitness there and here, and what
// the end table, summary.json and the report say of it ("lose around 10% of their fitness",
// "lose more than 20% and never recover").
#include <cmath>
#include <optional>
#include <span>
#include <string>

namespace esc::eval {

struct Transfer {
  std::string experiment;               // the origin experiment
  int origin_run = 0;                   // its run (from 0) whose best genome this run took
  double origin_fitness = 0.0;          // that run's best fitness, in the origin experiment
  bool evaluate_only = false;           // `evaluate from`: the genome is only evaluated here
  // The genome's own fitness here: individual 0 of generation 0, which is the stored genome
  // unchanged. Unset until generation 0 is evaluated.
  std::optional<double> fitness_here;
};

// (here - origin) / |origin| in percent; nullopt before generation 0 or for an origin of 0.
[[nodiscard]] inline std::optional<double> change_percent(const Transfer& t) noexcept {
  if (!t.fitness_here || t.origin_fitness == 0.0) return std::nullopt;
  return 100.0 * (*t.fitness_here - t.origin_fitness) / std::abs(t.origin_fitness);
}

// How much of what the genome lost here the run made up by evolving on: (best here - fitness
// here) / (origin - fitness here) in percent, `best_here` the run's best fitness over its
// generations here. 50: "only recover half of it"; 100: back at the origin's level; above:
// past it. nullopt when the run only evaluates, before generation 0, or when the genome lost
// nothing here.
[[nodiscard]] inline std::optional<double> loss_regained_percent(const Transfer& t, double best_here) noexcept {
  if (t.evaluate_only || !t.fitness_here || !(*t.fitness_here < t.origin_fitness)) return std::nullopt;
  return 100.0 * (best_here - *t.fitness_here) / (t.origin_fitness - *t.fitness_here);
}

// The first generation whose best fitness reaches the origin's (`best` per generation, from
// 0); nullopt when none does, or when the run only evaluates.
[[nodiscard]] inline std::optional<int> regained_at(const Transfer& t, std::span<const double> best) noexcept {
  if (t.evaluate_only) return std::nullopt;
  for (std::size_t g = 0; g < best.size(); ++g)
    if (best[g] >= t.origin_fitness) return static_cast<int>(g);
  return std::nullopt;
}

}  // namespace esc::eval
