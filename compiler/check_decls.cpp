// Names and the lowering of arenas, robots, behaviors, fitness functions and controllers.
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include <fmt/format.h>

#include "compiler/lower_expr.hpp"
#include "compiler/model.hpp"
#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/settings.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::compiler {

std::string_view kind_name(DeclKind k) noexcept {
  switch (k) {
    case DeclKind::Arena: return "arena";
    case DeclKind::Robot: return "robot";
    case DeclKind::Behavior: return "behavior";
    case DeclKind::Fitness: return "fitness";
    case DeclKind::Controller: return "controller";
    case DeclKind::Experiment: return "experiment";
    case DeclKind::Library: return "library";
    case DeclKind::Primitives: return "primitive set";
  }
  return "declaration";
}

namespace {

std::string article(std::string_view kind) {
  const bool vowel = !kind.empty() && std::string_view("aeiou").find(kind[0]) != std::string_view::npos;
  return std::string(vowel ? "an " : "a ") + std::string(kind);
}

}  // namespace

void Model::add(DeclKind k, const ast::DeclHead& h, const void* d) {
  if (h.name.text.empty()) return;
  auto [it, inserted] = symbols_.try_emplace(h.name.text, Symbol{k, &h, d});
  if (inserted) return;
  const Symbol& first = it->second;
  Diagnostic& diag = sink_.error(h.name.where, fmt::format("`{}` is already declared", h.name.text));
  diag.notes.emplace_back(first.head->name.where,
                          fmt::format("first declared here, as {}", article(kind_name(first.kind))));
  diag.help.push_back(
      "every arena, robot, behavior, fitness, controller, experiment, library and primitive set needs its own name");
}

void Model::declare(const ast::Module& m) {
  modules_.push_back(&m);
  // In source order, so that "first declared here" points at the earlier one.
  std::vector<std::pair<int, std::pair<DeclKind, const ast::DeclHead*>>> all;
  std::map<const ast::DeclHead*, const void*> ptr;
  auto collect = [&](DeclKind k, const auto& v) {
    for (const auto& d : v) {
      all.push_back({d.order, {k, &d}});
      ptr[&d] = &d;
    }
  };
  collect(DeclKind::Arena, m.arenas);
  collect(DeclKind::Robot, m.robots);
  collect(DeclKind::Behavior, m.behaviors);
  collect(DeclKind::Fitness, m.fitnesses);
  collect(DeclKind::Controller, m.controllers);
  collect(DeclKind::Experiment, m.experiments);
  collect(DeclKind::Library, m.libraries);
  collect(DeclKind::Primitives, m.primitives);
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [order, kd] : all) add(kd.first, *kd.second, ptr[kd.second]);
}

const Symbol* Model::lookup(const ast::Name& ref, DeclKind want) {
  if (ref.text.empty()) return nullptr;
  const auto it = symbols_.find(ref.text);
  if (it == symbols_.end()) {
    std::vector<std::string> same_kind, all;
    for (const auto& [name, s] : symbols_) {
      all.push_back(name);
      if (s.kind == want) same_kind.push_back(name);
    }
    std::string msg = fmt::format("unknown {} `{}`", kind_name(want), ref.text);
    auto best = closest(ref.text, same_kind);
    if (best) msg += fmt::format("; did you mean `{}`?", *best);
    Diagnostic& d = sink_.error(ref.where, msg);
    if (!best) {
      if (same_kind.empty())
        d.help.push_back(fmt::format("no {} is declared; declare one, or import a file that does", kind_name(want)));
      else if (same_kind.size() <= 8)
        d.help.push_back(fmt::format("declared {}s: {}", kind_name(want), quoted_list(same_kind, ", ")));
    }
    return nullptr;
  }
  const Symbol& s = it->second;
  if (s.kind != want) {
    Diagnostic& d = sink_.error(ref.where, fmt::format("`{}` is {}, not {}", ref.text, article(kind_name(s.kind)),
                                                       article(kind_name(want))));
    d.notes.emplace_back(s.head->name.where, fmt::format("`{}` is declared here", ref.text));
    return nullptr;
  }
  if (s.head->poisoned) return nullptr;
  return &s;
}

void Model::check_all() {
  for (const ast::Module* m : modules_) {
    for (const auto& d : m->arenas) (void)arena(d);
    for (const auto& d : m->robots) (void)robot(d);
    for (const auto& d : m->behaviors) (void)behavior(d);
    for (const auto& d : m->fitnesses) (void)fitness(d);
    for (const auto& d : m->primitives) (void)primitives(d);
    for (const auto& d : m->controllers) (void)controller(d);
  }
  check_dependency_cycles();
}

// ---- evolved behaviors --------------------------------------------------------------

const std::optional<Model::EvolvedRef>& Model::evolved(const ast::BehaviorDecl& d) {
  if (auto it = evolved_.find(&d); it != evolved_.end()) return it->second;
  auto& slot = evolved_[&d];
  if (d.poisoned || !d.evolved) return slot;
  const Symbol* xs = lookup(d.from_experiment, DeclKind::Experiment);
  if (xs == nullptr) return slot;
  const auto* xd = static_cast<const ast::ExperimentDecl*>(xs->decl);
  std::vector<std::string> compared;
  const ast::Name* found = nullptr;
  for (const ast::ExpItem& item : xd->items)
    if (item.kind == ast::ExpItem::Kind::Compare)
      for (const ast::Name& n : item.refs) {
        compared.push_back(n.text);
        if (n.text == d.from_controller.text && found == nullptr) found = &n;
      }
  if (d.from_controller.text.empty()) return slot;
  if (found == nullptr) {
    std::string msg = fmt::format("experiment `{}` does not compare a controller `{}`", d.from_experiment.text,
                                  d.from_controller.text);
    const auto best = closest(d.from_controller.text, compared);
    if (best) msg += fmt::format("; did you mean `{}`?", *best);
    Diagnostic& diag = sink_.error(d.from_controller.where, msg);
    diag.notes.emplace_back(xd->name.where, fmt::format("`{}` is declared here", d.from_experiment.text));
    if (!best && !compared.empty())
      diag.help.push_back(fmt::format("`{}` compares {}", d.from_experiment.text, quoted_list(compared, ", ")));
    return slot;
  }
  const Symbol* cs = lookup(d.from_controller, DeclKind::Controller);
  if (cs == nullptr) return slot;
  slot = EvolvedRef{xd, static_cast<const ast::ControllerDecl*>(cs->decl)};
  return slot;
}

void Model::check_dependency_cycles() {
  // Edges: experiment -> the experiments whose evolved controllers its controllers use.
  struct Edge {
    const ast::ExperimentDecl* to;
    const ast::Name* via;   // where the other experiment is named
  };
  std::map<const ast::ExperimentDecl*, std::vector<Edge>> edges;
  std::vector<const ast::ExperimentDecl*> all;
  for (const ast::Module* m : modules_)
    for (const auto& x : m->experiments) {
      all.push_back(&x);
      auto& out = edges[&x];
      for (const ast::ExpItem& item : x.items) {
        if (item.kind == ast::ExpItem::Kind::StartFrom) {
          const auto it = symbols_.find(item.refs[0].text);
          if (it != symbols_.end() && it->second.kind == DeclKind::Experiment && it->second.decl != &x)
            out.push_back({static_cast<const ast::ExperimentDecl*>(it->second.decl), &item.refs[0]});
          continue;
        }
        if (item.kind != ast::ExpItem::Kind::Compare) continue;
        for (const ast::Name& ref : item.refs) {
          const auto it = symbols_.find(ref.text);
          if (it == symbols_.end() || it->second.kind != DeclKind::Controller) continue;
          const auto* cd = static_cast<const ast::ControllerDecl*>(it->second.decl);
          for (const Supervised& sv : supervised(*cd)) {
            const ast::BehaviorDecl* bd = sv.decl;
            if (!bd->evolved) continue;
            if (const auto& e = evolved(*bd)) out.push_back({e->experiment, &bd->from_experiment});
          }
        }
      }
    }
  std::map<const ast::ExperimentDecl*, int> state;   // 0 new, 1 on the stack, 2 done
  std::vector<const ast::ExperimentDecl*> stack;
  std::set<std::set<const ast::ExperimentDecl*>> reported;
  std::function<void(const ast::ExperimentDecl*)> visit = [&](const ast::ExperimentDecl* x) {
    state[x] = 1;
    stack.push_back(x);
    for (const Edge& e : edges[x]) {
      if (state[e.to] == 1) {
        const auto from = std::find(stack.begin(), stack.end(), e.to);
        std::set<const ast::ExperimentDecl*> members(from, stack.end());
        if (!reported.insert(members).second) continue;
        std::string path;
        for (auto it = from; it != stack.end(); ++it) path += fmt::format("`{}` -> ", (*it)->name.text);
        path += fmt::format("`{}`", e.to->name.text);
        Diagnostic& d = sink_.error(e.via->where,
                                    fmt::format("experiments depend on each other's evolved controllers in a cycle: {}",
                                                path));
        d.help.push_back("an experiment can use the evolved controllers only of experiments that do not use its own");
      } else if (state[e.to] == 0 && stack.size() < 1000) {
        visit(e.to);
      }
    }
    stack.pop_back();
    state[x] = 2;
  };
  for (const ast::ExperimentDecl* x : all)
    if (state[x] == 0) visit(x);
}

// ---- arenas -------------------------------------------------------------------------

namespace {

struct Corners {
  std::array<sim::Vec2, 4> p;
};

Corners corners(const sim::BoxObstacle& b) {
  const double c = std::cos(b.angle_rad), s = std::sin(b.angle_rad);
  const double hx = b.size_m.x / 2, hy = b.size_m.y / 2;
  Corners k;
  const std::array<std::pair<double, double>, 4> d = {{{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}}};
  for (std::size_t i = 0; i < 4; ++i)
    k.p[i] = {b.center_m.x + c * d[i].first - s * d[i].second, b.center_m.y + s * d[i].first + c * d[i].second};
  return k;
}

std::string cm(double m) { return fmt::format("{}cm", number_text(std::round(m * 1e4) / 100)); }

}  // namespace

const std::optional<sim::ArenaSpec>& Model::arena(const ast::ArenaDecl& d) {
  if (auto it = arenas_.find(&d); it != arenas_.end()) return it->second;
  auto& slot = arenas_[&d];
  if (d.poisoned) return slot;
  const int errors = sink_.errors();
  sim::ArenaSpec a;
  a.boxes.clear();
  a.cylinders.clear();
  constexpr double kEps = 1e-12;

  if (d.sizes.empty()) {
    sink_.error(d.name.where, fmt::format("arena `{}` has no size", d.name.text))
        .help.push_back("add `size 60cm x 60cm`");
  }
  for (std::size_t i = 1; i < d.sizes.size(); ++i)
    sink_.error(d.sizes[i].where, "the arena's size is already given")
        .notes.emplace_back(d.sizes[0].where, "first given here");
  bool size_ok = false;
  if (!d.sizes.empty()) {
    const auto w = to_si(d.sizes[0].w, Dim::Length, sink_);
    const auto h = to_si(d.sizes[0].h, Dim::Length, sink_);
    if (w && h) {
      if (*w <= 0 || *h <= 0) {
        sink_.error(d.sizes[0].where, "an arena's width and height must be greater than 0");
      } else {
        a.width_m = *w;
        a.height_m = *h;
        size_ok = true;
      }
    }
  }
  const std::string arena_text = size_ok ? fmt::format("{} x {}", cm(a.width_m), cm(a.height_m)) : "";
  for (const ast::Cylinder& c : d.cylinders) {
    const auto x = to_si(c.x, Dim::Length, sink_), y = to_si(c.y, Dim::Length, sink_),
               r = to_si(c.radius, Dim::Length, sink_);
    if (!x || !y || !r) continue;
    if (*r <= 0) {
      sink_.error(c.radius.where, "a cylinder's radius must be greater than 0");
      continue;
    }
    if (size_ok && (*x - *r < -kEps || *y - *r < -kEps || *x + *r > a.width_m + kEps || *y + *r > a.height_m + kEps)) {
      sink_.error(c.where, fmt::format("this cylinder is not inside the arena ({})", arena_text))
          .help.push_back("positions are measured from the arena's lower-left inner corner");
      continue;
    }
    a.cylinders.push_back({{*x, *y}, *r});
  }
  for (const ast::Block& b : d.blocks) {
    const auto x = to_si(b.x, Dim::Length, sink_), y = to_si(b.y, Dim::Length, sink_),
               w = to_si(b.w, Dim::Length, sink_), h = to_si(b.h, Dim::Length, sink_);
    std::optional<double> ang = 0.0;
    if (b.angle) ang = to_si(*b.angle, Dim::Angle, sink_);
    if (!x || !y || !w || !h || !ang) continue;
    if (*w <= 0 || *h <= 0) {
      sink_.error(b.where, "a block's width and height must be greater than 0");
      continue;
    }
    const sim::BoxObstacle box{{*x, *y}, {*w, *h}, *ang};
    if (size_ok) {
      const Corners k = corners(box);
      const bool inside = std::all_of(k.p.begin(), k.p.end(), [&](const sim::Vec2& p) {
        return p.x >= -1e-9 && p.y >= -1e-9 && p.x <= a.width_m + 1e-9 && p.y <= a.height_m + 1e-9;
      });
      if (!inside) {
        sink_.error(b.where, fmt::format("this block is not inside the arena ({})", arena_text))
            .help.push_back("positions are measured from the arena's lower-left inner corner to the block's centre");
        continue;
      }
    }
    a.boxes.push_back(box);
  }
  for (std::size_t i = 1; i < d.starts.size(); ++i)
    sink_.error(d.starts[i].where, "the arena's start is already given")
        .notes.emplace_back(d.starts[0].where, "first given here");
  if (!d.starts.empty() && !d.starts[0].random) {
    const ast::Start& s = d.starts[0];
    const auto x = to_si(s.x, Dim::Length, sink_), y = to_si(s.y, Dim::Length, sink_);
    std::optional<double> heading = 0.0;
    if (s.heading) heading = to_si(*s.heading, Dim::Angle, sink_);
    if (x && y && heading) {
      if (size_ok && (*x < 0 || *y < 0 || *x > a.width_m || *y > a.height_m))
        sink_.error(s.where, fmt::format("the start position is outside the arena ({})", arena_text));
      else
        a.fixed_start = sim::Pose{*x, *y, *heading};
    }
  }
  // Zones first: a light may stand above one.
  std::map<std::string, std::size_t> zone_index;
  for (std::size_t i = 0; i < d.zones.size(); ++i) {
    const ast::Zone& z = d.zones[i];
    if (i == sim::kMaxZones)
      sink_.error(z.where, fmt::format("an arena holds at most {} zones", sim::kMaxZones));
    if (!z.name.text.empty() && !zone_index.try_emplace(z.name.text, i).second) {
      sink_.error(z.name.where, fmt::format("zone `{}` is already declared in this arena", z.name.text))
          .notes.emplace_back(d.zones[zone_index[z.name.text]].name.where, "first declared here");
      continue;
    }
    sim::Zone k;
    k.shape = z.circle ? sim::ZoneShape::Circle : sim::ZoneShape::Rectangle;
    double half_w = 0, half_h = 0;
    if (z.circle) {
      const auto r = to_si(z.radius, Dim::Length, sink_);
      if (!r) continue;
      if (*r <= 0) {
        sink_.error(z.radius.where, "a zone's radius must be greater than 0");
        continue;
      }
      k.radius_m = *r;
      half_w = half_h = *r;
    } else {
      const auto w = to_si(z.w, Dim::Length, sink_), h = to_si(z.h, Dim::Length, sink_);
      if (!w || !h) continue;
      if (*w <= 0 || *h <= 0) {
        sink_.error(z.where, "a zone's width and height must be greater than 0");
        continue;
      }
      k.size_m = {*w, *h};
      half_w = *w / 2;
      half_h = *h / 2;
    }
    bool vis_given = false;
    std::set<std::string> flags;
    for (const ast::Name& f : z.flags) {
      if (!flags.insert(f.text).second) {
        sink_.error(f.where, fmt::format("`{}` is already given for this zone", f.text));
        continue;
      }
      if (f.text == "recharge") {
        k.recharge = true;
      } else {
        if (vis_given) sink_.error(f.where, "a zone is either `visible` or `invisible`");
        vis_given = true;
        k.visible = f.text == "visible";
      }
    }
    if (z.random) {
      k.random_position = true;
      if (size_ok) k.center_m = {a.width_m / 2, a.height_m / 2};
      if (size_ok && (2 * half_w > a.width_m + kEps || 2 * half_h > a.height_m + kEps)) {
        sink_.error(z.where, fmt::format("this zone is larger than the arena ({})", arena_text));
        continue;
      }
    } else {
      const auto x = to_si(z.x, Dim::Length, sink_), y = to_si(z.y, Dim::Length, sink_);
      if (!x || !y) continue;
      k.center_m = {*x, *y};
      if (size_ok && (*x - half_w < -kEps || *y - half_h < -kEps || *x + half_w > a.width_m + kEps ||
                      *y + half_h > a.height_m + kEps)) {
        sink_.error(z.where, fmt::format("this zone is not inside the arena ({})", arena_text))
            .help.push_back("positions are measured from the arena's lower-left inner corner to the zone's centre");
        continue;
      }
    }
    a.zones.push_back(k);
  }
  std::set<std::string> light_names;
  for (std::size_t i = 0; i < d.lights.size(); ++i) {
    const ast::Light& l = d.lights[i];
    if (i == sim::kMaxLights)
      sink_.error(l.where, fmt::format("an arena holds at most {} lights", sim::kMaxLights));
    if (!l.name.text.empty() && !light_names.insert(l.name.text).second) {
      sink_.error(l.name.where, fmt::format("light `{}` is already declared in this arena", l.name.text));
      continue;
    }
    sim::LightSource k;
    if (l.height) {
      const auto h = to_si(*l.height, Dim::Length, sink_);
      if (!h) continue;
      if (*h < 0) {
        sink_.error(l.height->where, "a light's height must not be negative");
        continue;
      }
      k.height_m = *h;
    }
    if (l.intensity) {
      const auto v = to_si(*l.intensity, Dim::None, sink_);
      if (!v) continue;
      if (*v <= 0) {
        sink_.error(l.intensity->where, "a light's intensity must be greater than 0");
        continue;
      }
      k.intensity = *v;
    }
    if (l.above) {
      const auto it = zone_index.find(l.above->text);
      if (it == zone_index.end()) {
        std::vector<std::string> zones;
        for (const ast::Zone& z : d.zones) zones.push_back(z.name.text);
        std::string msg = fmt::format("unknown zone `{}` in arena `{}`", l.above->text, d.name.text);
        if (auto best = closest(l.above->text, zones)) msg += fmt::format("; did you mean `{}`?", *best);
        sink_.error(l.above->where, msg);
        continue;
      }
      k.above_zone = static_cast<int>(it->second);
      if (it->second < a.zones.size()) k.position_m = a.zones[it->second].center_m;
    } else if (l.x && l.y) {
      const auto x = to_si(*l.x, Dim::Length, sink_), y = to_si(*l.y, Dim::Length, sink_);
      if (!x || !y) continue;
      if (size_ok && (*x < -kEps || *y < -kEps || *x > a.width_m + kEps || *y > a.height_m + kEps)) {
        sink_.error(l.where, fmt::format("this light is not inside the arena ({})", arena_text));
        continue;
      }
      k.position_m = {*x, *y};
    }
    a.lights.push_back(k);
  }
  auto length_item = [&](const std::vector<ast::ArenaLength>& items, std::string_view word, double& out) {
    for (std::size_t i = 1; i < items.size(); ++i)
      sink_.error(items[i].where, fmt::format("the arena's `{}` is already given", word))
          .notes.emplace_back(items[0].where, "first given here");
    if (items.empty()) return;
    const auto v = to_si(items[0].value, Dim::Length, sink_);
    if (!v) return;
    if (*v <= 0) {
      sink_.error(items[0].value.where, fmt::format("`{}` must be greater than 0", word));
      return;
    }
    out = *v;
  };
  length_item(d.sweep_cells, "sweep_cell", a.sweep_cell_m);
  length_item(d.reach_radii, "reach_radius", a.reach_radius_m);
  if (sink_.errors() == errors) slot = a;
  return slot;
}

const ArenaNames& Model::arena_names(const ast::ArenaDecl& d) {
  auto [it, fresh] = arena_names_.try_emplace(&d);
  if (fresh) {
    it->second.arena = d.name.text;
    for (const ast::Zone& z : d.zones) it->second.zones.push_back(z.name.text);
    for (const ast::Light& l : d.lights) it->second.lights.push_back(l.name.text);
  }
  return it->second;
}

// ---- robots -------------------------------------------------------------------------

bool Model::apply_settings(sim::KheperaParams& p, const std::vector<ast::Setting>& settings) {
  bool ok = true;
  std::map<std::string, const ast::Setting*> seen;
  for (const ast::Setting& s : settings) {
    if (s.key.text.empty()) {
      ok = false;
      continue;
    }
    const RobotSetting* info = find_robot_setting(s.key.text);
    if (info == nullptr) {
      std::string msg = fmt::format("unknown robot setting `{}`", s.key.text);
      const auto best = closest(s.key.text, robot_setting_names());
      if (best) msg += fmt::format("; did you mean `{}`?", *best);
      Diagnostic& d = sink_.error(s.key.where, msg);
      if (!best) d.help.push_back(fmt::format("robot settings: {}", fmt::join(robot_setting_names(), ", ")));
      ok = false;
      continue;
    }
    if (auto [it, fresh] = seen.try_emplace(s.key.text, &s); !fresh) {
      sink_.error(s.key.where, fmt::format("`{}` is already set in this block", s.key.text))
          .notes.emplace_back(it->second->key.where, "first set here");
      ok = false;
      continue;
    }
    const ast::Value& v = s.value;
    if (v.kind == ast::Value::Kind::Quantity && !v.q.finite) {
      ok = false;
      continue;
    }
    const SettingValue r = read_robot_value(*info, v.kind == ast::Value::Kind::Bool, v.flag, v.q.value, v.q.text, v.q.unit);
    if (!r.ok) {
      const SourceRange& where =
          v.kind == ast::Value::Kind::Quantity && !v.q.unit.empty() && r.message.find("unit") != std::string::npos
              ? v.q.unit_where
              : v.where;
      Diagnostic& d = sink_.error(where, r.message);
      if (!r.help.empty()) d.help.push_back(r.help);
      ok = false;
      continue;
    }
    info->set(p, r.si);
  }
  return ok;
}

const std::optional<sim::KheperaParams>& Model::robot(const ast::RobotDecl& d) {
  if (auto it = robots_.find(&d); it != robots_.end()) return it->second;
  static const std::optional<sim::KheperaParams> kNone;
  if (d.poisoned) return robots_[&d];
  if (robots_in_progress_.count(&d) != 0) {
    sink_.error(d.name.where, fmt::format("robot `{}` is derived from itself", d.name.text));
    robots_[&d] = std::nullopt;
    return robots_[&d];
  }
  robots_in_progress_.insert(&d);
  std::optional<sim::KheperaParams> base = sim::KheperaParams{};
  if (d.base) {
    base.reset();
    if (const Symbol* s = lookup(*d.base, DeclKind::Robot)) base = robot(*static_cast<const ast::RobotDecl*>(s->decl));
  }
  robots_in_progress_.erase(&d);
  if (auto it = robots_.find(&d); it != robots_.end()) return it->second;   // set by a cycle report
  auto& slot = robots_[&d];
  if (!base) return slot;
  sim::KheperaParams p = *base;
  if (!apply_settings(p, d.settings)) return slot;
  if (std::string m = check_robot(p); !m.empty()) {
    sink_.error(d.name.where, m);
    return slot;
  }
  slot = p;
  return slot;
}

// ---- behaviors ----------------------------------------------------------------------

const std::optional<control::Behavior>& Model::behavior(const ast::BehaviorDecl& d, const ast::ArenaDecl* arena) {
  const Key key{&d, arena};
  if (auto it = behaviors_.find(key); it != behaviors_.end()) return it->second;
  if (arena != nullptr && !behavior(d)) return behaviors_[key];   // reported without the arena
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
  if (arena != nullptr) scope.arena = &arena_names(*arena);
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
    Diagnostic& diag = sink_.error(d.body_fn.where, fmt::format("unknown command `{}`{}", d.body_fn.text,
                                                                closest(d.body_fn.text, {"wheels"})
                                                                    ? "; did you mean `wheels`?"
                                                                    : ""));
    diag.help.push_back("a behavior's body is `wheels(left, right)`, two wheel commands in [-1, 1]");
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

// ---- fitness ------------------------------------------------------------------------

const std::optional<FitnessResult>& Model::fitness(const ast::FitnessDecl& d, const ast::ArenaDecl* arena) {
  const Key key{&d, arena};
  if (auto it = fitnesses_.find(key); it != fitnesses_.end()) return it->second;
  if (arena != nullptr && !fitness(d)) return fitnesses_[key];   // reported without the arena
  auto& slot = fitnesses_[key];
  if (d.poisoned) return slot;
  const int errors = sink_.errors();
  FitnessResult f;
  f.spec.name = d.name.text;
  ExprScope scope;
  if (arena != nullptr) scope.arena = &arena_names(*arena);
  if (d.steps.empty())
    sink_.error(d.name.where, fmt::format("fitness `{}` has no `step:` term", d.name.text))
        .help.push_back("add `step: forward_speed`, the value added up at every control step");
  for (std::size_t i = 1; i < d.steps.size(); ++i)
    sink_.error(d.steps[i].where, "the fitness already has a `step:` term")
        .notes.emplace_back(d.steps[0].where, "first given here");
  if (!d.steps.empty() && d.steps[0].expr) {
    if (auto p = lower_expr(*d.steps[0].expr, scope, sink_)) f.spec.step = std::move(*p);
    f.step_text = d.steps[0].text;
  }
  for (const ast::FitnessTerm& s : d.stops) {
    if (!s.expr) continue;
    if (auto p = lower_expr(*s.expr, scope, sink_)) f.spec.stop_when.push_back(std::move(*p));
    f.stop_texts.push_back(s.text);
  }
  if (sink_.errors() == errors) slot = std::move(f);
  return slot;
}

// ---- controllers --------------------------------------------------------------------

const std::vector<Model::Supervised>& Model::supervised(const ast::ControllerDecl& d) {
  if (auto it = supervised_.find(&d); it != supervised_.end()) return it->second;
  auto& out = supervised_[&d];
  for (const ast::SupervisedRef& r : d.behaviors) {
    const auto it = symbols_.find(r.name.text);
    if (it != symbols_.end() && it->second.kind == DeclKind::Library) {
      const auto* lib = static_cast<const ast::LibraryDecl*>(it->second.decl);
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
        const auto mt = symbols_.find(m);
        if (mt == symbols_.end() || mt->second.kind != DeclKind::Behavior || mt->second.head->poisoned) {
          supervised_failed_.insert(&d);
          continue;
        }
        out.push_back({&r, static_cast<const ast::BehaviorDecl*>(mt->second.decl)});
      }
      continue;
    }
    const Symbol* s = lookup(r.name, DeclKind::Behavior);
    if (s == nullptr) {
      supervised_failed_.insert(&d);
      continue;
    }
    out.push_back({&r, static_cast<const ast::BehaviorDecl*>(s->decl)});
  }
  return out;
}

const std::optional<control::ControllerSpec>& Model::controller(const ast::ControllerDecl& d) {
  if (auto it = controllers_.find(&d); it != controllers_.end()) return it->second;
  auto& slot = controllers_[&d];
  if (d.poisoned) return slot;
  const int errors = sink_.errors();
  control::ControllerSpec c;
  c.name = d.name.text;
  c.head = d.supervisor ? control::Head::Supervisor : d.symbolic ? control::Head::Symbolic : control::Head::Classical;
  c.mlp.kind = d.elman ? control::NetworkKind::Elman : control::NetworkKind::Mlp;
  const bool chooses = d.symbolic || d.supervisor;   // no `wheels` output
  auto& used = controller_behaviors_[&d];
  used.clear();

  const std::vector<std::string> observables = expr::observable_names();
  for (const ast::Input& in : d.inputs) {
    const auto o = expr::find_observable(in.name.text);
    if (!o) {
      std::string msg = fmt::format("unknown input `{}`", in.name.text);
      const auto best = closest(in.name.text, observables);
      if (best) msg += fmt::format("; did you mean `{}`?", *best);
      Diagnostic& diag = sink_.error(in.name.where, msg);
      if (!best) diag.help.push_back("inputs are observables, such as `ir[0..7]`, `speed` or `wheels[0]`");
      continue;
    }
    if (!in.lo) {
      for (expr::Slot i = 0; i < o->count; ++i) c.mlp.inputs.push_back(o->first + i);
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
  }

  bool has_wheels = false;
  const std::vector<std::string> layer_words = {"hidden", "wheels"};
  for (std::size_t i = 0; i < d.layers.size(); ++i) {
    const ast::Layer& l = d.layers[i];
    if (l.word.text == "hidden") {
      if (!l.size) {
        sink_.error(l.where, "a hidden layer needs a size").help.push_back("write `hidden 20`");
        continue;
      }
      if (const auto n = to_whole(*l.size, "a hidden layer's size", 1, 100000, sink_)) c.mlp.hidden.push_back(static_cast<int>(*n));
    } else if (l.word.text == "wheels") {
      if (l.size) sink_.error(l.size->where, "the `wheels` output takes no size: it is always 2 wheel commands");
      if (d.symbolic) {
        sink_.error(l.where, "a symbolic controller's network has no `wheels` output: its outputs choose among the actions")
            .help.push_back("write `symbolic(mlp(ir[0..7] -> hidden 14), actions [forward, left, right])`");
      } else if (d.supervisor) {
        sink_.error(l.where, "a supervisor's network has no `wheels` output: its outputs choose among the behaviors")
            .help.push_back("write `supervisor(elman(ir[0..7] -> hidden 5), behaviors [forward(0.5), left(0.3)])`");
      } else if (i + 1 != d.layers.size()) {
        sink_.error(l.where, "`wheels` must be the last layer");
      }
      has_wheels = true;
    } else if (!l.word.text.empty()) {
      std::string msg = fmt::format("unknown layer `{}`", l.word.text);
      const auto best = closest(l.word.text, layer_words);
      if (best) msg += fmt::format("; did you mean `{}`?", *best);
      Diagnostic& diag = sink_.error(l.word.where, msg);
      if (!best) diag.help.push_back("layers are `hidden N` and, last, `wheels`");
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
    const Symbol* s = lookup(a, DeclKind::Behavior);
    if (s == nullptr) continue;
    const auto* bd = static_cast<const ast::BehaviorDecl*>(s->decl);
    if (bd->evolved) {
      sink_.error(a.where, fmt::format("`{}` is an evolved controller: it can be a supervisor's behavior, not a "
                                       "symbolic controller's action", a.text))
          .notes.emplace_back(bd->name.where, fmt::format("`{}` is declared here", a.text));
      continue;
    }
    const auto& b = behavior(*bd);
    if (b) {
      c.actions.push_back(*b);
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
      const auto& e = evolved(*bd);
      if (!e) {
        behaviors_ok = false;
        continue;
      }
      const auto& sub = controller(*e->controller);   // null while in a cycle (reported)
      if (!sub) {
        behaviors_ok = false;
        continue;
      }
      if (sub->is_tree()) {
        sink_.error(r.where, fmt::format("`{}` is evolved by tree controller `{}`: evolved trees cannot be "
                                              "supervised yet, only evolved networks", bd->name.text, sub->name))
            .notes.emplace_back(bd->name.where, fmt::format("`{}` is declared here", bd->name.text));
        behaviors_ok = false;
        continue;
      }
      c.behaviors.push_back({name, control::FixedController{
                                              std::make_shared<const control::ControllerSpec>(*sub), {}}});
      continue;
    }
    const auto& b = behavior(*bd);
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
    used.push_back(bd);
  }
  if (!d.tree && c.mlp.inputs.empty() && sink_.errors() == errors)
    sink_.error(d.kind_where, "a controller needs at least one input");
  if (d.tree && sink_.errors() == errors && c.actions.size() == d.actions.size() && behaviors_ok && !lower_tree(d, c))
    behaviors_ok = false;
  if (sink_.errors() == errors && c.actions.size() == d.actions.size() && behaviors_ok) slot = std::move(c);
  return slot;
}

bool Model::bind_behaviors(control::ControllerSpec& c, const ast::ControllerDecl& d, const ast::ArenaDecl& arena) {
  const auto it = controller_behaviors_.find(&d);
  if (it == controller_behaviors_.end()) return true;
  const auto& decls = it->second;
  bool ok = true;
  std::size_t k = 0;
  auto rebind = [&](control::Behavior& b) {
    if (k >= decls.size()) return;
    const auto& bound = behavior(*decls[k++], &arena);
    if (bound) b = *bound;
    else ok = false;
  };
  for (control::Behavior& b : c.actions) rebind(b);
  for (control::SupervisedBehavior& s : c.behaviors)
    if (auto* call = std::get_if<control::BehaviorCall>(&s.what)) rebind(call->behavior);
  return ok;
}

}  // namespace esc::compiler
