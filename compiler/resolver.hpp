#pragma once
// Names of a compilation: one namespace of declarations over every loaded file, each name
// bound to its declaration (typed: a variant of declaration pointers); lookup with kind
// checks and "did you mean"; and the cycles of a dependency graph between declarations.
// Lowering (lower_*.cpp) asks the resolver for declarations and never sees an untyped one.
#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"

namespace esc::compiler {

using Decl = std::variant<const ast::ArenaDecl*, const ast::RobotDecl*, const ast::BehaviorDecl*,
                          const ast::FitnessDecl*, const ast::ControllerDecl*, const ast::ExperimentDecl*,
                          const ast::LibraryDecl*, const ast::PrimitivesDecl*, const ast::StudyDecl*>;

// "arena", "robot", ..., "primitive set": the kind of the declaration `d` holds.
[[nodiscard]] std::string_view kind_name(const Decl& d) noexcept;
[[nodiscard]] const ast::DeclHead& head(const Decl& d) noexcept;

// Every name a script may read a renamable sensor array by (robot_settings.hpp), each with the
// observable it reads: `ir` -> `ir`, `prox` -> `ir`, `prox_ground` -> `ground_sensor`.
using SensorNames = std::map<std::string, std::string, std::less<>>;

class Resolver {
 public:
  explicit Resolver(Sink& sink) : sink_(sink) {}

  // Registers the module's names in source order; reports a name declared twice.
  void declare(const ast::Module& m);
  // Every declared module, in the order declared.
  [[nodiscard]] const std::vector<const ast::Module*>& modules() const noexcept { return modules_; }
  // The names the declared robots read their renamable sensors by: `ir` and `ground_sensor`,
  // and every `ir_name` and `ground_name` written in a robot block (`prox`), so that a
  // controller resolves its inputs before an experiment binds it to a robot (sensor_uses.hpp
  // checks the robot's own name then).
  [[nodiscard]] const SensorNames& sensor_names();

  // The D named by `ref`. Reports an unknown name (with "did you mean" among the D's) and a
  // name of another kind; null then, and also, silently, when the D holds a syntax error.
  template <class D>
  [[nodiscard]] const D* lookup(const ast::Name& ref) {
    const Decl* d = lookup(ref, Decl(static_cast<const D*>(nullptr)));
    return d == nullptr ? nullptr : std::get<const D*>(*d);
  }
  // The D called `name`, or null (unknown, or another kind); never reports.
  template <class D>
  [[nodiscard]] const D* find(std::string_view name) const {
    const auto it = symbols_.find(std::string(name));
    if (it == symbols_.end()) return nullptr;
    const D* const* d = std::get_if<const D*>(&it->second);
    return d == nullptr ? nullptr : *d;
  }

 private:
  // `want` holds a null pointer of the wanted kind.
  const Decl* lookup(const ast::Name& ref, const Decl& want);
  void add(const Decl& d);

  Sink& sink_;
  std::optional<SensorNames> sensor_names_;          // of the modules declared so far
  std::set<const ast::Setting*> clashes_reported_;   // sensor names given to a second array
  std::map<std::string, Decl> symbols_;
  std::vector<const ast::Module*> modules_;
};

// A dependency between declarations of one kind: the user depends on `to`, which it names at
// `via`.
template <class D>
struct Dependency {
  const D* to;
  const ast::Name* via;
};

// Walks the graph depth-first from each node in turn and calls `report` once for each cycle
// (once per set of members): the cycle's path from its first member back to it, and the edge
// that closes it.
template <class D>
void for_each_cycle(
    const std::vector<const D*>& nodes, std::map<const D*, std::vector<Dependency<D>>>& edges,
    const std::function<void(const std::vector<const D*>& path, const Dependency<D>& closing)>& report) {
  std::map<const D*, int> state;   // 0 new, 1 on the stack, 2 done
  std::vector<const D*> stack;
  std::vector<std::vector<const D*>> reported;   // sorted member lists
  std::function<void(const D*)> visit = [&](const D* x) {
    state[x] = 1;
    stack.push_back(x);
    for (const Dependency<D>& e : edges[x]) {
      if (state[e.to] == 1) {
        const auto from = std::find(stack.begin(), stack.end(), e.to);
        std::vector<const D*> members(from, stack.end());
        std::sort(members.begin(), members.end(), std::less<>());
        if (std::find(reported.begin(), reported.end(), members) != reported.end()) continue;
        reported.push_back(members);
        report(std::vector<const D*>(from, stack.end()), e);
      } else if (state[e.to] == 0 && stack.size() < 1000) {
        visit(e.to);
      }
    }
    stack.pop_back();
    state[x] = 2;
  };
  for (const D* x : nodes)
    if (state[x] == 0) visit(x);
}

}  // namespace esc::compiler
