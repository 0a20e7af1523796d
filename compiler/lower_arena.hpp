#pragma once
// Lowers `arena` declarations to sim::ArenaSpec: reads every item, asks the runtime's rules
// (sim::arena_problems) and reports each broken one at the item that broke it; and, per
// experiment, the rules of a robot in the arena (it fits, a fixed start is clear).
#include <map>
#include <optional>

#include "compiler/ast.hpp"
#include "compiler/lower_expr.hpp"
#include "compiler/sink.hpp"
#include "runtime/sim/arena.hpp"
#include "runtime/sim/robot_params.hpp"
#include "runtime/sim/validate.hpp"

namespace esc::compiler {

// An arena as lowered, with the item each of its parts comes from (in the spec's order).
struct LoweredArena {
  sim::ArenaSpec spec;
  std::vector<const ast::Block*> blocks;
  std::vector<const ast::Cylinder*> cylinders;
  std::vector<const ast::Wall*> walls;
  std::vector<const ast::Zone*> zones;
  std::vector<const ast::Light*> lights;
};

class ArenaLowering {
 public:
  explicit ArenaLowering(Sink& sink) : sink_(sink) {}

  // Memoised: an arena used by several experiments is reported once. Null when it is wrong.
  const std::optional<LoweredArena>& lower(const ast::ArenaDecl& d);
  // The names `in(zone)` and `reached(light)` resolve against.
  const ArenaNames& names(const ast::ArenaDecl& d);
  // The robot fits the arena and a fixed start keeps it clear of walls and obstacles;
  // reported at the start, or at `use` (where the experiment names the arena or robot).
  bool check_placement(const ast::ArenaDecl& d, const LoweredArena& a, const sim::RobotParams& robot,
                       const SourceRange& use);

 private:
  // Where in `d` the part a problem is about was written.
  static SourceRange where(const ast::ArenaDecl& d, const LoweredArena& a, const sim::Problem& p);
  void read_obstacles(const ast::ArenaDecl& d, LoweredArena& a);
  void read_goal(const ast::ArenaDecl& d, LoweredArena& a);
  void read_zones(const ast::ArenaDecl& d, LoweredArena& a, std::map<std::string, std::size_t>& zone_index);
  void read_lights(const ast::ArenaDecl& d, LoweredArena& a, const std::map<std::string, std::size_t>& zone_index);

  Sink& sink_;
  std::map<const ast::ArenaDecl*, std::optional<LoweredArena>> arenas_;
  std::map<const ast::ArenaDecl*, ArenaNames> names_;
};

}  // namespace esc::compiler
