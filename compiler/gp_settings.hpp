#pragma once
// The options of `evolve gp(...)` (runtime/evo/gp/gp.hpp's GpSettings): one table for
// scripts, `esc run --set gp.KEY=VALUE`, resolved settings (`gp.KEY`) and the
// documentation; and the check that the settings suit every compared tree controller (the
// GP engine's own).
#include <string>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/option_table.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

using GpOption = OptionRow<evo::gp::GpSettings>;

[[nodiscard]] const std::vector<GpOption>& gp_options();

// `evolve gp(...) [for N generations]` -> x.gp; problems reported.
void lower_gp_item(const ast::ExpItem& item, eval::ExperimentSpec& x, Sink& sink);

// Empty when the GP settings (if any) suit every compared tree controller's primitive set
// (GeneticProgramming accepts them), else the first problem, naming the controller.
[[nodiscard]] std::string check_gp(const eval::ExperimentSpec& spec);

// Writes the `gp.*` keys of resolved_settings (none without GP settings).
void resolve_gp_settings(eval::ExperimentSpec& spec);

}  // namespace esc::compiler
