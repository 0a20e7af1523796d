#include "compiler/sensor_uses.hpp"

#include <algorithm>
#include <tuple>
#include <variant>

#include <fmt/format.h>

#include "compiler/robot_settings.hpp"
#include "runtime/genome/tree/primitive_set.hpp"

namespace esc::compiler {

namespace {

// `range[3]`, `goal_distance`: the slot as scripts name it.
std::string slot_name(expr::Slot slot) {
  return expr::observable_name(slot).value_or(fmt::format("slot {}", slot));
}

// "the robot of experiment `maze`".
std::string robot_of(const Navigation& n) {
  return n.body.empty() ? fmt::format("the robot of experiment `{}`", n.experiment)
                        : fmt::format("body `{}` of experiment `{}`'s group", n.body, n.experiment);
}

// `range[i]` or `radar[i]` beyond the `count` sensors the robot has: what it reads (named as
// the robot names the array: `prox_ground[2]` on the Thymio II) and how many there are.
RuleMessage beyond(expr::Slot slot, expr::Slot first, int count, const Navigation& n, std::string_view what,
                   std::string_view array, std::string_view declare) {
  const expr::Slot i = slot - first;
  if (count == 0)
    return {fmt::format("`{}[{}]` reads {} {}, but {} has none", array, i, what, i, robot_of(n)),
            {fmt::format("declare them in the robot's settings: `{}`", declare)}};
  return {fmt::format("`{}[{}]` reads {} {}, but {} has {} (`{}[0]` .. `{}[{}]`)", array, i, what, i, robot_of(n),
                      count, array, array, count - 1),
          {}};
}

void add_program(std::set<expr::Slot>& out, const expr::Program& p) {
  for (const expr::Instr& in : p.code())
    if (in.op == expr::Op::Load) out.insert(in.slot);
}

void add_behavior(std::set<expr::Slot>& out, const control::Behavior& b) {
  add_program(out, b.left);
  add_program(out, b.right);
}

}  // namespace

namespace {

Navigation navigation_of(const eval::ExperimentSpec& x, const sim::RobotParams& r, std::string body) {
  return {x.name,
          x.arena_name,
          std::move(body),
          x.arena.goal.has_value(),
          static_cast<int>(r.rangefinders.angles_rad.size()),
          r.radars,
          static_cast<int>(r.ir.mounts.size()),
          static_cast<int>(r.ground.mounts.size()),
          static_cast<int>(r.bumpers.size()),
          {{"ir", r.ir.name}, {"ground_sensor", r.ground.name}}};
}

}  // namespace

Navigation navigation_of(const eval::ExperimentSpec& x) { return navigation_of(x, x.robot, {}); }

Navigation navigation_of(const eval::ExperimentSpec& x, std::size_t body) {
  if (body == 0 || body >= x.bodies.size()) return navigation_of(x, x.robot, x.bodies.empty() ? std::string() : x.bodies[0].name);
  return navigation_of(x, x.bodies[body].params, x.bodies[body].name);
}

std::string_view Navigation::name_of(std::string_view observable) const {
  const auto it = names.find(observable);
  return it == names.end() ? observable : std::string_view(it->second);
}

namespace {

// The renamable array `name` reads under one of its names, or null.
const RenamableSensors* renamable(std::string_view name, const SensorNames* names) {
  std::string_view observable = name;
  if (names != nullptr)
    if (const auto it = names->find(name); it != names->end()) observable = it->second;
  for (const RenamableSensors& r : kRenamableSensors)
    if (r.observable == observable) return &r;
  return nullptr;
}

}  // namespace

std::optional<expr::Observable> find_observable(std::string_view name, const SensorNames* names) {
  if (const RenamableSensors* r = renamable(name, names)) return expr::find_observable(r->observable);
  return expr::find_observable(name);
}

std::optional<RuleMessage> misnamed(std::string_view name, const Navigation& n, const SensorNames* names) {
  const RenamableSensors* r = renamable(name, names);
  if (r == nullptr) return std::nullopt;
  const std::string_view own = n.name_of(r->observable);
  if (name == own) return std::nullopt;
  return RuleMessage{fmt::format("`{}` names {}, but {} calls its {} `{}`", name, r->what, robot_of(n), r->what, own),
                     {fmt::format("a controller written for another body: read `{}[i]` on this one, or run it on a "
                                  "robot with `{} {}`",
                                  own, r->setting, name)}};
}

std::optional<RuleMessage> unavailable(expr::Slot slot, const Navigation& n) {
  const bool radar = slot >= expr::slot::radar && slot < expr::slot::radar + expr::kRadarCount;
  if ((slot == expr::slot::goal_distance || radar) && !n.goal)
    return RuleMessage{fmt::format("`{}` needs the arena's goal, but arena `{}` has none", slot_name(slot), n.arena),
                       {fmt::format("add `goal at (X, Y)` to arena `{}`", n.arena)}};
  if (radar && static_cast<int>(slot - expr::slot::radar) >= n.radars)
    return beyond(slot, expr::slot::radar, n.radars, n, "goal radar", "radar", "radars 4");
  if (slot >= expr::slot::range && slot < expr::slot::range + expr::kRangeCount &&
      static_cast<int>(slot - expr::slot::range) >= n.rangefinders)
    return beyond(slot, expr::slot::range, n.rangefinders, n, "rangefinder", "range",
                  "rangefinders [90deg, 45deg, 0deg, -45deg, -90deg, 180deg]");
  // The light sensors are the IR sensors in passive mode: as many, at the same mounts.
  for (const auto& [first, what, array] : {std::tuple{expr::slot::ir, "IR sensor", n.name_of("ir")},
                                          std::tuple{expr::slot::light, "light sensor", std::string_view("light")}})
    if (slot >= first && slot < first + expr::kIrCount && static_cast<int>(slot - first) >= n.ir_sensors)
      return beyond(slot, first, n.ir_sensors, n, what, array, "ir_sensors [(68deg, 90deg), (13deg, 10deg)]");
  if (slot >= expr::slot::ground_sensor && slot < expr::slot::ground_sensor + expr::kGroundSensorCount &&
      static_cast<int>(slot - expr::slot::ground_sensor) >= n.ground_sensors)
    // Mounts within every shipped body's radius (the Thymio's own, 7.3 cm out, would sit outside
    // a Khepera), so that the help can be taken as it is.
    return beyond(slot, expr::slot::ground_sensor, n.ground_sensors, n, "ground sensor", n.name_of("ground_sensor"),
                  "ground_sensors [(9deg, 2cm), (-9deg, 2cm)]");
  if (slot >= expr::slot::bumper && slot < expr::slot::bumper + expr::kBumperCount &&
      static_cast<int>(slot - expr::slot::bumper) >= n.bumpers)
    return beyond(slot, expr::slot::bumper, n.bumpers, n, "bumper", "bumper", "bumpers [(-45deg, 45deg)]");
  return std::nullopt;
}

std::set<expr::Slot> slots_read(const eval::FitnessSpec& f) {
  std::set<expr::Slot> out;
  add_program(out, f.step);
  for (const expr::Program& p : f.stop_when) add_program(out, p);
  for (const auto* end : {&f.epoch_end, &f.evaluation_end})
    if (*end) add_program(out, **end);
  for (const auto* folded : {&f.epoch_aggregates, &f.evaluation_aggregates})
    for (const expr::StepAggregate& a : *folded) add_program(out, a.of);
  return out;
}

std::set<expr::Slot> slots_read_by_measures(const eval::ExperimentSpec& x) {
  std::set<expr::Slot> out = slots_read(x.fitness);
  for (const eval::FitnessSpec& f : x.further) out.merge(slots_read(f));
  for (const eval::DescriptorSpec& d : x.descriptors) {
    add_program(out, d.program);
    for (const expr::StepAggregate& a : d.aggregates) add_program(out, a.of);
  }
  return out;
}

std::set<expr::Slot> slots_read(const control::ControllerSpec& c) {
  std::set<expr::Slot> out(c.mlp.inputs.begin(), c.mlp.inputs.end());
  for (const control::Behavior& a : c.actions) add_behavior(out, a);
  for (const control::SupervisedBehavior& b : c.behaviors) {
    if (const auto* call = std::get_if<control::BehaviorCall>(&b.what)) {
      add_behavior(out, call->behavior);
    } else if (const auto& fixed = std::get<control::FixedController>(b.what); fixed.spec != nullptr) {
      const std::set<expr::Slot> inner = slots_read(*fixed.spec);
      out.insert(inner.begin(), inner.end());
    }
  }
  if (c.primitives)
    for (const genome::tree::Primitive& p : c.primitives->primitives())
      if (p.kind == genome::tree::Kind::Observable) out.insert(p.slot);
  return out;
}

std::optional<RuleMessage> unreadable_on_bodies(const eval::ExperimentSpec& x) {
  const std::set<expr::Slot> measures = slots_read_by_measures(x);
  std::set<expr::Slot> every_body;
  for (const control::ControllerSpec& c : x.controllers)
    if (!c.per_body()) every_body.merge(slots_read(c));
  const Navigation first = navigation_of(x, 0);
  for (std::size_t b = 0; b < std::max<std::size_t>(x.bodies.size(), 1); ++b) {
    // The first body unnamed, as a robot alone is.
    const Navigation n = b == 0 ? navigation_of(x) : navigation_of(x, b);
    for (const expr::Slot s : measures) {
      // Names first: a slot read by another name is that, whatever its count.
      for (const RenamableSensors& r : kRenamableSensors) {
        const std::optional<expr::Observable> o = expr::find_observable(r.observable);
        if (!o || s < o->first || s >= o->first + o->count || first.name_of(r.observable) == n.name_of(r.observable))
          continue;
        return RuleMessage{
            fmt::format("the experiment's measures read the {}, which `{}` calls `{}` and `{}` `{}`: one program "
                        "cannot read both",
                        r.what, first.body, first.name_of(r.observable), n.body, n.name_of(r.observable)),
            {fmt::format("measure the group by what every body reads alike, or give the bodies one name (`{}`)",
                         r.setting)}};
      }
      if (auto m = unavailable(s, n)) {
        if (b == 0) return m;
        m->message = "the experiment's measures read what a body of its group lacks: " + m->message;
        m->help.push_back("a fitness, objective or descriptor is read on every robot: give it what every body reads");
        return m;
      }
    }
    std::set<expr::Slot> controllers = every_body;
    for (const control::ControllerSpec& c : x.controllers)
      if (c.per_body() && b < c.body_networks.size()) controllers.merge(slots_read(c.networks.at(c.body_networks[b])));
    for (const expr::Slot s : controllers)
      if (auto m = unavailable(s, n)) return m;
  }
  return std::nullopt;
}

}  // namespace esc::compiler
