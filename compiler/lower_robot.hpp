#pragma once
// Lowers `robot` declarations (and an experiment's inline robot settings) to
// sim::RobotParams, remembering where the script set each setting, so that a broken
// runtime rule (sim::robot_problems) is reported at the setting that broke it.
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/resolver.hpp"
#include "compiler/sink.hpp"
#include "runtime/sim/robot_params.hpp"

namespace esc::compiler {

struct LoweredRobot {
  sim::RobotParams params;
  struct Written {
    SourceRange where;   // the value
    int order;           // later settings have larger orders
    std::vector<SourceRange> items;   // a list of tuples': each tuple, where a problem names one
  };
  std::map<std::string_view, Written> written;   // by setting keyword: where the script last set it
};

class RobotLowering {
 public:
  RobotLowering(Sink& sink, Resolver& names) : sink_(sink), names_(names) {}

  // Memoised; null when the robot (or one it derives from) is wrong (reported).
  const std::optional<LoweredRobot>& lower(const ast::RobotDecl& d);
  // Applies a block of settings in order; false when one is wrong (reported).
  bool apply(LoweredRobot& robot, const std::vector<ast::Setting>& settings);
  // Reports every broken runtime rule at the setting the script wrote last among those the
  // rule reads, or at `fallback` when it wrote none; false when any.
  bool check(const LoweredRobot& robot, const SourceRange& fallback);

 private:
  Sink& sink_;
  Resolver& names_;
  std::map<const ast::RobotDecl*, std::optional<LoweredRobot>> robots_;
  std::set<const ast::RobotDecl*> in_progress_;
  int order_ = 0;
};

}  // namespace esc::compiler
