#pragma once
// Lowers `experiment` declarations to eval::ExperimentSpec: every item (arena, robot and its
// inline settings, fitness, epochs, steps, runs, seed, `evolve`, `compare`,
// `start/evaluate from`), the checks that involve several declarations (the robot in the
// arena, which algorithm evolves which controller, stored controllers to start from), the
// dependencies on other experiments' evolved controllers and their cycles.
#include <map>
#include <optional>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/lower_arena.hpp"
#include "compiler/lower_behavior.hpp"
#include "compiler/lower_controller.hpp"
#include "compiler/lower_evolution.hpp"
#include "compiler/lower_fitness.hpp"
#include "compiler/lower_robot.hpp"
#include "compiler/robot_settings.hpp"
#include "compiler/resolver.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

// The lowering of every other kind of declaration, which an experiment puts together.
struct Lowerings {
  ArenaLowering& arenas;
  RobotLowering& robots;
  BehaviorLowering& behaviors;
  FitnessLowering& fitnesses;
  ControllerLowering& controllers;
};

class ExperimentLowering {
 public:
  ExperimentLowering(Sink& sink, Resolver& names, const Lowerings& parts) : sink_(sink), names_(names), parts_(parts) {}

  // Memoised; nullopt when the experiment is wrong (reported).
  const std::optional<eval::ExperimentSpec>& lower(const ast::ExperimentDecl& d);
  // Reports every cycle of experiments that use each other's evolved controllers or start
  // from each other.
  void check_cycles();

 private:
  using Items = std::map<ast::ExpItem::Kind, const ast::ExpItem*>;
  // `start from` / `evaluate from experiment E`: E compares every controller compared
  // here, and an evaluation evolves nothing, by any algorithm (reported).
  void check_start_from(const ast::ExperimentDecl& from, const Items& first, const EvolveItems& evolves);
  // `formation ...`: where the group's robots start, read by the formation's setting rows.
  bool lower_formation(const ast::ExpItem& item, eval::ExperimentSpec& x);
  // A further body of a group that reads other sensors than the first (group_difference):
  // refused unless every compared controller has a network per body.
  struct SensorDifference {
    const ast::Name* body;
    BodyDifference difference;
    std::optional<SourceRange> set_at;   // where the further body's setting is written
    std::string first;           // the first body's name
    const ast::Name* plain = nullptr;   // a compared controller that is one network, once known
  };
  // `robot khepera x 2, lit_khepera x 3`: the group's bodies after the first (`first`, its
  // robots counted already), each with the first's drive and step (group_difference), and
  // their robots. The first body that reads other sensors is left in `sensors`.
  bool lower_bodies(const ast::ExpItem& item, const sim::RobotParams& first, eval::ExperimentSpec& x,
                    std::optional<SensorDifference>& sensors);
  void report_sensor_difference(const SensorDifference& s);
  // Gives each distinct action or behavior of the compared controllers an experiment-wide id
  // (control::Choice::id; x.choice_ids of them) and returns the names that read them.
  static ChoiceNames number_choices(eval::ExperimentSpec& x);
  // The evolved controllers the compared controllers supervise: which experiment's
  // controller fills which supervised behavior.
  void add_dependencies(eval::ExperimentSpec& x, const std::vector<const ast::ControllerDecl*>& compared);

  Sink& sink_;
  Resolver& names_;
  Lowerings parts_;
  std::map<const ast::ExperimentDecl*, std::optional<eval::ExperimentSpec>> experiments_;
};

}  // namespace esc::compiler
