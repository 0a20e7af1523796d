// Experiments: the items of an `experiment` block -> eval::ExperimentSpec.
#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include <fmt/format.h>

#include "compiler/model.hpp"
#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/settings.hpp"

namespace esc::compiler {

namespace {

constexpr long long kIntMax = std::numeric_limits<int>::max();

// Distance from point p to a rotated box (0 inside).
double distance_to_box(const sim::BoxObstacle& b, double px, double py) {
  const double c = std::cos(-b.angle_rad), s = std::sin(-b.angle_rad);
  const double dx = px - b.center_m.x, dy = py - b.center_m.y;
  const double lx = c * dx - s * dy, ly = s * dx + c * dy;
  const double ex = std::max(std::abs(lx) - b.size_m.x / 2, 0.0);
  const double ey = std::max(std::abs(ly) - b.size_m.y / 2, 0.0);
  return std::hypot(ex, ey);
}

std::string cm(double m) { return fmt::format("{}cm", number_text(std::round(m * 1e4) / 100)); }

}  // namespace

bool Model::check_fit(const ast::ArenaDecl& a, const sim::ArenaSpec& arena, const sim::KheperaParams& robot,
                      const SourceRange& use) {
  const double r = robot.body_radius_m;
  if (arena.width_m <= 2 * r || arena.height_m <= 2 * r) {
    Diagnostic& d = sink_.error(use, fmt::format("the robot ({} across) does not fit in arena `{}` ({} x {})", cm(2 * r),
                                                 a.name.text, cm(arena.width_m), cm(arena.height_m)));
    if (!a.sizes.empty()) d.notes.emplace_back(a.sizes[0].where, "the arena's size is given here");
    return false;
  }
  if (!arena.fixed_start || a.starts.empty()) return true;
  const sim::Pose& p = *arena.fixed_start;
  const SourceRange& where = a.starts[0].where;
  if (p.x_m < r || p.y_m < r || p.x_m > arena.width_m - r || p.y_m > arena.height_m - r) {
    sink_.error(where, fmt::format("the robot starting here would overlap a wall: its body radius is {}", cm(r)))
        .notes.emplace_back(use, "the robot's size comes from this experiment");
    return false;
  }
  for (const auto& c : arena.cylinders) {
    if (std::hypot(p.x_m - c.center_m.x, p.y_m - c.center_m.y) < c.radius_m + r) {
      sink_.error(where, fmt::format("the robot starting here would overlap the cylinder at ({}, {})",
                                     cm(c.center_m.x), cm(c.center_m.y)))
          .notes.emplace_back(use, "the robot's size comes from this experiment");
      return false;
    }
  }
  for (const auto& b : arena.boxes) {
    if (distance_to_box(b, p.x_m, p.y_m) < r) {
      sink_.error(where, fmt::format("the robot starting here would overlap the block at ({}, {})", cm(b.center_m.x),
                                     cm(b.center_m.y)))
          .notes.emplace_back(use, "the robot's size comes from this experiment");
      return false;
    }
  }
  return true;
}

std::optional<eval::ExperimentSpec> Model::experiment(const ast::ExperimentDecl& d) {
  if (auto it = experiments_.find(&d); it != experiments_.end()) return it->second;
  auto& slot = experiments_[&d];
  if (d.poisoned) return std::nullopt;
  const int errors = sink_.errors();
  bool ok = true;   // false also when a referenced declaration failed silently
  using K = ast::ExpItem::Kind;

  eval::ExperimentSpec x;
  x.name = d.name.text;
  std::map<K, const ast::ExpItem*> first;
  const ast::ArenaDecl* arena_decl = nullptr;
  const ast::ExpItem* robot_item = nullptr;
  std::string robot_name = "default";
  std::string step_text;
  std::vector<std::string> stop_texts;
  bool epochs_gave_steps = false;
  const ast::FitnessDecl* fitness_decl = nullptr;
  std::vector<const ast::ControllerDecl*> controller_decls;
  const ast::ExperimentDecl* start_decl = nullptr;
  std::vector<const ast::Name*> compared;   // the names in `compare`, one per controller
  const ast::ExpItem* gp_item = nullptr;

  for (const ast::ExpItem& item : d.items) {
    // `evolve gp(...)` evolves the trees, beside an `evolve es(...)` for the networks.
    if (item.kind == K::Evolve && !item.refs.empty() && item.refs[0].text == "gp") {
      if (gp_item != nullptr) {
        sink_.error(item.where, "`evolve gp` is already given in this experiment")
            .notes.emplace_back(gp_item->where, "first given here");
        continue;
      }
      gp_item = &item;
      lower_gp(item, x);
      continue;
    }
    auto [it, fresh] = first.try_emplace(item.kind, &item);
    const bool steps_again = item.kind == K::Steps && epochs_gave_steps;
    if (!fresh || steps_again) {
      const ast::ExpItem* prior = fresh ? first[K::Epochs] : it->second;
      std::string word;
      switch (item.kind) {
        case K::Arena: word = "arena"; break;
        case K::Robot: word = "robot"; break;
        case K::Epochs: word = "epochs"; break;
        case K::Steps: word = "steps"; break;
        case K::Fitness: word = "fitness"; break;
        case K::Evolve: word = "evolve"; break;
        case K::Runs: word = "runs"; break;
        case K::Seed: word = "seed"; break;
        case K::Compare: word = "compare"; break;
        case K::StartFrom: word = item.evaluate_only ? "evaluate from" : "start from"; break;
      }
      sink_.error(item.where, fmt::format("`{}` is already given in this experiment", word))
          .notes.emplace_back(prior->where, "first given here");
      continue;
    }
    switch (item.kind) {
      case K::Arena: {
        const Symbol* s = lookup(item.refs[0], DeclKind::Arena);
        if (s == nullptr) {
          ok = false;
          break;
        }
        arena_decl = static_cast<const ast::ArenaDecl*>(s->decl);
        const auto& a = arena(*arena_decl);
        if (!a) ok = false;
        else x.arena = *a;
        x.arena_name = item.refs[0].text;
        break;
      }
      case K::Robot: {
        robot_item = &item;
        const Symbol* s = lookup(item.refs[0], DeclKind::Robot);
        if (s == nullptr) {
          ok = false;
          break;
        }
        const auto& r = robot(*static_cast<const ast::RobotDecl*>(s->decl));
        if (!r) {
          ok = false;
          break;
        }
        x.robot = *r;
        robot_name = item.refs[0].text;
        if (!apply_settings(x.robot, item.settings)) ok = false;
        else if (std::string m = check_robot(x.robot); !m.empty()) sink_.error(item.refs[0].where, m);
        break;
      }
      case K::Epochs: {
        if (!item.numbers.empty())
          if (auto n = to_whole(item.numbers[0], "`epochs`", 1, kIntMax, sink_)) x.epochs = static_cast<int>(*n);
        if (item.numbers.size() > 1) {
          epochs_gave_steps = true;
          if (auto n = to_whole(item.numbers[1], "`steps`", 1, kIntMax, sink_)) x.steps = static_cast<int>(*n);
        }
        break;
      }
      case K::Steps:
        if (!item.numbers.empty())
          if (auto n = to_whole(item.numbers[0], "`steps`", 1, kIntMax, sink_)) x.steps = static_cast<int>(*n);
        break;
      case K::Fitness: {
        const Symbol* s = lookup(item.refs[0], DeclKind::Fitness);
        if (s == nullptr) {
          ok = false;
          break;
        }
        fitness_decl = static_cast<const ast::FitnessDecl*>(s->decl);
        const auto& f = fitness(*fitness_decl);
        if (!f) {
          ok = false;
          break;
        }
        x.fitness = f->spec;
        step_text = f->step_text;
        stop_texts = f->stop_texts;
        break;
      }
      case K::Evolve: {
        const ast::Name& method = item.refs[0];
        if (method.text != "es") {
          std::string msg = fmt::format("unknown evolution method `{}`", method.text);
          if (const auto best = closest(method.text, {"es", "gp"})) msg += fmt::format("; did you mean `{}`?", *best);
          Diagnostic& diag = sink_.error(method.where, msg);
          diag.help.push_back("write `evolve es(mu 30, lambda 150, comma) for 250 generations` (networks)");
          diag.help.push_back("or `evolve gp(population 150, tournament 7) for 50 generations` (tree controllers)");
          break;
        }
        evo::EsSettings& es = x.es;
        std::map<std::string, const ast::EsOption*> seen;
        std::map<std::string, std::string> group_of = {
            {"comma", "selection"},       {"plus", "selection"},          {"intermediate", "recombination"},
            {"discrete", "recombination"}, {"no_recombination", "recombination"}, {"self_adaptive", "step sizes"},
            {"one_sigma", "step sizes"}};
        const std::vector<std::string> names = {"mu", "lambda", "comma", "plus", "intermediate", "discrete",
                                                "no_recombination", "self_adaptive", "one_sigma", "bounds", "sigma",
                                                "min_sigma", "generations"};
        for (const ast::EsOption& o : item.options) {
          const std::string& n = o.name.text;
          if (n.empty()) continue;
          if (std::find(names.begin(), names.end(), n) == names.end()) {
            std::string msg = fmt::format("unknown ES option `{}`", n);
            const auto best = closest(n, names);
            if (best) msg += fmt::format("; did you mean `{}`?", *best);
            Diagnostic& diag = sink_.error(o.name.where, msg);
            if (!best) diag.help.push_back(fmt::format("ES options: {}", fmt::join(names, ", ")));
            continue;
          }
          const std::string group = group_of.count(n) != 0 ? group_of[n] : n;
          if (auto [it2, fresh2] = seen.try_emplace(group, &o); !fresh2) {
            sink_.error(o.where, fmt::format("the {} is already given", group == n ? "`" + n + "`" : group))
                .notes.emplace_back(it2->second->where, "first given here");
            continue;
          }
          const bool wants_value = n == "mu" || n == "lambda" || n == "sigma" || n == "min_sigma" || n == "generations";
          const bool wants_range = n == "bounds";
          if (wants_range != (o.lo.has_value()) || (wants_value != o.value.has_value() && !wants_range)) {
            if (wants_range)
              sink_.error(o.where, "`bounds` takes a range").help.push_back("write `bounds [-1, 1]`");
            else if (wants_value)
              sink_.error(o.where, fmt::format("`{}` needs a value", n)).help.push_back(fmt::format("write `{} 30`", n));
            else
              sink_.error(o.where, fmt::format("`{}` takes no value", n));
            continue;
          }
          if (n == "mu") {
            if (auto v = to_whole(*o.value, "`mu`", 1, kIntMax, sink_)) es.mu = static_cast<int>(*v);
          } else if (n == "lambda") {
            if (auto v = to_whole(*o.value, "`lambda`", 1, kIntMax, sink_)) es.lambda = static_cast<int>(*v);
          } else if (n == "generations") {
            if (auto v = to_whole(*o.value, "`generations`", 1, kIntMax, sink_)) es.generations = static_cast<int>(*v);
          } else if (n == "sigma" || n == "min_sigma") {
            if (auto v = to_si(*o.value, Dim::None, sink_)) {
              if (*v <= 0) sink_.error(o.value->where, fmt::format("`{}` must be greater than 0", n));
              else (n == "sigma" ? es.initial_sigma : es.min_sigma) = *v;
            }
          } else if (n == "bounds") {
            const auto lo = to_si(*o.lo, Dim::None, sink_), hi = to_si(*o.hi, Dim::None, sink_);
            if (lo && hi) {
              if (!(*lo < *hi)) {
                sink_.error(o.where, fmt::format("empty bounds: the lower bound ({}) must be below the upper ({})",
                                                 number_text(*lo), number_text(*hi)));
              } else {
                es.lower = *lo;
                es.upper = *hi;
              }
            }
          } else if (n == "comma") es.selection = evo::Selection::Comma;
          else if (n == "plus") es.selection = evo::Selection::Plus;
          else if (n == "intermediate") es.recombination = evo::Recombination::Intermediate;
          else if (n == "discrete") es.recombination = evo::Recombination::Discrete;
          else if (n == "no_recombination") es.recombination = evo::Recombination::None;
          else if (n == "self_adaptive") es.step_sizes = evo::StepSizes::PerGene;
          else if (n == "one_sigma") es.step_sizes = evo::StepSizes::One;
        }
        if (item.generations) {
          if (seen.count("generations") != 0)
            sink_.error(item.generations->where, "the number of generations is already given in `es(...)`");
          else if (auto v = to_whole(*item.generations, "`generations`", 1, kIntMax, sink_))
            es.generations = static_cast<int>(*v);
        }
        if (es.selection == evo::Selection::Comma && es.lambda < es.mu)
          sink_.error(item.where, fmt::format("comma selection needs `lambda` >= `mu`, found mu {} and lambda {}",
                                              es.mu, es.lambda))
              .help.push_back("raise `lambda`, or use `plus` selection");
        break;
      }
      case K::StartFrom: {
        const Symbol* s = lookup(item.refs[0], DeclKind::Experiment);
        if (s == nullptr) {
          ok = false;
          break;
        }
        start_decl = static_cast<const ast::ExperimentDecl*>(s->decl);
        if (start_decl == &d) {
          sink_.error(item.refs[0].where, fmt::format("experiment `{}` cannot start from itself", d.name.text));
          ok = false;
          break;
        }
        x.start_from = eval::StartFrom{item.refs[0].text, item.evaluate_only, {}};
        break;
      }
      case K::Runs:
        if (!item.numbers.empty())
          if (auto n = to_whole(item.numbers[0], "`runs`", 1, kIntMax, sink_)) x.runs = static_cast<int>(*n);
        break;
      case K::Seed:
        if (!item.numbers.empty())
          if (auto n = to_whole(item.numbers[0], "`seed`", 0, 1LL << 53, sink_)) x.seed = static_cast<std::uint64_t>(*n);
        break;
      case K::Compare: {
        std::set<std::string> listed;
        for (const ast::Name& ref : item.refs) {
          if (ref.text.empty()) continue;
          if (!listed.insert(ref.text).second) {
            sink_.error(ref.where, fmt::format("controller `{}` is listed twice", ref.text));
            continue;
          }
          const Symbol* s = lookup(ref, DeclKind::Controller);
          if (s == nullptr) {
            ok = false;
            continue;
          }
          const auto* cd = static_cast<const ast::ControllerDecl*>(s->decl);
          const auto& c = controller(*cd);
          if (!c) {
            ok = false;
          } else {
            x.controllers.push_back(*c);
            controller_decls.push_back(cd);
            compared.push_back(&ref);
          }
        }
        break;
      }
    }
  }

  auto require = [&](K k, std::string_view what, std::string_view example) {
    if (first.count(k) != 0) return;
    sink_.error(d.name.where, fmt::format("experiment `{}` names no {}", d.name.text, what))
        .help.push_back(fmt::format("add `{}`", example));
  };
  require(K::Arena, "arena", "arena <name>");
  require(K::Fitness, "fitness", "fitness <name>");
  require(K::Compare, "controllers to compare", "compare <controller>, <controller>");
  if (ok && sink_.errors() == errors) {
    const auto es_item = first.find(K::Evolve);
    check_algorithms(d, x, compared, es_item == first.end() ? nullptr : es_item->second, gp_item);
  }

  // `in(zone)` and `reached(light)` resolve in this experiment's arena.
  if (ok && sink_.errors() == errors && arena_decl != nullptr) {
    if (fitness_decl != nullptr) {
      const auto& f = fitness(*fitness_decl, arena_decl);
      if (f) x.fitness = f->spec;
      else ok = false;
    }
    for (std::size_t i = 0; i < controller_decls.size() && i < x.controllers.size(); ++i)
      if (!bind_behaviors(x.controllers[i], *controller_decls[i], *arena_decl)) ok = false;
  }
  if (ok && sink_.errors() == errors && arena_decl != nullptr) {
    const SourceRange use = robot_item != nullptr ? robot_item->where : first[K::Arena]->where;
    (void)check_fit(*arena_decl, x.arena, x.robot, use);
  }
  if (start_decl != nullptr) {
    check_start_from(*start_decl, first);
    for (const control::ControllerSpec& c : x.controllers)
      if (c.is_tree())
        sink_.error(first[K::StartFrom]->where,
                    fmt::format("tree controller `{}` cannot start from stored trees yet; only networks can", c.name))
            .help.push_back("compare the tree controllers in an experiment of their own");
  }
  if (!ok || sink_.errors() != errors) return std::nullopt;

  // Evolved behaviors: which experiment's controller fills which supervised behavior.
  for (std::size_t i = 0; i < controller_decls.size() && i < x.controllers.size(); ++i) {
    const auto& behaviors = x.controllers[i].behaviors;
    const auto& listed = supervised(*controller_decls[i]);
    for (std::size_t j = 0; j < behaviors.size() && j < listed.size(); ++j) {
      if (!std::holds_alternative<control::FixedController>(behaviors[j].what)) continue;
      const auto& e = evolved(*listed[j].decl);
      if (!e) continue;
      const std::string xn = e->experiment->name.text, cn = e->controller->name.text;
      auto dep = std::find_if(x.dependencies.begin(), x.dependencies.end(),
                              [&](const eval::Dependency& k) { return k.experiment == xn && k.controller == cn; });
      if (dep == x.dependencies.end()) dep = x.dependencies.insert(x.dependencies.end(), eval::Dependency{xn, cn, {}});
      dep->targets.emplace_back(i, j);
    }
  }

  x.resolved_settings["robot"] = robot_name;
  x.resolved_settings["fitness.step"] = step_text;
  std::string stops;
  for (const std::string& s : stop_texts) stops += (stops.empty() ? "" : "; ") + s;
  x.resolved_settings["fitness.stop"] = stops;
  resolve_settings(x);
  slot = x;
  return slot;
}

void Model::check_start_from(const ast::ExperimentDecl& from,
                             const std::map<ast::ExpItem::Kind, const ast::ExpItem*>& first) {
  using K = ast::ExpItem::Kind;
  const ast::ExpItem& item = *first.at(K::StartFrom);
  if (item.evaluate_only && first.count(K::Evolve) != 0) {
    Diagnostic& diag =
        sink_.error(first.at(K::Evolve)->where, "an experiment that evaluates stored controllers evolves nothing");
    diag.notes.emplace_back(item.where, "it evaluates stored controllers here");
    diag.help.push_back(fmt::format("write `start from experiment {}` to evolve on from them", from.name.text));
  }
  std::vector<std::string> theirs;
  for (const ast::ExpItem& i : from.items)
    if (i.kind == K::Compare)
      for (const ast::Name& n : i.refs) theirs.push_back(n.text);
  const auto c = first.find(K::Compare);
  if (c == first.end()) return;
  for (const ast::Name& n : c->second->refs) {
    if (n.text.empty() || std::find(theirs.begin(), theirs.end(), n.text) != theirs.end()) continue;
    Diagnostic& diag = sink_.error(
        n.where, fmt::format("experiment `{}` does not compare `{}`: there is no stored `{}` to start from",
                             from.name.text, n.text, n.text));
    diag.notes.emplace_back(item.refs[0].where, fmt::format("`{}` is named here", from.name.text));
    if (!theirs.empty()) diag.help.push_back(fmt::format("`{}` compares {}", from.name.text, quoted_list(theirs, ", ")));
  }
}

std::vector<eval::ExperimentSpec> Model::experiments(const ast::Module& main, std::vector<eval::ExperimentSpec>* all) {
  std::vector<eval::ExperimentSpec> out;
  // Check every experiment of every file; return those of the main file.
  for (const ast::Module* m : modules_)
    for (const auto& d : m->experiments) {
      auto x = experiment(d);
      if (all != nullptr && x) all->push_back(*x);
      if (m == &main && x) out.push_back(std::move(*x));
    }
  return out;
}

}  // namespace esc::compiler
