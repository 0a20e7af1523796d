#pragma once
// A broken runtime rule (sim::Problem, runtime/sim/validate.hpp) in the script's words and
// units: "`ir_aperture` must be below 180deg, found 200deg". The compiler and `--set` phrase
// every problem the validators find here; where it is shown is the caller's business.
#include <string>
#include <string_view>
#include <vector>

#include "runtime/sim/validate.hpp"

namespace esc::compiler {

// What a problem's phrase may mention besides the problem itself.
struct RuleContext {
  const sim::ArenaSpec* arena = nullptr;
  std::string_view arena_name = {};
  const sim::RobotParams* robot = nullptr;
};

struct RuleMessage {
  std::string message;             // one sentence, no trailing period
  std::vector<std::string> help;
};

[[nodiscard]] RuleMessage rule_message(const sim::Problem& p, const RuleContext& context);

// A value in SI shown in the unit a script would use for its dimension ("200deg", "5.5cm",
// "15.6mm", "10000000").
[[nodiscard]] std::string shown(double si, sim::Dimension dimension);

}  // namespace esc::compiler
