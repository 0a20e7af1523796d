#pragma once
// Lowers `behavior` declarations: a hand-written behavior to control::Behavior (its wheel
// expressions, resolved in an experiment's arena when given), an evolved one
// (`= evolved from experiment E controller C`) to the declarations it names.
#include <map>
#include <optional>
#include <string>
#include <tuple>

#include "compiler/ast.hpp"
#include "compiler/lower_arena.hpp"
#include "compiler/sensor_uses.hpp"
#include "compiler/resolver.hpp"
#include "compiler/sink.hpp"
#include "runtime/control/controller_spec.hpp"

namespace esc::compiler {

// `behavior b = evolved from experiment E controller C`, resolved.
struct EvolvedRef {
  const ast::ExperimentDecl* experiment = nullptr;
  const ast::ControllerDecl* controller = nullptr;
  std::string compared_as;          // the name the experiment compares it under
};

// A library's mark, the word after its name: `useless` or none (reported otherwise).
void check_library_mark(const ast::LibraryDecl& d, Sink& sink);

class BehaviorLowering {
 public:
  BehaviorLowering(Sink& sink, Resolver& names, ArenaLowering& arenas) : sink_(sink), names_(names), arenas_(arenas) {}

  // With an arena, `in(zone)` / `reached(light)` resolve in it, and with `navigation` (the
  // arena's goal and the robot's sensors), `goal_distance`, `range[i]` and `radar[i]` are
  // checked (memoised per behavior, arena and sensor counts; reported once, without the arena,
  // for what does not depend on it). Null for an evolved behavior.
  const std::optional<control::Behavior>& lower(const ast::BehaviorDecl& d, const ast::ArenaDecl* arena = nullptr,
                                                const Navigation* navigation = nullptr);
  // An evolved behavior's experiment and controller (reported once); null when wrong or
  // when `d` is hand-written.
  const std::optional<EvolvedRef>& evolved(const ast::BehaviorDecl& d);

 private:
  Sink& sink_;
  Resolver& names_;
  ArenaLowering& arenas_;
  // (behavior, arena, and what the robot offers: the goal, its sensors' counts and names);
  // -1 counts without navigation. Every count a behavior may read is in it: a behavior bound
  // under one body is not taken for another body's (a group's networks per body).
  using Key = std::tuple<const ast::BehaviorDecl*, const ast::ArenaDecl*, bool, int, int, int, int, int,
                         std::map<std::string, std::string, std::less<>>>;
  std::map<Key, std::optional<control::Behavior>> behaviors_;
  std::map<const ast::BehaviorDecl*, std::optional<EvolvedRef>> evolved_;
};

}  // namespace esc::compiler
