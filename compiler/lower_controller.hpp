#pragma once
// Lowers `controller` declarations to control::ControllerSpec: the network (inputs, layers,
// head) or the tree, the actions and supervised behaviors (libraries expanded), and, per
// experiment, the behaviors again in that experiment's arena.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/lower_behavior.hpp"
#include "compiler/lower_primitives.hpp"
#include "compiler/resolver.hpp"
#include "compiler/sensor_uses.hpp"
#include "compiler/sink.hpp"
#include "runtime/control/controller_spec.hpp"

namespace esc::compiler {

// One entry of a supervisor's behavior list, a library expanded into its members.
struct Supervised {
  const ast::SupervisedRef* ref;
  const ast::BehaviorDecl* decl;
};

class ControllerLowering {
 public:
  ControllerLowering(Sink& sink, Resolver& names, BehaviorLowering& behaviors, PrimitivesLowering& primitives)
      : sink_(sink), names_(names), behaviors_(behaviors), primitives_(primitives) {}

  // Memoised; null when the controller (or a controller it supervises) is wrong (reported).
  const std::optional<control::ControllerSpec>& lower(const ast::ControllerDecl& d);
  // A supervisor's behavior list with libraries expanded into their members, in order;
  // entries that fail to resolve are reported (once) and left out.
  const std::vector<Supervised>& supervised(const ast::ControllerDecl& d);
  // Lowers the controller's behaviors (actions, supervised behaviors) again in `arena`, and
  // checks that what it reads (inputs, behaviors, terminals, frozen controllers) has its
  // sensor under `navigation`; false when one fails (reported).
  bool bind(control::ControllerSpec& c, const ast::ControllerDecl& d, const ast::ArenaDecl& arena,
            const Navigation& navigation);
  // A controller per body, compared as `use` in experiment `x` (of robot `robot`, the first
  // body's name): each body of x's group is
  // given its network (ControllerSpec::body_networks), bound under that body's sensors; a body
  // without a network, or a network for a body the group lacks, is an error at `use`.
  bool bind_bodies(control::ControllerSpec& c, const ast::ControllerDecl& d, const ast::ArenaDecl& arena,
                   const eval::ExperimentSpec& x, const std::string& robot, const ast::Name& use);

 private:
  // `per_body(...)`: its networks lowered, each a network controller of one head.
  std::optional<control::ControllerSpec> lower_per_body(const ast::ControllerDecl& d);

  Sink& sink_;
  Resolver& names_;
  BehaviorLowering& behaviors_;
  PrimitivesLowering& primitives_;
  std::map<const ast::ControllerDecl*, std::optional<control::ControllerSpec>> controllers_;
  // The behavior declarations a controller uses, in the order of its actions / behaviors.
  std::map<const ast::ControllerDecl*, std::vector<const ast::BehaviorDecl*>> used_;
  std::map<const ast::ControllerDecl*, std::vector<Supervised>> supervised_;
  // A controller per body's networks' declarations, in its order.
  std::map<const ast::ControllerDecl*, std::vector<const ast::ControllerDecl*>> networks_;
  // The slots each network input reads, [first, first + count), for bind()'s sensor check.
  struct InputSlots {
    const ast::Input* input;
    expr::Slot first, count;
  };
  std::map<const ast::ControllerDecl*, std::vector<InputSlots>> inputs_;
  // Whether a controller's inputs, terminals and frozen controllers have their sensors, per
  // (controller, goal, rangefinders, radars): reported once, not once per experiment.
  using SensorKey = std::tuple<const ast::ControllerDecl*, bool, int, int, int, int, int,
                               std::map<std::string, std::string, std::less<>>>;
  std::map<SensorKey, bool> sensors_ok_;
  bool check_sensors(const control::ControllerSpec& c, const ast::ControllerDecl& d, const Navigation& navigation);
  std::set<const ast::ControllerDecl*> supervised_failed_;
};

}  // namespace esc::compiler
