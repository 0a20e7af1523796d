// Arenas: the items of an `arena` block -> sim::ArenaSpec, checked by the runtime's rules.
#include "compiler/lower_arena.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "compiler/arena_settings.hpp"
#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/rule_messages.hpp"

namespace esc::compiler {

void ArenaLowering::read_obstacles(const ast::ArenaDecl& d, LoweredArena& a) {
  for (const ast::Cylinder& c : d.cylinders) {
    const auto x = to_si(c.x, Dim::Length, sink_), y = to_si(c.y, Dim::Length, sink_),
               r = to_si(c.radius, Dim::Length, sink_);
    if (!x || !y || !r) continue;
    a.spec.cylinders.push_back({{*x, *y}, *r});
    a.cylinders.push_back(&c);
  }
  for (const ast::Block& b : d.blocks) {
    const auto x = to_si(b.x, Dim::Length, sink_), y = to_si(b.y, Dim::Length, sink_),
               w = to_si(b.w, Dim::Length, sink_), h = to_si(b.h, Dim::Length, sink_);
    std::optional<double> angle = 0.0;
    if (b.angle) angle = to_si(*b.angle, Dim::Angle, sink_);
    if (!x || !y || !w || !h || !angle) continue;
    a.spec.boxes.push_back({{*x, *y}, {*w, *h}, *angle});
    a.blocks.push_back(&b);
  }
  for (const ast::Wall& w : d.walls) {
    const auto x1 = to_si(w.x1, Dim::Length, sink_), y1 = to_si(w.y1, Dim::Length, sink_),
               x2 = to_si(w.x2, Dim::Length, sink_), y2 = to_si(w.y2, Dim::Length, sink_);
    std::optional<double> thickness = sim::kDefaultWallThickness_m;
    if (w.thickness) thickness = to_si(*w.thickness, Dim::Length, sink_);
    if (!x1 || !y1 || !x2 || !y2 || !thickness) continue;
    a.spec.walls.push_back({{*x1, *y1}, {*x2, *y2}, *thickness});
    a.walls.push_back(&w);
  }
}

void ArenaLowering::read_goal(const ast::ArenaDecl& d, LoweredArena& a) {
  for (std::size_t i = 1; i < d.goals.size(); ++i)
    sink_.error(d.goals[i].where, "the arena's goal is already given")
        .notes.emplace_back(d.goals[0].where, "first given here");
  if (d.goals.empty()) return;
  const auto x = to_si(d.goals[0].x, Dim::Length, sink_), y = to_si(d.goals[0].y, Dim::Length, sink_);
  if (x && y) a.spec.goal = sim::Vec2{*x, *y};
}

void ArenaLowering::read_zones(const ast::ArenaDecl& d, LoweredArena& a,
                               std::map<std::string, std::size_t>& zone_index) {
  std::map<std::string, const ast::Zone*> declared;
  for (const ast::Zone& z : d.zones) {
    if (!z.name.text.empty() && !declared.try_emplace(z.name.text, &z).second) {
      sink_.error(z.name.where, fmt::format("zone `{}` is already declared in this arena", z.name.text))
          .notes.emplace_back(declared[z.name.text]->name.where, "first declared here");
      continue;
    }
    sim::Zone k;
    k.shape = z.circle ? sim::ZoneShape::Circle : sim::ZoneShape::Rectangle;
    if (z.circle) {
      const auto r = to_si(z.radius, Dim::Length, sink_);
      if (!r) continue;
      k.radius_m = *r;
    } else {
      const auto w = to_si(z.w, Dim::Length, sink_), h = to_si(z.h, Dim::Length, sink_);
      if (!w || !h) continue;
      k.size_m = {*w, *h};
    }
    bool visibility_given = false;
    std::set<std::string> flags;
    for (const ast::Name& f : z.flags) {
      if (!flags.insert(f.text).second) {
        sink_.error(f.where, fmt::format("`{}` is already given for this zone", f.text));
        continue;
      }
      if (f.text == "recharge") {
        k.recharge = true;
      } else {
        if (visibility_given) sink_.error(f.where, "a zone is either `visible` or `invisible`");
        visibility_given = true;
        k.visible = f.text == "visible";
      }
    }
    if (z.random) {
      k.random_position = true;
      k.center_m = {a.spec.width_m / 2, a.spec.height_m / 2};
    } else {
      const auto x = to_si(z.x, Dim::Length, sink_), y = to_si(z.y, Dim::Length, sink_);
      if (!x || !y) continue;
      k.center_m = {*x, *y};
    }
    zone_index[z.name.text] = a.spec.zones.size();
    a.spec.zones.push_back(k);
    a.zones.push_back(&z);
  }
}

void ArenaLowering::read_lights(const ast::ArenaDecl& d, LoweredArena& a,
                                const std::map<std::string, std::size_t>& zone_index) {
  std::set<std::string> declared;
  for (const ast::Light& l : d.lights) {
    if (!l.name.text.empty() && !declared.insert(l.name.text).second) {
      sink_.error(l.name.where, fmt::format("light `{}` is already declared in this arena", l.name.text));
      continue;
    }
    sim::LightSource k;
    if (l.height) {
      const auto h = to_si(*l.height, Dim::Length, sink_);
      if (!h) continue;
      k.height_m = *h;
    }
    if (l.intensity) {
      const auto v = to_si(*l.intensity, Dim::None, sink_);
      if (!v) continue;
      k.intensity = *v;
    }
    if (l.above) {
      const auto it = zone_index.find(l.above->text);
      if (it == zone_index.end()) {
        if (std::none_of(d.zones.begin(), d.zones.end(),
                         [&](const ast::Zone& z) { return z.name.text == l.above->text; })) {
          std::vector<std::string> zones;
          for (const ast::Zone& z : d.zones) zones.push_back(z.name.text);
          suggest(
              sink_.error(l.above->where, fmt::format("unknown zone `{}` in arena `{}`", l.above->text, d.name.text)),
              l.above->text, zones);
        }
        continue;   // or the zone is wrong itself (reported)
      }
      k.above_zone = static_cast<int>(it->second);
      k.position_m = a.spec.zones[it->second].center_m;
    } else if (l.x && l.y) {
      const auto x = to_si(*l.x, Dim::Length, sink_), y = to_si(*l.y, Dim::Length, sink_);
      if (!x || !y) continue;
      k.position_m = {*x, *y};
    }
    a.spec.lights.push_back(k);
    a.lights.push_back(&l);
  }
}

const std::optional<LoweredArena>& ArenaLowering::lower(const ast::ArenaDecl& d) {
  if (auto it = arenas_.find(&d); it != arenas_.end()) return it->second;
  auto& slot = arenas_[&d];
  if (d.poisoned) return slot;
  const int errors = sink_.errors();
  LoweredArena a;
  a.spec.boxes.clear();
  a.spec.cylinders.clear();

  if (d.sizes.empty())
    sink_.error(d.name.where, fmt::format("arena `{}` has no size", d.name.text))
        .help.push_back("add `size 60cm x 60cm`");
  for (std::size_t i = 1; i < d.sizes.size(); ++i)
    sink_.error(d.sizes[i].where, "the arena's size is already given")
        .notes.emplace_back(d.sizes[0].where, "first given here");
  bool sized = false;
  if (!d.sizes.empty()) {
    const auto w = to_si(d.sizes[0].w, Dim::Length, sink_);
    const auto h = to_si(d.sizes[0].h, Dim::Length, sink_);
    if (w && h) {
      a.spec.width_m = *w;
      a.spec.height_m = *h;
      sized = true;
    }
  }
  read_obstacles(d, a);
  read_goal(d, a);
  for (std::size_t i = 1; i < d.starts.size(); ++i)
    sink_.error(d.starts[i].where, "the arena's start is already given")
        .notes.emplace_back(d.starts[0].where, "first given here");
  if (!d.starts.empty() && !d.starts[0].random) {
    const ast::Start& s = d.starts[0];
    const auto x = to_si(s.x, Dim::Length, sink_), y = to_si(s.y, Dim::Length, sink_);
    std::optional<double> heading = 0.0;
    if (s.heading) heading = to_si(*s.heading, Dim::Angle, sink_);
    if (x && y && heading) a.spec.fixed_start = sim::Pose{*x, *y, *heading};
  }
  std::map<std::string, std::size_t> zone_index;   // zones first: a light may stand above one
  read_zones(d, a, zone_index);
  read_lights(d, a, zone_index);
  for (const ArenaSetting& s : arena_settings()) {
    const std::vector<ast::ArenaLength>& items = d.*s.items;
    for (std::size_t i = 1; i < items.size(); ++i)
      sink_.error(items[i].where, fmt::format("the arena's `{}` is already given", s.name))
          .notes.emplace_back(items[0].where, "first given here");
    if (items.empty()) continue;
    if (const auto v = to_si(items[0].value, Dim::Length, sink_)) a.spec.*s.value = *v;
  }
  // The runtime's rules, once what the script wrote reads well (a wrong size would make
  // every part "outside").
  if (sized && sink_.errors() == errors)
    for (const sim::Problem& p : sim::arena_problems(a.spec)) {
      RuleMessage m = rule_message(p, RuleContext{&a.spec, d.name.text, nullptr});
      sink_.error(where(d, a, p), std::move(m.message)).help = std::move(m.help);
    }
  if (sink_.errors() == errors) slot = std::move(a);
  return slot;
}

SourceRange ArenaLowering::where(const ast::ArenaDecl& d, const LoweredArena& a, const sim::Problem& p) {
  const auto i = static_cast<std::size_t>(std::max(p.index, 0));
  const auto length = [&](std::string_view name) -> const std::vector<ast::ArenaLength>& {
    return d.*find_arena_setting(name)->items;
  };
  switch (p.rule) {
    case sim::Rule::ArenaWidth: return d.sizes[0].w.where;
    case sim::Rule::ArenaHeight: return d.sizes[0].h.where;
    case sim::Rule::ObstacleCount:   // counted blocks first, then cylinders, then walls
      if (i < a.blocks.size()) return a.blocks[i]->where;
      if (i - a.blocks.size() < a.cylinders.size()) return a.cylinders[i - a.blocks.size()]->where;
      return a.walls[i - a.blocks.size() - a.cylinders.size()]->where;
    case sim::Rule::BlockSize:
    case sim::Rule::BlockInside: return a.blocks[i]->where;
    case sim::Rule::CylinderRadius: return a.cylinders[i]->radius.where;
    case sim::Rule::CylinderInside: return a.cylinders[i]->where;
    case sim::Rule::WallThickness:
      if (a.walls[i]->thickness) return a.walls[i]->thickness->where;
      return a.walls[i]->where;
    case sim::Rule::WallLength:
    case sim::Rule::WallInside: return a.walls[i]->where;
    case sim::Rule::GoalInside: return d.goals[0].where;
    case sim::Rule::ZoneRadius: return a.zones[i]->radius.where;
    case sim::Rule::ZoneCount:
    case sim::Rule::ZoneSize:
    case sim::Rule::ZoneInside:
    case sim::Rule::ZoneFits: return a.zones[i]->where;
    case sim::Rule::LightHeight: return a.lights[i]->height->where;
    case sim::Rule::LightIntensity: return a.lights[i]->intensity->where;
    case sim::Rule::LightCount:
    case sim::Rule::LightZone:
    case sim::Rule::LightInside: return a.lights[i]->where;
    case sim::Rule::SweepCell: return length("sweep_cell")[0].value.where;
    case sim::Rule::SweepGrid:   // a grid too fine: the cell if the script chose it, else the size
      return length("sweep_cell").empty() ? d.sizes[0].where : length("sweep_cell")[0].where;
    case sim::Rule::ReachRadius: return length("reach_radius")[0].value.where;
    default: return d.starts.empty() ? d.name.where : d.starts[0].where;   // the start
  }
}

const ArenaNames& ArenaLowering::names(const ast::ArenaDecl& d) {
  auto [it, fresh] = names_.try_emplace(&d);
  if (fresh) {
    it->second.arena = d.name.text;
    for (const ast::Zone& z : d.zones) it->second.zones.push_back(z.name.text);
    for (const ast::Light& l : d.lights) it->second.lights.push_back(l.name.text);
  }
  return it->second;
}

bool ArenaLowering::check_placement(const ast::ArenaDecl& d, const LoweredArena& a, const sim::RobotParams& robot,
                                    const SourceRange& use) {
  const auto problems = sim::placement_problems(a.spec, robot);
  for (const sim::Problem& p : problems) {
    RuleMessage m = rule_message(p, RuleContext{&a.spec, d.name.text, &robot});
    const bool at_start = p.rule != sim::Rule::RobotFits;
    Diagnostic& diag = sink_.error(at_start ? d.starts[0].where : use, std::move(m.message));
    diag.help = std::move(m.help);
    if (at_start) diag.notes.emplace_back(use, "the robot's size comes from this experiment");
    else if (!d.sizes.empty()) diag.notes.emplace_back(d.sizes[0].where, "the arena's size is given here");
  }
  return problems.empty();
}

}  // namespace esc::compiler
