// Behaviors: `behavior NAME(P, ...) { wheels(LEFT, RIGHT) }` -> control::Behavior, and
// `behavior NAME = evolved from experiment E controller C` -> the declarations it names.
#include "compiler/lower_behavior.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "compiler/lower_expr.hpp"
#include "compiler/names.hpp"

namespace esc::compiler {

void check_library_mark(const ast::LibraryDecl& d, Sink& sink) {
  if (d.poisoned || !d.mark || d.mark->text == "useless") return;
  suggest(sink.error(d.mark->where, fmt::format("unknown mark `{}` for library `{}`", d.mark->text, d.name.text)),
          d.mark->text, {"useless"},
          {.otherwise = "a library may be marked `useless` (`library distractors useless { ... }`): reports draw its "
                        "behaviors apart from the useful ones",
           .always = true});
}

const std::optional<EvolvedRef>& BehaviorLowering::evolved(const ast::BehaviorDecl& d) {
  if (auto it = evolved_.find(&d); it != evolved_.end()) return it->second;
  auto& slot = evolved_[&d];
  if (d.poisoned || !d.evolved) return slot;
  const auto* xd = names_.lookup<ast::ExperimentDecl>(d.from_experiment);
  if (xd == nullptr) return slot;
  // Found by the name it is compared under (`compare CS8 as CS`: `CS`).
  std::vector<std::string> names;
  const ast::Name* declared = nullptr;
  for (const ast::Compared& c : ast::compared(*xd)) {
    names.push_back(c.name->text);
    if (c.name->text == d.from_controller.text) declared = c.controller;
  }
  if (d.from_controller.text.empty()) return slot;
  if (declared == nullptr) {
    Diagnostic& diag = sink_.error(d.from_controller.where,
                                   fmt::format("experiment `{}` does not compare a controller `{}`",
                                               d.from_experiment.text, d.from_controller.text));
    diag.notes.emplace_back(xd->name.where, fmt::format("`{}` is declared here", d.from_experiment.text));
    if (!names.empty())
      suggest(diag, d.from_controller.text, names,
              {.otherwise = fmt::format("`{}` compares {}", d.from_experiment.text, quoted_list(names, ", "))});
    return slot;
  }
  if (const auto* cd = names_.lookup<ast::ControllerDecl>(*declared)) slot = EvolvedRef{xd, cd, d.from_controller.text};
  return slot;
}

const std::optional<control::Behavior>& BehaviorLowering::lower(const ast::BehaviorDecl& d,
                                                                const ast::ArenaDecl* arena,
                                                                const Navigation* navigation) {
  const Key key = navigation == nullptr
                      ? Key{&d, arena, false, -1, -1, -1, -1, -1, {}}
                      : Key{&d, arena, navigation->goal, navigation->rangefinders, navigation->radars,
                            navigation->ir_sensors, navigation->ground_sensors, navigation->bumpers, navigation->names};
  if (auto it = behaviors_.find(key); it != behaviors_.end()) return it->second;
  // What fails without the arena, or in the arena whatever the robot, is reported there once:
  // only what a body's sensors decide is reported per body.
  if (arena != nullptr && !lower(d)) return behaviors_[key];
  if (navigation != nullptr && arena != nullptr && !lower(d, arena)) return behaviors_[key];
  auto& slot = behaviors_[key];
  if (d.poisoned) return slot;
  if (d.evolved) {   // not a hand-written behavior: see evolved()
    (void)evolved(d);
    return slot;
  }
  const int errors = sink_.errors();
  control::Behavior b;
  b.name = d.name.text;
  ExprScope scope;
  if (arena != nullptr) scope.arena = &arenas_.names(*arena);
  scope.navigation = navigation;
  scope.sensor_names = &names_.sensor_names();
  for (const ast::Name& p : d.params) {
    if (std::find(scope.params.begin(), scope.params.end(), p.text) != scope.params.end()) {
      if (arena == nullptr) sink_.error(p.where, fmt::format("parameter `{}` is listed twice", p.text));
      continue;
    }
    scope.params.push_back(p.text);
  }
  if (d.params.size() > expr::kMaxParams && arena == nullptr)
    sink_.error(d.params[expr::kMaxParams].where,
                fmt::format("a behavior takes at most {} parameters, `{}` has {}", expr::kMaxParams, d.name.text,
                            d.params.size()));
  if (d.body_fn.text != "wheels") {
    suggest(sink_.error(d.body_fn.where, fmt::format("unknown command `{}`", d.body_fn.text)), d.body_fn.text,
            {"wheels"},
            {.otherwise = "a behavior's body is `wheels(left, right)`, two wheel commands in [-1, 1]", .always = true});
  } else if (d.body_args.size() != 2) {
    sink_.error(d.body_where, fmt::format("`wheels` takes 2 arguments (left, right), found {}", d.body_args.size()));
  } else if (sink_.errors() == errors) {
    auto l = lower_expr(*d.body_args[0], scope, sink_);
    auto r = lower_expr(*d.body_args[1], scope, sink_);
    if (l && r) {
      b.left = std::move(*l);
      b.right = std::move(*r);
    }
  }
  for (const std::string& p : scope.params) b.params.push_back(p);
  if (sink_.errors() == errors) slot = std::move(b);
  return slot;
}

}  // namespace esc::compiler
