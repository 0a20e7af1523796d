#pragma once
// The options of `evolve gp(...)` (runtime/evo/gp/gp.hpp's GpSettings): one table for
// scripts, `esc run --set gp.KEY=VALUE`, resolved settings (`gp.KEY`) and the
// documentation; the reading of each option's value, and the check that the settings suit
// every compared tree controller (the GP engine's own).
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

struct GpOption {
  enum class Kind {
    Whole,      // a whole number >= min
    Fraction,   // a probability in [0, 1]
    Plain,      // a plain number >= 0
    Depths,     // `init_depth [LO, HI]`, whole numbers
  };
  std::string_view name;
  Kind kind;
  long long min = 0;                              // Whole
  int evo::gp::GpSettings::*whole = nullptr;      // Whole
  double evo::gp::GpSettings::*real = nullptr;    // Fraction, Plain
};

[[nodiscard]] const std::vector<GpOption>& gp_options();
[[nodiscard]] const GpOption* find_gp_option(std::string_view name);
[[nodiscard]] std::vector<std::string> gp_option_names();

// Reads `v` (a script's value or a `--set gp.KEY=` value) as option `o` into `s`; reports
// at `v` ("`crossover` is a probability in [0, 1], found 1.5").
bool read_gp_option(evo::gp::GpSettings& s, const GpOption& o, const ast::Value& v, Sink& sink);

// `evolve gp(...) [for N generations]` -> x.gp; problems reported.
void lower_gp_item(const ast::ExpItem& item, eval::ExperimentSpec& x, Sink& sink);

// Empty when the GP settings (if any) suit every compared tree controller's primitive set
// (GeneticProgramming accepts them), else the first problem, naming the controller.
[[nodiscard]] std::string check_gp(const eval::ExperimentSpec& spec);

// Writes the `gp.*` keys of resolved_settings (none without GP settings).
void resolve_gp_settings(eval::ExperimentSpec& spec);

}  // namespace esc::compiler
