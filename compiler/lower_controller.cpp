// Controllers: `controller NAME = mlp(...) | elman(...) | neat(...) | symbolic(...) |
// supervisor(...) | tree(...)` -> control::ControllerSpec.
#include "compiler/lower_controller.hpp"

#include <algorithm>
#include <memory>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "runtime/genome/tree/primitive_set.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::compiler {

const std::vector<Supervised>& ControllerLowering::supervised(const ast::ControllerDecl& d) {
  if (auto it = supervised_.find(&d); it != supervised_.end()) return it->second;
  auto& out = supervised_[&d];
  for (const ast::SupervisedRef& r : d.behaviors) {
    if (const auto* lib = names_.find<ast::LibraryDecl>(r.name.text)) {
      if (!r.args.empty()) {
        sink_.error(r.where, fmt::format("`{}` is a library and takes no arguments", r.name.text))
            .notes.emplace_back(lib->name.where, fmt::format("`{}` is declared here", r.name.text));
        supervised_failed_.insert(&d);
        continue;
      }
      if (lib->poisoned) {
        supervised_failed_.insert(&d);
        continue;
      }
      if (lib->members.empty())
        sink_.error(r.where, fmt::format("library `{}` has no behaviors", r.name.text))
            .notes.emplace_back(lib->name.where, fmt::format("`{}` is declared here", r.name.text));
      for (const std::string& m : lib->members) {
        const auto* member = names_.find<ast::BehaviorDecl>(m);
        if (member == nullptr || member->poisoned) {
          supervised_failed_.insert(&d);
          continue;
        }
        out.push_back({&r, member});
      }
      continue;
    }
    const auto* bd = names_.lookup<ast::BehaviorDecl>(r.name);
    if (bd == nullptr) {
      supervised_failed_.insert(&d);
      continue;
    }
    out.push_back({&r, bd});
  }
  return out;
}

const std::optional<control::ControllerSpec>& ControllerLowering::lower(const ast::ControllerDecl& d) {
  if (auto it = controllers_.find(&d); it != controllers_.end()) return it->second;
  auto& slot = controllers_[&d];
  if (d.poisoned) return slot;
  if (!d.per_body.empty()) {
    // Lowering the networks may add entries: `slot` is looked up again.
    auto c = lower_per_body(d);
    return controllers_[&d] = std::move(c);
  }
  const int errors = sink_.errors();
  control::ControllerSpec c;
  c.name = d.name.text;
  c.head = d.supervisor ? control::Head::Supervisor : d.symbolic ? control::Head::Symbolic : control::Head::Classical;
  c.mlp.kind = d.elman  ? control::NetworkKind::Elman
               : d.neat ? control::NetworkKind::Graph
                        : control::NetworkKind::Mlp;
  const bool chooses = d.symbolic || d.supervisor;   // no `wheels` output
  auto& used = used_[&d];
  used.clear();

  const std::vector<std::string> observables = expr::observable_names();
  auto& spans = inputs_[&d];
  spans.clear();
  for (const ast::Input& in : d.inputs) {
    const auto o = find_observable(in.name.text, &names_.sensor_names());
    if (!o) {
      suggest(sink_.error(in.name.where, fmt::format("unknown input `{}`", in.name.text)), in.name.text, observables,
              {.otherwise = "inputs are observables, such as `ir[0..7]`, `speed` or `wheels[0]`"});
      continue;
    }
    if (!in.lo) {
      for (expr::Slot i = 0; i < o->count; ++i) c.mlp.inputs.push_back(o->first + i);
      spans.push_back({&in, o->first, o->count});
      continue;
    }
    if (!o->indexed) {
      sink_.error(in.where, fmt::format("`{}` is a single value and cannot be indexed", in.name.text));
      continue;
    }
    const auto lo = to_whole(*in.lo, "an index", 0, o->count - 1, sink_);
    std::optional<long long> hi = lo;
    if (in.hi) hi = to_whole(*in.hi, "an index", 0, o->count - 1, sink_);
    if (!lo || !hi) continue;
    if (*hi < *lo) {
      sink_.error(in.where, fmt::format("empty range `{}[{}..{}]`: the first index must not exceed the last",
                                        in.name.text, *lo, *hi));
      continue;
    }
    for (long long i = *lo; i <= *hi; ++i) c.mlp.inputs.push_back(o->first + static_cast<expr::Slot>(i));
    spans.push_back({&in, o->first + static_cast<expr::Slot>(*lo), static_cast<expr::Slot>(*hi - *lo + 1)});
  }

  bool has_wheels = false;
  const std::vector<std::string> layer_words = {"hidden", "wheels"};
  for (std::size_t i = 0; i < d.layers.size(); ++i) {
    const ast::Layer& l = d.layers[i];
    if (l.word.text == "hidden" && d.neat) {
      sink_.error(l.where, "a NEAT network declares no hidden layers: NEAT grows its hidden nodes")
          .help.push_back("write `neat(ir[0..7] -> wheels)`");
    } else if (l.word.text == "hidden") {
      if (!l.size) {
        sink_.error(l.where, "a hidden layer needs a size").help.push_back("write `hidden 20`");
        continue;
      }
      if (const auto n = to_whole(*l.size, "a hidden layer's size", 1, 100000, sink_))
        c.mlp.hidden.push_back(static_cast<int>(*n));
    } else if (l.word.text == "wheels") {
      if (l.size) sink_.error(l.size->where, "the `wheels` output takes no size: it is always 2 wheel commands");
      if (d.symbolic) {
        sink_
            .error(l.where,
                   "a symbolic controller's network has no `wheels` output: its outputs choose among the actions")
            .help.push_back("write `symbolic(mlp(ir[0..7] -> hidden 14), actions [forward, left, right])`");
      } else if (d.supervisor) {
        sink_.error(l.where, "a supervisor's network has no `wheels` output: its outputs choose among the behaviors")
            .help.push_back("write `supervisor(elman(ir[0..7] -> hidden 5), behaviors [forward(0.5), left(0.3)])`");
      } else if (i + 1 != d.layers.size()) {
        sink_.error(l.where, "`wheels` must be the last layer");
      }
      has_wheels = true;
    } else if (!l.word.text.empty()) {
      suggest(sink_.error(l.word.where, fmt::format("unknown layer `{}`", l.word.text)), l.word.text, layer_words,
              {.otherwise = "layers are `hidden N` and, last, `wheels`"});
    }
  }
  if (d.elman && sink_.errors() == errors) {
    std::vector<const ast::Layer*> hidden;
    for (const ast::Layer& l : d.layers)
      if (l.word.text == "hidden") hidden.push_back(&l);
    if (hidden.empty())
      sink_.error(d.kind_where, "an Elman network needs exactly one hidden layer, found none")
          .help.push_back("write `elman(ir[0..7] -> hidden 5 -> wheels)`");
    else if (hidden.size() > 1)
      sink_.error(hidden[1]->where,
                  fmt::format("an Elman network has exactly one hidden layer, found {}", hidden.size()))
          .help.push_back("use `mlp(...)` for several hidden layers");
  }
  if (!d.tree && !chooses && !has_wheels && sink_.errors() == errors)
    sink_.error(d.kind_where, "a classical controller must end with `-> wheels`")
        .help.push_back("write `mlp(ir[0..7] -> hidden 20 -> wheels)`");

  std::set<std::string> listed;
  for (const ast::Name& a : d.actions) {
    if (!listed.insert(a.text).second) {
      sink_.error(a.where, fmt::format("action `{}` is listed twice", a.text));
      continue;
    }
    const auto* bd = names_.lookup<ast::BehaviorDecl>(a);
    if (bd == nullptr) continue;
    if (bd->evolved) {
      sink_.error(a.where, fmt::format("`{}` is an evolved controller: it can be a supervisor's behavior, not a "
                                       "symbolic controller's action", a.text))
          .notes.emplace_back(bd->name.where, fmt::format("`{}` is declared here", a.text));
      continue;
    }
    const auto& b = behaviors_.lower(*bd);
    if (b) {
      c.actions.push_back(*b);
      c.choices.push_back({a.text, bd->name.text, bd->library, bd->useless, -1});
      used.push_back(bd);
    }
  }
  bool behaviors_ok = supervised_failed_.count(&d) == 0;
  std::map<std::string, int> labels;   // a behavior listed twice (a library repeated) gets `_2`, `_3`, ...
  for (const Supervised& sv : supervised(d)) {
    const ast::SupervisedRef& r = *sv.ref;
    const ast::BehaviorDecl* bd = sv.decl;
    std::string name = bd->library.empty() ? bd->name.text : bd->member;
    if (const int n = ++labels[name]; n > 1) name += fmt::format("_{}", n);
    if (bd->evolved) {
      if (!r.args.empty()) {
        sink_.error(r.where, fmt::format("`{}` is an evolved controller and takes no arguments", bd->name.text))
            .notes.emplace_back(bd->name.where, fmt::format("`{}` is declared here", bd->name.text));
        behaviors_ok = false;
        continue;
      }
      const auto& e = behaviors_.evolved(*bd);
      if (!e) {
        behaviors_ok = false;
        continue;
      }
      const auto& sub = lower(*e->controller);   // null while in a cycle (reported)
      if (!sub) {
        behaviors_ok = false;
        continue;
      }
      if (sub->per_body()) {
        Diagnostic& diag = sink_.error(
            r.where, fmt::format("`{}` freezes `{}`, a controller per body, and a behavior is one network",
                                 bd->name.text, sub->name));
        diag.notes.emplace_back(bd->name.where, fmt::format("`{}` is declared here", bd->name.text));
        diag.help.push_back("freeze one of its networks, evolved alone in an experiment of its body");
        behaviors_ok = false;
        continue;
      }
      c.behaviors.push_back({name, control::FixedController{
                                              std::make_shared<const control::ControllerSpec>(*sub), {}}});
      c.choices.push_back({name, bd->name.text, bd->library, bd->useless, -1});
      continue;
    }
    const auto& b = behaviors_.lower(*bd);
    if (!b) {
      behaviors_ok = false;
      continue;
    }
    if (r.args.size() != b->params.size()) {
      Diagnostic& diag = sink_.error(
          r.where, fmt::format("behavior `{}` takes {} argument{}, found {}", bd->name.text, b->params.size(),
                               b->params.size() == 1 ? "" : "s", r.args.size()));
      diag.notes.emplace_back(bd->name.where, fmt::format("`{}` is declared here", bd->name.text));
      if (!b->params.empty())
        diag.help.push_back(fmt::format("give a constant for each parameter: `{}({})`", bd->name.text,
                                        fmt::join(b->params, ", ")));
      behaviors_ok = false;
      continue;
    }
    control::BehaviorCall call{*b, {}};
    std::string label = name;
    std::vector<std::string> shown;
    bool args_ok = true;
    for (const ast::Quantity& q : r.args) {
      if (!q.finite) {
        args_ok = false;
        continue;
      }
      const auto v = to_si(q, Dim::None, sink_);
      if (!v) {
        args_ok = false;
        continue;
      }
      call.args.push_back(*v);
      shown.push_back(number_text(*v));
    }
    if (!args_ok) {
      behaviors_ok = false;
      continue;
    }
    if (!r.args.empty()) label += fmt::format("({})", fmt::join(shown, ", "));
    c.behaviors.push_back({label, std::move(call)});
    c.choices.push_back({name, bd->name.text, bd->library, bd->useless, -1});
    used.push_back(bd);
  }
  if (!d.tree && c.mlp.inputs.empty() && sink_.errors() == errors)
    sink_.error(d.kind_where, "a controller needs at least one input");
  if (d.tree && sink_.errors() == errors && c.actions.size() == d.actions.size() && behaviors_ok &&
      !primitives_.tree(d, c))
    behaviors_ok = false;
  if (sink_.errors() == errors && c.actions.size() == d.actions.size() && behaviors_ok) slot = std::move(c);
  return slot;
}

std::optional<control::ControllerSpec> ControllerLowering::lower_per_body(const ast::ControllerDecl& d) {
  const int errors = sink_.errors();
  control::ControllerSpec c;
  auto& decls = networks_[&d];
  decls.clear();
  std::map<std::string, const ast::Name*> bodies;
  const ast::Name* first = nullptr;
  for (const auto& [body, network] : d.per_body) {
    if (const auto [it, fresh] = bodies.try_emplace(body.text, &body); !fresh) {
      sink_.error(body.where, fmt::format("body `{}` is given a network twice", body.text))
          .notes.emplace_back(it->second->where, "first given here");
      continue;
    }
    const bool known = names_.lookup<ast::RobotDecl>(body) != nullptr;
    const ast::ControllerDecl* nd = names_.lookup<ast::ControllerDecl>(network);
    if (!known || nd == nullptr) continue;
    if (!nd->per_body.empty()) {
      sink_.error(network.where, fmt::format("`{}` is itself a controller per body: each body takes a network", network.text))
          .notes.emplace_back(nd->name.where, fmt::format("`{}` is declared here", network.text));
      continue;
    }
    const auto& n = lower(*nd);
    if (!n) continue;
    if (n->is_tree() || n->is_graph()) {
      Diagnostic& diag = sink_.error(
          network.where, fmt::format("`{}` is a {}: a controller per body holds networks of fixed topology, whose "
                                     "weights make one genome",
                                     network.text, n->is_tree() ? "tree" : "NEAT network"));
      diag.notes.emplace_back(nd->name.where, fmt::format("`{}` is declared here", network.text));
      diag.help.push_back("give each body an `mlp(...)` or `elman(...)` network, classical, symbolic or a supervisor");
      continue;
    }
    // Another experiment's evolved controllers are filled in per compared controller
    // (add_dependencies), not per network of one.
    if (const auto frozen = std::find_if(n->behaviors.begin(), n->behaviors.end(),
                                         [](const control::SupervisedBehavior& b) {
                                           return std::holds_alternative<control::FixedController>(b.what);
                                         });
        frozen != n->behaviors.end()) {
      Diagnostic& diag = sink_.error(network.where, fmt::format("`{}` supervises `{}`, an evolved controller: a "
                                                                "controller per body's networks take hand-written "
                                                                "behaviors only",
                                                                network.text, frozen->name));
      diag.notes.emplace_back(nd->name.where, fmt::format("`{}` is declared here", network.text));
      diag.help.push_back("compare the supervisor in an experiment of one body, or give it hand-written behaviors");
      continue;
    }
    if (first != nullptr && (n->head != c.networks.front().head || n->choice_names() != c.networks.front().choice_names() ||
                             n->output_count() != c.networks.front().output_count())) {
      const control::ControllerSpec& f = c.networks.front();
      const auto outputs = [](const control::ControllerSpec& x) {
        const auto names = x.choice_names();
        return names.empty() ? std::string("the wheels") : fmt::format("[{}]", fmt::join(names, ", "));
      };
      sink_.error(network.where, fmt::format("`{}` ({}, choosing {}) has another head than `{}` ({}, choosing {}): the "
                                             "networks of a controller per body drive the group with the same outputs",
                                             network.text, n->head_name(), outputs(*n), first->text, f.head_name(),
                                             outputs(f)))
          .help.push_back("give every body's network the same head: its actions, or its behaviors, in one order");
      continue;
    }
    if (first == nullptr) first = &network;
    c.networks.push_back(*n);
    c.network_bodies.push_back(body.text);
    decls.push_back(nd);
  }
  if (sink_.errors() != errors || c.networks.size() != d.per_body.size()) return std::nullopt;
  // The first body's network, its head and choices stand for the controller where one network
  // is read (its inputs in tables, `using(B)`).
  control::ControllerSpec per_body = c.networks.front();
  per_body.name = d.name.text;
  per_body.networks = std::move(c.networks);
  per_body.network_bodies = std::move(c.network_bodies);
  return per_body;
}

bool ControllerLowering::bind_bodies(control::ControllerSpec& c, const ast::ControllerDecl& d,
                                     const ast::ArenaDecl& arena, const eval::ExperimentSpec& x,
                                     const std::string& robot, const ast::Name& use) {
  const std::vector<const ast::ControllerDecl*>& decls = networks_[&d];
  std::vector<std::string> group;
  if (x.bodies.empty()) group.push_back(robot);
  for (const eval::ExperimentSpec::GroupBody& b : x.bodies) group.push_back(b.name);
  bool ok = true;
  c.body_networks.clear();
  for (std::size_t b = 0; b < group.size(); ++b) {
    const auto it = std::find(c.network_bodies.begin(), c.network_bodies.end(), group[b]);
    if (it == c.network_bodies.end()) {
      Diagnostic& diag = sink_.error(use.where, fmt::format("controller `{}` has no network for `{}`, a body of "
                                                            "experiment `{}`'s group",
                                                            use.text, group[b], x.name));
      diag.notes.emplace_back(d.kind_where, fmt::format("`{}`'s networks are given here", d.name.text));
      diag.help.push_back(fmt::format("add `{}: NETWORK` to its list", group[b]));
      ok = false;
      continue;
    }
    const auto k = static_cast<std::size_t>(it - c.network_bodies.begin());
    c.body_networks.push_back(k);
    if (k < decls.size() && !bind(c.networks[k], *decls[k], arena, navigation_of(x, b))) ok = false;
  }
  for (std::size_t k = 0; k < c.network_bodies.size(); ++k)
    if (std::find(group.begin(), group.end(), c.network_bodies[k]) == group.end()) {
      Diagnostic& diag = sink_.error(use.where, fmt::format("controller `{}` has a network for `{}`, a body experiment "
                                                            "`{}` does not have",
                                                            use.text, c.network_bodies[k], x.name));
      diag.notes.emplace_back(d.per_body[k].body.where, "given here");
      diag.help.push_back("list only the bodies of the experiment's `robot` item");
      ok = false;
    }
  return ok;
}

bool ControllerLowering::check_sensors(const control::ControllerSpec& c, const ast::ControllerDecl& d,
                                       const Navigation& navigation) {
  bool ok = true;
  const auto report = [&](const SourceRange& where, RuleMessage m, std::string help) {
    Diagnostic& diag = sink_.error(where, std::move(m.message));
    diag.help = std::move(m.help);
    diag.help.push_back(std::move(help));
    ok = false;
  };
  // The first slot of `slots` that has no sensor, reported at `where`.
  const auto check = [&](const auto& slots, const SourceRange& where, const std::string& help) {
    for (const expr::Slot s : slots)
      if (auto m = unavailable(s, navigation)) return report(where, std::move(*m), help);
  };
  for (const InputSlots& in : inputs_[&d]) {
    if (auto m = misnamed(in.input->name.text, navigation, &names_.sensor_names())) {
      report(in.input->where, std::move(*m), fmt::format("controller `{}` reads it as a network input", d.name.text));
      continue;
    }
    std::vector<expr::Slot> slots;
    for (expr::Slot i = 0; i < in.count; ++i) slots.push_back(in.first + i);
    check(slots, in.input->where, fmt::format("controller `{}` reads it as a network input", d.name.text));
  }
  if (c.primitives) {
    std::vector<expr::Slot> terminals;
    const std::string help = fmt::format("primitive set `{}` holds it as a terminal", d.primitives.text);
    std::optional<RuleMessage> wrong_body;
    for (const genome::tree::Primitive& p : c.primitives->primitives()) {
      if (p.kind != genome::tree::Kind::Observable) continue;
      terminals.push_back(p.slot);
      const std::string_view array = std::string_view(p.name).substr(0, p.name.find('['));
      if (!wrong_body) wrong_body = misnamed(array, navigation, &names_.sensor_names());
    }
    if (wrong_body) report(d.primitives.where, std::move(*wrong_body), help);
    else check(terminals, d.primitives.where, help);
  }
  const auto& listed = supervised(d);
  for (std::size_t j = 0; j < c.behaviors.size() && j < listed.size(); ++j)
    if (const auto* fixed = std::get_if<control::FixedController>(&c.behaviors[j].what); fixed && fixed->spec)
      check(slots_read(*fixed->spec), listed[j].ref->where,
            fmt::format("the evolved controller `{}` reads it", listed[j].decl->name.text));
  return ok;
}

bool ControllerLowering::bind(control::ControllerSpec& c, const ast::ControllerDecl& d, const ast::ArenaDecl& arena,
                              const Navigation& navigation) {
  const SensorKey key{&d,
                      navigation.goal,
                      navigation.rangefinders,
                      navigation.radars,
                      navigation.ir_sensors,
                      navigation.ground_sensors,
                      navigation.bumpers,
                      navigation.names};
  auto [checked, fresh] = sensors_ok_.try_emplace(key, true);
  if (fresh) checked->second = check_sensors(c, d, navigation);
  bool ok = checked->second;
  const auto it = used_.find(&d);
  if (it == used_.end()) return ok;
  const auto& decls = it->second;
  std::size_t k = 0;
  auto rebind = [&](control::Behavior& b) {
    if (k >= decls.size()) return;
    const auto& bound = behaviors_.lower(*decls[k++], &arena, &navigation);
    if (bound) b = *bound;
    else ok = false;
  };
  for (control::Behavior& b : c.actions) rebind(b);
  for (control::SupervisedBehavior& s : c.behaviors)
    if (auto* call = std::get_if<control::BehaviorCall>(&s.what)) rebind(call->behavior);
  return ok;
}

}  // namespace esc::compiler
