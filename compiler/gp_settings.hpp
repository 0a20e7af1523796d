#pragma once
// The options of `evolve gp(...)` (runtime/evo/gp/gp.hpp's GpSettings): their names, how
// they are read in a script and in `esc run --set gp.KEY=VALUE`, their resolved-settings
// text, and the check that the settings suit every compared tree controller.
#include <string>
#include <string_view>
#include <vector>

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

// Sets option `o` to `value` (Depths: `value` and `hi`); a message when the value does not
// fit its kind ("`crossover` must be in [0, 1], found 1.5"), else empty.
[[nodiscard]] std::string set_gp_option(evo::gp::GpSettings& s, const GpOption& o, double value, double hi = 0);

// `--set gp.KEY=VALUE`: `key` without the `gp.` prefix, `value` trimmed. An experiment
// without GP settings checks the value and ignores it (dependencies of a GP experiment get
// the same --set).
[[nodiscard]] std::string apply_gp_setting(eval::ExperimentSpec& spec, std::string_view key, std::string_view value);

// Empty when the GP settings (if any) suit every compared tree controller's primitive set
// (GeneticProgramming accepts them), else the first problem, naming the controller.
[[nodiscard]] std::string check_gp(const eval::ExperimentSpec& spec);

// Writes the `gp.*` keys of resolved_settings (none without GP settings).
void resolve_gp_settings(eval::ExperimentSpec& spec);

}  // namespace esc::compiler
