#pragma once
// The checked model of a compilation: one global namespace of declarations over every
// loaded file, and the lowering of each declaration to its runtime object (memoised, so a
// declaration used by several experiments is checked and reported once).
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/lower_expr.hpp"
#include "compiler/sink.hpp"
#include "runtime/control/controller_spec.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

enum class DeclKind { Arena, Robot, Behavior, Fitness, Controller, Experiment, Library, Primitives };
[[nodiscard]] std::string_view kind_name(DeclKind k) noexcept;

struct Symbol {
  DeclKind kind;
  const ast::DeclHead* head;
  const void* decl;
};

struct FitnessResult {
  eval::FitnessSpec spec;
  std::string step_text;
  std::vector<std::string> stop_texts;
};

class Model {
 public:
  explicit Model(Sink& sink) : sink_(sink) {}

  void declare(const ast::Module& m);       // registers names; reports duplicates
  void check_all();                          // lowers every declaration once
  // The main file's experiments; `all`, when given, receives every experiment of every file.
  [[nodiscard]] std::vector<eval::ExperimentSpec> experiments(const ast::Module& main,
                                                              std::vector<eval::ExperimentSpec>* all = nullptr);

 private:
  // Looks `ref` up as a `want`; reports unknown names and wrong kinds. Null when it fails
  // (also, silently, when the target holds a syntax error).
  const Symbol* lookup(const ast::Name& ref, DeclKind want);
  void add(DeclKind k, const ast::DeclHead& h, const void* d);

  const std::optional<sim::ArenaSpec>& arena(const ast::ArenaDecl& d);
  const std::optional<sim::KheperaParams>& robot(const ast::RobotDecl& d);
  // With an arena, `in(zone)` / `reached(light)` resolve in it (memoised per pair).
  const std::optional<control::Behavior>& behavior(const ast::BehaviorDecl& d, const ast::ArenaDecl* arena = nullptr);
  const std::optional<FitnessResult>& fitness(const ast::FitnessDecl& d, const ast::ArenaDecl* arena = nullptr);
  const ArenaNames& arena_names(const ast::ArenaDecl& d);
  // Lowers the controller's behaviors (actions, supervised behaviors) again in `arena`;
  // false when one fails (reported).
  bool bind_behaviors(control::ControllerSpec& c, const ast::ControllerDecl& d, const ast::ArenaDecl& arena);
  const std::optional<control::ControllerSpec>& controller(const ast::ControllerDecl& d);
  std::optional<eval::ExperimentSpec> experiment(const ast::ExperimentDecl& d);
  // `start from` / `evaluate from experiment E`: E compares every controller compared
  // here, and an evaluation evolves nothing (reported).
  void check_start_from(const ast::ExperimentDecl& from,
                        const std::map<ast::ExpItem::Kind, const ast::ExpItem*>& first);

  // A supervisor's behavior list with libraries expanded into their members, in order;
  // entries that fail to resolve are reported (once) and left out.
  struct Supervised {
    const ast::SupervisedRef* ref;
    const ast::BehaviorDecl* decl;
  };
  const std::vector<Supervised>& supervised(const ast::ControllerDecl& d);

  // ---- genetic programming (check_gp.cpp) ----
  // A `primitives` declaration: its functions and terminals, without what a tree's result
  // adds (wheels, the actions, the behaviors, if-then-else over the result).
  struct PrimitiveList {
    std::vector<evo::gp::Primitive> items;
    bool branches = false;            // `if` is listed
  };
  const std::optional<PrimitiveList>& primitives(const ast::PrimitivesDecl& d);
  // Gives `c` (its head, actions and behaviors lowered) the primitive set of `tree(...)`;
  // false when that fails (reported).
  bool lower_tree(const ast::ControllerDecl& d, control::ControllerSpec& c);
  // `evolve gp(...) [for N generations]` -> x.gp (problems reported).
  void lower_gp(const ast::ExpItem& item, eval::ExperimentSpec& x);
  // Every compared controller has its algorithm (`es` for networks, `gp` for trees), and
  // the GP settings suit every tree's primitives (reported at `compared` / `gp_item`).
  void check_algorithms(const ast::ExperimentDecl& d, const eval::ExperimentSpec& x,
                        const std::vector<const ast::Name*>& compared, const ast::ExpItem* es_item,
                        const ast::ExpItem* gp_item);
  std::map<const void*, std::optional<PrimitiveList>> primitive_lists_;
  std::set<std::string> reported_sets_;   // unbuildable (set, root) pairs already reported

  // `behavior b = evolved from experiment E controller C`, resolved (reported once).
  struct EvolvedRef {
    const ast::ExperimentDecl* experiment = nullptr;
    const ast::ControllerDecl* controller = nullptr;
  };
  const std::optional<EvolvedRef>& evolved(const ast::BehaviorDecl& d);
  // Reports every cycle of experiments that use each other's evolved controllers.
  void check_dependency_cycles();

  // Applies `robot { ... }` settings in order; false when one is wrong (reported).
  bool apply_settings(sim::KheperaParams& p, const std::vector<ast::Setting>& settings);
  // Checks that the robot fits the arena and a fixed start pose is clear (reported).
  bool check_fit(const ast::ArenaDecl& a, const sim::ArenaSpec& arena, const sim::KheperaParams& robot,
                 const SourceRange& use);

  Sink& sink_;
  std::map<std::string, Symbol> symbols_;
  std::vector<const ast::Module*> modules_;
  std::map<const void*, std::optional<sim::ArenaSpec>> arenas_;
  std::map<const void*, std::optional<sim::KheperaParams>> robots_;
  std::set<const void*> robots_in_progress_;
  using Key = std::pair<const void*, const void*>;   // declaration, arena (or null)
  std::map<Key, std::optional<control::Behavior>> behaviors_;
  std::map<Key, std::optional<FitnessResult>> fitnesses_;
  std::map<const void*, ArenaNames> arena_names_;
  // The behavior declarations a controller uses, in the order of its actions / behaviors.
  std::map<const void*, std::vector<const ast::BehaviorDecl*>> controller_behaviors_;
  std::map<const void*, std::optional<control::ControllerSpec>> controllers_;
  std::map<const void*, std::optional<eval::ExperimentSpec>> experiments_;
  std::map<const void*, std::string> robot_names_;
  std::map<const void*, std::optional<EvolvedRef>> evolved_;
  std::map<const void*, std::vector<Supervised>> supervised_;
  std::set<const void*> supervised_failed_;
};

}  // namespace esc::compiler
