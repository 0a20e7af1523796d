// Experiments: the items of an `experiment` block -> eval::ExperimentSpec.
#include "compiler/lower_experiment.hpp"

#include <algorithm>
#include <set>
#include <variant>

#include <fmt/format.h>

#include "compiler/algorithm_options.hpp"
#include "compiler/experiment_settings.hpp"
#include "compiler/lower_evolution.hpp"
#include "compiler/lower_objectives.hpp"
#include "compiler/lower_success.hpp"
#include "compiler/names.hpp"
#include "compiler/robot_settings.hpp"
#include "compiler/setting_keys.hpp"
#include "compiler/setting_values.hpp"

namespace esc::compiler {

namespace {

using K = ast::ExpItem::Kind;

std::string_view item_word(const ast::ExpItem& item) {
  switch (item.kind) {
    case K::Arena: return "arena";
    case K::Robot: return "robot";
    case K::Epochs: return "epochs";
    case K::Steps: return "steps";
    case K::Fitness: return "fitness";
    case K::Objective: return "objective";
    case K::Descriptor: return "descriptor";
    case K::Success: return "success";
    case K::StopAtSuccess: return "stop at success";
    case K::Evolve: return "evolve";
    case K::Runs: return "runs";
    case K::Seed: return "seed";
    case K::Compare: return "compare";
    case K::StartFrom: return item.evaluate_only ? "evaluate from" : "start from";
    case K::Formation: return "formation";
    case K::Roles: return "roles";
  }
  return "";
}

// The declaration `ref` names and its lowering; null when either fails (reported).
template <class D, class Lowering>
auto lowered(Resolver& names, Lowering& lowering, const ast::Name& ref, const D*& decl) {
  decl = names.lookup<D>(ref);
  const auto* l = decl != nullptr ? &lowering.lower(*decl) : nullptr;
  return l != nullptr && *l ? &**l : nullptr;
}

}  // namespace

const std::optional<eval::ExperimentSpec>& ExperimentLowering::lower(const ast::ExperimentDecl& d) {
  if (auto it = experiments_.find(&d); it != experiments_.end()) return it->second;
  auto& slot = experiments_[&d];
  if (d.poisoned) return slot;
  const int errors = sink_.errors();
  bool ok = true;   // false also when a referenced declaration failed silently

  eval::ExperimentSpec x;
  x.name = d.name.text;
  // The settings every experiment holds (the ES's), its defaults until `evolve` gives them.
  for (const AlgorithmOptions& a : algorithm_options())
    if (a.scope == evo::SettingsScope::Always) a.settings_in(x);
  Items first;
  const ast::ArenaDecl* arena_decl = nullptr;
  const LoweredArena* arena = nullptr;
  const ast::ExpItem* robot_item = nullptr;
  std::optional<LoweredRobot> robot;
  std::string robot_name = "default";
  const ast::FitnessDecl* fitness_decl = nullptr;
  const LoweredFitness* fitness = nullptr;
  std::vector<const ast::ControllerDecl*> controller_decls;
  std::vector<const ast::Name*> compared;   // the names in `compare`, one per controller
  const ast::ExperimentDecl* start_decl = nullptr;
  std::vector<const ast::Name*> by;         // `by` of each controller, empty text when none
  EvolveItems evolve;
  ObjectiveItems objective_items;
  bool epochs_gave_steps = false;
  std::optional<SensorDifference> sensors_differ;
  // `epochs`, `steps`, `runs`, `seed`: each number read by its row of the table.
  const auto setting = [&](std::string_view key, const ast::Quantity& q) {
    const ExperimentSetting& row = *find_experiment_setting(key);
    if (q.finite) (void)row.read(row, x, as_value(q), sink_);
  };

  for (const ast::ExpItem& item : d.items) {
    // `evolve NAME(...)`: `es` for the networks, `gp` for the trees, any other beside them.
    if (is_algorithm_evolve(item)) {
      lower_evolve(item, x, evolve, sink_);
      continue;
    }
    // Objectives and descriptors: as many as the experiment declares.
    if (item.kind == K::Objective || item.kind == K::Descriptor) {
      (item.kind == K::Objective ? objective_items.objectives : objective_items.descriptors).push_back(&item);
      continue;
    }
    auto [it, fresh] = first.try_emplace(item.kind, &item);
    const bool steps_again = item.kind == K::Steps && epochs_gave_steps;
    if (!fresh || steps_again) {
      sink_.error(item.where, fmt::format("`{}` is already given in this experiment", item_word(item)))
          .notes.emplace_back((fresh ? first[K::Epochs] : it->second)->where, "first given here");
      continue;
    }
    switch (item.kind) {
      case K::Arena:
        arena = lowered(names_, parts_.arenas, item.refs[0], arena_decl);
        if (arena != nullptr) x.arena = arena->spec;
        else ok = false;
        x.arena_name = item.refs[0].text;
        break;
      case K::Robot: {
        robot_item = &item;
        const ast::RobotDecl* rd = nullptr;
        if (const LoweredRobot* declared = lowered(names_, parts_.robots, item.refs[0], rd)) {
          robot = *declared;
          robot_name = item.refs[0].text;
          // The inline settings and the runtime's rules for the robot they make.
          const bool first_ok =
              parts_.robots.apply(*robot, item.settings) && parts_.robots.check(*robot, item.refs[0].where);
          if (!first_ok) ok = false;
          x.robot = robot->params;
          if (!item.numbers.empty()) setting("robots", item.numbers[0]);
          // Further bodies are compared with the first: not with one its errors left half set.
          if (first_ok && !item.members.empty() && !lower_bodies(item, robot->params, x, sensors_differ)) ok = false;
        } else {
          ok = false;
        }
        break;
      }
      case K::Epochs:
        if (!item.numbers.empty()) setting("epochs", item.numbers[0]);
        if (item.numbers.size() > 1) {
          epochs_gave_steps = true;
          setting("steps", item.numbers[1]);
        }
        break;
      case K::Steps:
        if (!item.numbers.empty()) setting("steps", item.numbers[0]);
        break;
      case K::Runs:
        if (!item.numbers.empty()) setting("runs", item.numbers[0]);
        break;
      case K::Formation:
        if (!lower_formation(item, x)) ok = false;
        break;
      case K::Roles:
        if (!item.numbers.empty()) setting("roles", item.numbers[0]);
        break;
      case K::Seed:
        if (!item.numbers.empty()) setting("seed", item.numbers[0]);
        break;
      case K::Objective:
      case K::Descriptor:
      case K::Success:   // after the objectives and descriptors, below
      case K::StopAtSuccess:
        break;
      case K::Fitness:
        objective_items.fitness = &item;
        fitness = lowered(names_, parts_.fitnesses, item.refs[0], fitness_decl);
        if (fitness != nullptr) x.fitness = fitness->spec;
        else ok = false;
        break;
      case K::Evolve: {
        // Not a registered algorithm's (is_algorithm_evolve, above).
        const ast::Name& method = item.refs[0];
        Diagnostic& diag = sink_.error(method.where, fmt::format("unknown evolution method `{}`", method.text));
        suggest(diag, method.text, algorithm_names());
        diag.help.push_back("write `evolve es(mu 30, lambda 150, comma) for 250 generations` (networks)");
        diag.help.push_back("or `evolve gp(population 150, tournament 7) for 50 generations` (tree controllers)");
        diag.help.push_back(fmt::format("algorithms: {}", quoted_list(algorithm_names())));
        break;
      }
      case K::StartFrom:
        start_decl = names_.lookup<ast::ExperimentDecl>(item.refs[0]);
        if (start_decl == nullptr) {
          ok = false;
        } else if (start_decl == &d) {
          sink_.error(item.refs[0].where, fmt::format("experiment `{}` cannot start from itself", d.name.text));
          ok = false;
        } else {
          x.start_from = eval::StartFrom{item.refs[0].text, item.evaluate_only, {}};
        }
        break;
      case K::Compare: {
        std::set<std::string> listed;
        for (std::size_t i = 0; i < item.refs.size(); ++i) {
          const ast::Name& ref = item.refs[i];
          const ast::Name& as = item.compared_as(i);
          if (ref.text.empty() || as.text.empty()) continue;
          if (!listed.insert(as.text).second) {
            sink_.error(as.where, fmt::format("controller `{}` is listed twice", as.text));
            continue;
          }
          const ast::ControllerDecl* cd = nullptr;
          const control::ControllerSpec* c = lowered(names_, parts_.controllers, ref, cd);
          if (c == nullptr) {
            ok = false;
            continue;
          }
          x.controllers.push_back(*c);
          x.controllers.back().name = as.text;   // `CS8 as CS`: stored and reported as CS
          controller_decls.push_back(cd);
          compared.push_back(&as);
          by.push_back(&item.algorithms[i]);
        }
        break;
      }
    }
  }

  // Bodies that read other sensors: every compared controller needs a network per body.
  if (sensors_differ)
    for (std::size_t i = 0; i < x.controllers.size() && i < compared.size(); ++i)
      if (!x.controllers[i].per_body()) {
        sensors_differ->plain = compared[i];
        report_sensor_difference(*sensors_differ);
        ok = false;
        break;
      }

  const auto require = [&](K k, std::string_view what, std::string_view example) {
    if (first.count(k) != 0) return;
    sink_.error(d.name.where, fmt::format("experiment `{}` names no {}", d.name.text, what))
        .help.push_back(fmt::format("add `{}`", example));
  };
  require(K::Arena, "arena", "arena <name>");
  require(K::Fitness, "fitness", "fitness <name>");
  require(K::Compare, "controllers to compare", "compare <controller>, <controller>");

  // `in(zone)` and `reached(light)` resolve in this experiment's arena, `using(B)` & co.
  // among its controllers' choices; what needs a goal or a sensor is read where the arena and
  // robot have it.
  if (ok && sink_.errors() == errors && arena_decl != nullptr) {
    const ChoiceNames choices = number_choices(x);
    const Navigation navigation = navigation_of(x);
    if (fitness_decl != nullptr) {
      const auto& f = parts_.fitnesses.lower(*fitness_decl, arena_decl, &d, &choices, &navigation, &x.cluster_radii);
      if (f) x.fitness = f->spec;
      else ok = false;
      if (f) fitness = &*f;
    }
    if (!lower_objectives(objective_items, d, *arena_decl, choices, navigation, names_, parts_.fitnesses, parts_.arenas,
                          sink_, x))
      ok = false;
    else if (const auto s = first.find(K::Success); s != first.end() && !lower_success(*s->second, objective_items, sink_, x))
      ok = false;
    if (const auto stop = first.find(K::StopAtSuccess); stop != first.end()) {
      if (x.success) {
        x.stop_at_success = true;
      } else if (!first.contains(K::Success)) {
        sink_.error(stop->second->where, "`stop at success` needs the experiment's success test")
            .help.push_back("declare it: `success when reach_goal > -17.1875mm` (the fitness, an objective or a "
                            "descriptor, compared with a number)");
        ok = false;
      }
    }
    for (std::size_t i = 0; i < controller_decls.size() && i < x.controllers.size(); ++i)
      if (x.controllers[i].per_body()
              ? !parts_.controllers.bind_bodies(x.controllers[i], *controller_decls[i], *arena_decl, x, robot_name,
                                                *compared[i])
              : !parts_.controllers.bind(x.controllers[i], *controller_decls[i], *arena_decl, navigation))
        ok = false;
    // The first body's reads are checked where they are written; the others' here, once those
    // hold.
    if (sensors_differ && robot_item != nullptr && sink_.errors() == errors)
      if (auto m = unreadable_on_bodies(x)) {
        sink_.error(robot_item->where, std::move(m->message)).help = std::move(m->help);
        ok = false;
      }
  }
  // After the objectives and descriptors: an algorithm's settings are checked against them.
  if (ok && sink_.errors() == errors) choose_algorithms(d, x, compared, by, evolve, sink_);
  if (ok && sink_.errors() == errors && arena != nullptr) {
    const SourceRange use = robot_item != nullptr ? robot_item->where : first[K::Arena]->where;
    (void)parts_.arenas.check_placement(*arena_decl, *arena, x.robot, use);
    const auto where = [&](K kind) { return first.contains(kind) ? &first[kind]->where : nullptr; };
    check_group(x, use, sink_, {.formation = where(K::Formation), .roles = where(K::Roles)});
    if (x.robots == 1 && x.robot.emission.intensity > 0.0)
      sink_.warning(use, "a robot alone does not read its own light: `emission` has no effect without other robots")
          .help.push_back("make a group (`robot NAME x N`), or remove `emission`");
  }
  if (start_decl != nullptr) check_start_from(*start_decl, first, evolve);
  if (!ok || sink_.errors() != errors) return slot;

  add_dependencies(x, controller_decls);
  x.resolved_settings["robot"] = robot_name;
  x.resolved_settings["fitness.step"] = fitness->step_text;
  std::string stops;
  for (const std::string& s : fitness->stop_texts) stops += (stops.empty() ? "" : "; ") + s;
  x.resolved_settings["fitness.stop"] = stops;
  // Only when given, so that experiments without end terms resolve as they always did.
  if (!fitness->epoch_text.empty()) x.resolved_settings["fitness.epoch"] = fitness->epoch_text;
  if (!fitness->evaluation_text.empty()) x.resolved_settings["fitness.evaluation"] = fitness->evaluation_text;
  if (!fitness->over_text.empty()) x.resolved_settings["fitness.over_robots"] = fitness->over_text;
  resolve_settings(x);
  resolve_objectives(x, objective_items);
  resolve_success(x);
  slot = std::move(x);
  return slot;
}

void ExperimentLowering::report_sensor_difference(const SensorDifference& s) {
  const BodyDifference& differ = s.difference;
  const bool sensors = differ.sensors();
  Diagnostic& d = sink_.error(s.body->where, group_difference_message(differ, s.body->text, s.first));
  if (s.set_at) d.notes.emplace_back(*s.set_at, fmt::format("`{}`'s `{}` is set here", s.body->text, differ.key));
  if (differ.key.ends_with("_name"))
    d.help.push_back(fmt::format("name its sensors as `{}` does, in the group's list: `{} {{ {} {} }}`", s.first,
                                 s.body->text, differ.key, differ.first));
  else if (!sensors)
    d.help.push_back(fmt::format("give both bodies the same `{}`, in a declaration or in the group's list (`{} {{ {} ... }}`)",
                                 differ.key, s.body->text, differ.key));
  if (sensors)
    d.help.push_back(fmt::format("{}ompare controllers with a network per body: `controller NAME = per_body({}: "
                                 "NETWORK, {}: NETWORK)` (docs/groups.md)",
                                 d.help.empty() ? "c" : "or c", s.first, s.body->text));
  if (s.plain != nullptr)
    d.notes.emplace_back(s.plain->where, fmt::format("`{}` is one network for every body", s.plain->text));
}

bool ExperimentLowering::lower_bodies(const ast::ExpItem& item, const sim::RobotParams& first,
                                      eval::ExperimentSpec& x, std::optional<SensorDifference>& sensors) {
  bool ok = true;
  long long total = x.robots;
  x.bodies = {{item.refs[0].text, first, x.robots}};
  for (const ast::GroupMember& m : item.members) {
    long long count = 1;
    if (m.count) {
      const auto n = read_count(as_value(*m.count), "robots", 1, eval::kMaxRobots, sink_);
      if (!n) {
        ok = false;
        continue;
      }
      count = *n;
    }
    const ast::RobotDecl* rd = nullptr;
    const LoweredRobot* declared = lowered(names_, parts_.robots, m.ref, rd);
    if (declared == nullptr) {
      ok = false;
      continue;
    }
    LoweredRobot body = *declared;
    if (!parts_.robots.apply(body, m.settings) || !parts_.robots.check(body, m.ref.where)) {
      ok = false;
      continue;
    }
    if (auto differ = group_difference(first, body.params)) {
      const auto set = body.written.find(differ->key);
      SensorDifference found{&m.ref, std::move(*differ), std::nullopt, item.refs[0].text};
      if (set != body.written.end()) found.set_at = set->second.where;
      // What a controller reads may differ where each body has a network of its own: seen
      // once the compared controllers are known. The drive and the step are the world's.
      if (!found.difference.sensors()) {
        report_sensor_difference(found);
        ok = false;
        continue;
      }
      if (!sensors) sensors = std::move(found);
    }
    total += count;
    x.bodies.push_back({m.ref.text, body.params, static_cast<int>(count)});
  }
  if (ok && total > eval::kMaxRobots) {
    sink_.error(item.where, fmt::format("the group's bodies add up to {} robots, and a group holds at most {}", total,
                                        eval::kMaxRobots));
    ok = false;
  }
  if (ok) x.robots = static_cast<int>(total);
  return ok;
}

// `formation line 10cm`, `formation circle 15cm`, `formation at [(x, y, heading), ...]`,
// `formation random`: read by the rows `formation`, `formation_spacing` and `formation_at`.
bool ExperimentLowering::lower_formation(const ast::ExpItem& item, eval::ExperimentSpec& x) {
  const ast::Name& kind = item.refs[0];
  ast::Value word;
  word.kind = ast::Value::Kind::Word;
  word.text = kind.text;
  word.where = kind.where;
  const ExperimentSetting& row = *find_experiment_setting("formation");
  if (kind.text.empty() || !row.read(row, x, word, sink_)) return false;
  const std::string_view shape = kind.text == "line" || kind.text == "circle" ? "spacing" : kind.text == "at" ? "list" : "";
  const bool spaced = !item.numbers.empty(), listed = item.list.has_value();
  if ((shape == "spacing") != spaced || (shape == "list") != listed) {
    Diagnostic& d = sink_.error(kind.where, shape == "spacing" ? fmt::format("`formation {}` takes a length", kind.text)
                                            : shape == "list"  ? std::string("`formation at` takes a pose per robot")
                                                               : std::string("`formation random` takes nothing more"));
    d.help.push_back(shape == "spacing" ? fmt::format("write `formation {} 10cm` ({})", kind.text,
                                                      kind.text == "line" ? "between neighbours' centres" : "its radius")
                     : shape == "list"  ? std::string("write `formation at [(20cm, 20cm, 90deg), (40cm, 20cm, 90deg)]`")
                                        : std::string("write `formation random`"));
    return false;
  }
  if (spaced) {
    const ExperimentSetting& spacing = *find_experiment_setting("formation_spacing");
    if (!item.numbers[0].finite || !spacing.read(spacing, x, as_value(item.numbers[0]), sink_)) return false;
  }
  if (listed) {
    const ExperimentSetting& at = *find_experiment_setting("formation_at");
    if (!at.read(at, x, *item.list, sink_)) return false;
  }
  return true;
}

ChoiceNames ExperimentLowering::number_choices(eval::ExperimentSpec& x) {
  ChoiceNames names{x.name, {}, 0};
  std::map<std::pair<std::string, std::string>, int> ids;   // (name, behavior) -> id
  const auto add = [&](const std::string& name, int id) {
    auto& v = names.ids[name];
    if (std::find(v.begin(), v.end(), id) == v.end()) v.push_back(id);
  };
  for (control::ControllerSpec& c : x.controllers)
    for (std::size_t j = 0; j < c.choices.size(); ++j) {
      control::Choice& choice = c.choices[j];
      choice.id = ids.try_emplace({choice.name, choice.behavior}, static_cast<int>(ids.size())).first->second;
      add(choice.name, choice.id);
      // `library.member` names every listing of the member (`crash`, `crash_2`, ...).
      if (!choice.library.empty()) add(choice.behavior, choice.id);
      // A supervisor's behavior listed with arguments also by the name usage tables print,
      // `forward_2(0.3)`: one name, copied from a table, reads the same choice.
      if (c.head == control::Head::Supervisor && j < c.behaviors.size() && c.behaviors[j].name != choice.name)
        add(c.behaviors[j].name, choice.id);
    }
  x.choice_ids = ids.size();
  names.count = ids.size();
  return names;
}

void ExperimentLowering::add_dependencies(eval::ExperimentSpec& x,
                                          const std::vector<const ast::ControllerDecl*>& compared) {
  for (std::size_t i = 0; i < compared.size() && i < x.controllers.size(); ++i) {
    const auto& behaviors = x.controllers[i].behaviors;
    const auto& listed = parts_.controllers.supervised(*compared[i]);
    for (std::size_t j = 0; j < behaviors.size() && j < listed.size(); ++j) {
      if (!std::holds_alternative<control::FixedController>(behaviors[j].what)) continue;
      const auto& e = parts_.behaviors.evolved(*listed[j].decl);
      if (!e) continue;
      const std::string xn = e->experiment->name.text, cn = e->compared_as;
      auto dep = std::find_if(x.dependencies.begin(), x.dependencies.end(),
                              [&](const eval::Dependency& k) { return k.experiment == xn && k.controller == cn; });
      if (dep == x.dependencies.end()) dep = x.dependencies.insert(x.dependencies.end(), eval::Dependency{xn, cn, {}});
      dep->targets.emplace_back(i, j);
    }
  }
}

void ExperimentLowering::check_start_from(const ast::ExperimentDecl& from, const Items& first,
                                          const EvolveItems& evolves) {
  const ast::ExpItem& item = *first.at(K::StartFrom);
  const ast::ExpItem* evolve = evolves.order.empty() ? nullptr : evolves.of(evolves.order.front());
  if (item.evaluate_only && evolve != nullptr) {
    Diagnostic& diag =
        sink_.error(evolve->where, "an experiment that evaluates stored controllers evolves nothing");
    diag.notes.emplace_back(item.where, "it evaluates stored controllers here");
    diag.help.push_back(fmt::format("write `start from experiment {}` to evolve on from them", from.name.text));
  }
  std::vector<std::string> theirs;
  for (const ast::Compared& c : ast::compared(from)) theirs.push_back(c.name->text);
  const auto c = first.find(K::Compare);
  if (c == first.end()) return;
  for (std::size_t i = 0; i < c->second->refs.size(); ++i) {
    const ast::Name& n = c->second->compared_as(i);
    if (n.text.empty() || std::find(theirs.begin(), theirs.end(), n.text) != theirs.end()) continue;
    Diagnostic& diag = sink_.error(
        n.where, fmt::format("experiment `{}` does not compare `{}`: there is no stored `{}` to start from",
                             from.name.text, n.text, n.text));
    diag.notes.emplace_back(item.refs[0].where, fmt::format("`{}` is named here", from.name.text));
    if (!theirs.empty())
      diag.help.push_back(fmt::format("`{}` compares {}", from.name.text, quoted_list(theirs, ", ")));
  }
}

void ExperimentLowering::check_cycles() {
  // Edges: experiment -> the experiments whose evolved controllers its controllers use, or
  // that it starts from.
  using Edge = Dependency<ast::ExperimentDecl>;
  std::map<const ast::ExperimentDecl*, std::vector<Edge>> edges;
  std::vector<const ast::ExperimentDecl*> all;
  for (const ast::Module* m : names_.modules())
    for (const auto& x : m->experiments) {
      all.push_back(&x);
      auto& out = edges[&x];
      for (const ast::ExpItem& item : x.items) {
        if (item.kind == K::StartFrom) {
          const auto* to = names_.find<ast::ExperimentDecl>(item.refs[0].text);
          if (to != nullptr && to != &x) out.push_back({to, &item.refs[0]});
          continue;
        }
        if (item.kind != K::Compare) continue;
        for (const ast::Name& ref : item.refs) {
          const auto* cd = names_.find<ast::ControllerDecl>(ref.text);
          if (cd == nullptr) continue;
          for (const Supervised& sv : parts_.controllers.supervised(*cd)) {
            if (!sv.decl->evolved) continue;
            if (const auto& e = parts_.behaviors.evolved(*sv.decl))
              out.push_back({e->experiment, &sv.decl->from_experiment});
          }
        }
      }
    }
  const auto report = [&](const std::vector<const ast::ExperimentDecl*>& path, const Edge& closing) {
    std::string text;
    for (const ast::ExperimentDecl* x : path) text += fmt::format("`{}` -> ", x->name.text);
    text += fmt::format("`{}`", closing.to->name.text);
    sink_.error(closing.via->where,
                fmt::format("experiments depend on each other's evolved controllers in a cycle: {}", text))
        .help.push_back("an experiment can use the evolved controllers only of experiments that do not use its own");
  };
  for_each_cycle<ast::ExperimentDecl>(all, edges, report);
}

}  // namespace esc::compiler
