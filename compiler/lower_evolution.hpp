#pragma once
// Which algorithm evolves which compared controller: `evolve NAME(...)` items
// (algorithm_options.hpp), `by NAME` in `compare`, and the checks that tie them together (an
// algorithm that cannot evolve the controller it is given, an `evolve` that evolves nothing,
// settings that do not suit a controller's network, tree operators that do not suit a tree).
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::compiler {

// The `evolve` items of one experiment, by algorithm.
struct EvolveItems {
  std::map<std::string, const ast::ExpItem*> given;
  std::vector<std::string> order;   // as written

  // `evolve NAME(...)`, or null.
  [[nodiscard]] const ast::ExpItem* of(const std::string& name) const {
    const auto it = given.find(name);
    return it == given.end() ? nullptr : it->second;
  }
};

// Every algorithm a script can name, for messages: `es`, `gp`, `cmaes`, ...
[[nodiscard]] std::vector<std::string> algorithm_names();
// Those that evolve genomes of `kind` (networks' weights, trees, graphs).
[[nodiscard]] std::vector<std::string> algorithms_for(genome::GenomeKind kind);
// The kind of genome controller `c` evolves.
[[nodiscard]] genome::GenomeKind genome_kind(const control::ControllerSpec& c) noexcept;

// Whether algorithm `name` evolves one of x's compared controllers (none when x only
// evaluates stored ones).
[[nodiscard]] bool in_use(const eval::ExperimentSpec& x, std::string_view name);

// Whether `item` is `evolve NAME(...)` of a registered algorithm.
[[nodiscard]] bool is_algorithm_evolve(const ast::ExpItem& item);

// `evolve NAME(...)` into x.algorithm_settings[NAME] (its `for N generations` into the
// experiment's generations, or GP's own); a second one of the same name reported.
void lower_evolve(const ast::ExpItem& item, eval::ExperimentSpec& x, EvolveItems& items, Sink& sink);

// Chooses the algorithm of every compared controller (ControllerSpec::evolved_by from `by`,
// x.networks from the `evolve` items) and reports what does not fit; `compared[i]` and `by[i]` are the
// names `compare` wrote for x.controllers[i] (`by[i]` empty text when none).
void choose_algorithms(const ast::ExperimentDecl& d, eval::ExperimentSpec& x,
                       const std::vector<const ast::Name*>& compared, const std::vector<const ast::Name*>& by,
                       const EvolveItems& items, Sink& sink);

// Problems of the settings of the algorithms that evolve x's controllers (of `algorithm`
// alone when given), reported at `where`: the first for each call, since the controllers an
// algorithm evolves share its settings. The tree operators are check_tree_operators's.
void check_algorithm_settings(const eval::ExperimentSpec& x, const SourceRange& where, Sink& sink,
                              std::string_view algorithm = {});

// Empty when the tree operators (GP's settings, if any) suit every compared tree
// controller's primitive set, whichever algorithm selects it, else the first problem,
// naming the controller.
[[nodiscard]] std::string check_tree_operators(const eval::ExperimentSpec& x);

}  // namespace esc::compiler
