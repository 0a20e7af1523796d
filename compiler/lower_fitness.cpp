// Fitness functions: `fitness NAME { step: EXPR  stop epoch when EXPR ...  epoch: EXPR
// evaluation: EXPR }` -> eval::FitnessSpec.
#include "compiler/lower_fitness.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "compiler/lower_objectives.hpp"
#include "compiler/names.hpp"

namespace esc::compiler {

namespace {

// An end term (`epoch:` or `evaluation:`), given at most once, with its step aggregates.
void end_term(const std::vector<ast::FitnessTerm>& terms, std::string_view word, ExprScope scope, Sink& sink,
              std::optional<expr::Program>& program, std::vector<expr::StepAggregate>& aggregates,
              std::string& text) {
  for (std::size_t i = 1; i < terms.size(); ++i)
    sink.error(terms[i].where, fmt::format("the fitness already has an `{}:` term", word))
        .notes.emplace_back(terms[0].where, "first given here");
  if (terms.empty() || !terms[0].expr) return;
  scope.use = ExprScope::Use::End;
  scope.step_aggregates = &aggregates;
  program = lower_expr(*terms[0].expr, scope, sink);
  text = terms[0].text;
}

}  // namespace

std::optional<eval::Reduction> lower_over_robots(const std::vector<ast::FitnessOver>& overs, Sink& sink) {
  for (std::size_t i = 1; i < overs.size(); ++i)
    sink.error(overs[i].where, "the reduction over the robots is already given")
        .notes.emplace_back(overs[0].where, "first given here");
  if (overs.empty() || overs[0].what.text.empty() || overs[0].reduce.text.empty()) return eval::Reduction::Mean;
  const ast::FitnessOver& o = overs[0];
  if (o.what.text != "robots") {
    sink.error(o.what.where, fmt::format("`over` reduces a group's terms over its robots, not over `{}`", o.what.text))
        .help.push_back(fmt::format("write `over robots {}`", o.reduce.text));
    return std::nullopt;
  }
  const std::vector<std::string> names(reduction_names().begin(), reduction_names().begin() + 4);
  const auto r = std::find(names.begin(), names.end(), o.reduce.text);
  if (r == names.end()) {
    Diagnostic& diag = sink.error(o.reduce.where, fmt::format("`{}` is not a reduction over the robots", o.reduce.text));
    suggest(diag, o.reduce.text, names, {{}, fmt::format("reductions over the robots: {}", quoted_list(names))});
    return std::nullopt;
  }
  return static_cast<eval::Reduction>(r - names.begin());
}

const std::optional<LoweredFitness>& FitnessLowering::lower(const ast::FitnessDecl& d, const ast::ArenaDecl* arena,
                                                            const ast::ExperimentDecl* experiment,
                                                            const ChoiceNames* choices,
                                                            const Navigation* navigation,
                                                            std::vector<double>* cluster_radii) {
  const Key key{&d, arena, experiment};
  if (auto it = fitnesses_.find(key); it != fitnesses_.end()) return it->second;
  if ((arena != nullptr || experiment != nullptr) && !lower(d)) return fitnesses_[key];   // reported without them
  auto& slot = fitnesses_[key];
  if (d.poisoned) return slot;
  const int errors = sink_.errors();
  LoweredFitness f;
  f.spec.name = d.name.text;
  ExprScope scope;
  scope.use = ExprScope::Use::Step;
  if (arena != nullptr) scope.arena = &arenas_.names(*arena);
  scope.choices = choices;
  scope.navigation = navigation;
  scope.sensor_names = &names_.sensor_names();
  scope.cluster_radii = cluster_radii;
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
  end_term(d.epoch_ends, "epoch", scope, sink_, f.spec.epoch_end, f.spec.epoch_aggregates, f.epoch_text);
  end_term(d.evaluation_ends, "evaluation", scope, sink_, f.spec.evaluation_end, f.spec.evaluation_aggregates,
           f.evaluation_text);
  if (const auto over = lower_over_robots(d.overs, sink_)) {
    f.spec.over_robots = *over;
    // The mean, the default, resolves as a fitness without `over` does.
    if (*over != eval::Reduction::Mean) f.over_text = reduction_names()[static_cast<std::size_t>(*over)];
  }
  if (sink_.errors() == errors) slot = std::move(f);
  return slot;
}

}  // namespace esc::compiler
