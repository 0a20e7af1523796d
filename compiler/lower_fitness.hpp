#pragma once
// Lowers `fitness` declarations to eval::FitnessSpec: the `step:` term, the stop conditions
// and the end terms (`epoch:`, `evaluation:`), resolved in an experiment's arena and among
// its controllers' choices (`using(B)`, `share(B)`, `count(B)`) when given.
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/lower_arena.hpp"
#include "compiler/lower_expr.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

struct LoweredFitness {
  eval::FitnessSpec spec;
  std::string step_text;                  // source text, for resolved settings
  std::vector<std::string> stop_texts;
  std::string epoch_text, evaluation_text;   // "" when there is no such term
  std::string over_text;                     // `over robots R`'s R; "" when not given (mean)
};

// `over robots R` (a fitness's, a descriptor's; at most one of `overs`): the reduction over a
// group's robots, Mean when none is given; nullopt after reporting a bad one to `sink`.
[[nodiscard]] std::optional<eval::Reduction> lower_over_robots(const std::vector<ast::FitnessOver>& overs, Sink& sink);

class FitnessLowering {
 public:
  FitnessLowering(Sink& sink, Resolver& names, ArenaLowering& arenas) : sink_(sink), names_(names), arenas_(arenas) {}

  // Memoised per (fitness, arena, experiment); what depends on neither is reported once.
  // `experiment` names whose compared controllers `choices` are, whose goal and sensors
  // `navigation` is, and whose clusters' radii `cluster_radii` holds (ExprScope).
  const std::optional<LoweredFitness>& lower(const ast::FitnessDecl& d, const ast::ArenaDecl* arena = nullptr,
                                             const ast::ExperimentDecl* experiment = nullptr,
                                             const ChoiceNames* choices = nullptr,
                                             const Navigation* navigation = nullptr,
                                             std::vector<double>* cluster_radii = nullptr);

 private:
  using Key = std::tuple<const ast::FitnessDecl*, const ast::ArenaDecl*, const ast::ExperimentDecl*>;
  Sink& sink_;
  Resolver& names_;
  ArenaLowering& arenas_;
  std::map<Key, std::optional<LoweredFitness>> fitnesses_;
};

}  // namespace esc::compiler
