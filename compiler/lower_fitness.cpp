// Fitness functions: `fitness NAME { step: EXPR  stop epoch when EXPR ... }` -> eval::FitnessSpec.
#include "compiler/lower_fitness.hpp"

#include <fmt/format.h>

#include "compiler/lower_expr.hpp"

namespace esc::compiler {

const std::optional<LoweredFitness>& FitnessLowering::lower(const ast::FitnessDecl& d, const ast::ArenaDecl* arena) {
  const auto key = std::pair{&d, arena};
  if (auto it = fitnesses_.find(key); it != fitnesses_.end()) return it->second;
  if (arena != nullptr && !lower(d)) return fitnesses_[key];   // reported without the arena
  auto& slot = fitnesses_[key];
  if (d.poisoned) return slot;
  const int errors = sink_.errors();
  LoweredFitness f;
  f.spec.name = d.name.text;
  ExprScope scope;
  if (arena != nullptr) scope.arena = &arenas_.names(*arena);
  if (d.steps.empty())
    sink_.error(d.name.where, fmt::format("fitness `{}` has no `step:` term", d.name.text))
        .help.push_back("add `step: forward_speed`, the value added up at every control step");
  for (std::size_t i = 1; i < d.steps.size(); ++i)
    sink_.error(d.steps[i].where, "the fitness already has a `step:` term")
        .notes.emplace_back(d.steps[0].where, "first given here");
  if (!d.steps.empty() && d.steps[0].expr) {
    if (auto p = lower_expr(*d.steps[0].expr, scope, sink_)) f.spec.step = std::move(*p);
    f.step_text = d.steps[0].text;
  }
  for (const ast::FitnessTerm& s : d.stops) {
    if (!s.expr) continue;
    if (auto p = lower_expr(*s.expr, scope, sink_)) f.spec.stop_when.push_back(std::move(*p));
    f.stop_texts.push_back(s.text);
  }
  if (sink_.errors() == errors) slot = std::move(f);
  return slot;
}

}  // namespace esc::compiler
