#include "runtime/eval/fingerprint.hpp"

#include "runtime/eval/settings_history.hpp"
#include "runtime/genome/tree/primitive_set.hpp"
#include "runtime/expr/observables.hpp"

#include <span>
#include <utility>
#include <variant>

#include <fmt/format.h>

namespace esc::eval {

namespace {

// A program's slot as fingerprints have always named it: the aggregates after the frame by
// the numbers they had before the navigator's observables grew the frame, and those
// observables apart (`f48`), so that stored runs keep their fingerprints and no two programs
// share one.
std::string slot_text(expr::Slot s) {
  if (s < expr::kFrameSizeBeforeNavigator) return fmt::format("{}", s);
  if (s < expr::kFrameSize) return fmt::format("f{}", s);
  return fmt::format("{}", s - expr::kFrameSize + expr::kFrameSizeBeforeNavigator);
}

class Writer {
 public:
  void line(std::string_view key, std::string_view value) { out_ += fmt::format("{} {}\n", key, value); }
  void number(std::string_view key, double v) { line(key, fmt::format("{:a}", v)); }
  void numbers(std::string_view key, std::span<const double> v) {
    std::string s;
    for (double x : v) s += fmt::format("{:a} ", x);
    line(key, s);
  }
  void program(std::string_view key, const expr::Program& p) {
    std::string s;
    for (const expr::Instr& i : p.code())
      s += fmt::format("{}:{}:{:a} ", static_cast<int>(i.op), slot_text(i.slot), i.value);
    line(key, s);
  }
  void behavior(std::string_view key, const control::Behavior& b) {
    line(key, fmt::format("{} ({})", b.name, fmt::join(b.params, ", ")));
    program(fmt::format("{}.left", key), b.left);
    program(fmt::format("{}.right", key), b.right);
  }
  void controller(const std::string& key, const control::ControllerSpec& c) {
    line(key, fmt::format("{} head {} kind {} activation {} inputs {} hidden {}", c.name, static_cast<int>(c.head),
                          static_cast<int>(c.mlp.kind), static_cast<int>(c.mlp.hidden_activation),
                          fmt::join(c.mlp.inputs, ","), fmt::join(c.mlp.hidden, ",")));
    // Only where given, so that controllers without `by` keep their fingerprints.
    if (!c.evolved_by.empty()) line(key + ".by", c.evolved_by);
    if (c.primitives)
      for (const genome::tree::Primitive& p : c.primitives->primitives())
        line(key + ".primitive",
             fmt::format("{} {} {} {} {} {} {:a} {:a} {:a} {}", p.name, static_cast<int>(p.kind), static_cast<int>(p.result),
                         static_cast<int>(p.arity), static_cast<int>(p.op), p.slot, p.value, p.lo, p.hi, p.index));
    for (std::size_t i = 0; i < c.actions.size(); ++i) behavior(fmt::format("{}.action{}", key, i), c.actions[i]);
    for (std::size_t i = 0; i < c.behaviors.size(); ++i) {
      const std::string k = fmt::format("{}.behavior{}", key, i);
      line(k, c.behaviors[i].name);
      if (const auto* call = std::get_if<control::BehaviorCall>(&c.behaviors[i].what)) {
        behavior(k + ".call", call->behavior);
        numbers(k + ".args", call->args);
      } else if (const auto* fixed = std::get_if<control::FixedController>(&c.behaviors[i].what)) {
        if (fixed->spec) controller(k + ".fixed", *fixed->spec);
        numbers(k + ".genome", fixed->genome);
      }
    }
    // Only for a controller per body, so that every other keeps its fingerprint.
    for (std::size_t i = 0; i < c.networks.size(); ++i) {
      const std::string k = fmt::format("{}.body{}", key, i);
      line(k, i < c.network_bodies.size() ? c.network_bodies[i] : std::string());
      controller(k + ".network", c.networks[i]);
    }
    if (!c.body_networks.empty()) line(key + ".body_networks", fmt::format("{}", fmt::join(c.body_networks, ",")));
  }
  [[nodiscard]] std::string text() && { return std::move(out_); }

 private:
  std::string out_;
};

}  // namespace

std::string fingerprint(const ExperimentSpec& spec) {
  Writer w;
  w.line("results_revision", std::to_string(kResultsRevision));
  for (const auto& [key, value] : spec.resolved_settings)
    if (!as_before_it_existed(key, value)) w.line("setting." + key, value);   // cache entries of older esc stay valid
  const sim::ArenaSpec& a = spec.arena;
  w.numbers("arena.size", std::initializer_list<double>{a.width_m, a.height_m, a.sweep_cell_m, a.reach_radius_m});
  for (const auto& b : a.boxes)
    w.numbers("arena.box", std::initializer_list<double>{b.center_m.x, b.center_m.y, b.size_m.x, b.size_m.y, b.angle_rad});
  for (const auto& c : a.cylinders)
    w.numbers("arena.cylinder", std::initializer_list<double>{c.center_m.x, c.center_m.y, c.radius_m});
  for (const auto& k : a.walls)
    w.numbers("arena.wall", std::initializer_list<double>{k.from_m.x, k.from_m.y, k.to_m.x, k.to_m.y, k.thickness_m});
  if (a.goal) w.numbers("arena.goal", std::initializer_list<double>{a.goal->x, a.goal->y});
  if (a.fixed_start)
    w.numbers("arena.start", std::initializer_list<double>{a.fixed_start->x_m, a.fixed_start->y_m, a.fixed_start->heading_rad});
  for (const auto& l : a.lights)
    w.numbers("arena.light", std::initializer_list<double>{l.position_m.x, l.position_m.y, l.height_m, l.intensity,
                                                           static_cast<double>(l.above_zone)});
  for (const auto& z : a.zones)
    w.numbers("arena.zone", std::initializer_list<double>{static_cast<double>(z.shape), z.center_m.x, z.center_m.y,
                                                          z.radius_m, z.size_m.x, z.size_m.y, z.visible ? 1.0 : 0.0,
                                                          z.random_position ? 1.0 : 0.0, z.recharge ? 1.0 : 0.0});
  // Only where given, so that experiments starting at random keep their fingerprints.
  if (spec.formation.kind != sim::FormationKind::Random) {
    w.line("formation", std::to_string(static_cast<int>(spec.formation.kind)));
    if (spec.formation.kind == sim::FormationKind::At)
      for (const sim::Pose& p : spec.formation.at)
        w.numbers("formation.at", std::initializer_list<double>{p.x_m, p.y_m, p.heading_rad});
    else
      w.number("formation.spacing", spec.formation.spacing_m);
  }
  // Only where read, so that experiments without clusters keep their fingerprints.
  if (!spec.cluster_radii.empty()) w.numbers("clusters.radii", spec.cluster_radii);
  // Only where given, so that fitnesses reduced by the mean keep their fingerprints.
  if (spec.fitness.over_robots != Reduction::Mean)
    w.line("fitness.over_robots", std::to_string(static_cast<int>(spec.fitness.over_robots)));
  w.program("fitness.step", spec.fitness.step);
  for (const auto& p : spec.fitness.stop_when) w.program("fitness.stop", p);
  if (spec.fitness.epoch_end) w.program("fitness.epoch", *spec.fitness.epoch_end);
  if (spec.fitness.evaluation_end) w.program("fitness.evaluation", *spec.fitness.evaluation_end);
  // Only where read, so that fitnesses without step aggregates keep their fingerprints.
  for (const auto& [key, list] : {std::pair{"fitness.epoch.aggregate", &spec.fitness.epoch_aggregates},
                                  std::pair{"fitness.evaluation.aggregate", &spec.fitness.evaluation_aggregates}})
    for (const expr::StepAggregate& folded : *list) {
      w.line(key, fmt::format("{} {} {}", static_cast<int>(folded.kind), folded.sample, folded.samples));
      w.program(key, folded.of);
    }
  for (std::size_t i = 0; i < spec.controllers.size(); ++i)
    w.controller(fmt::format("controller{}", i), spec.controllers[i]);
  if (spec.start_from)
    for (std::size_t c = 0; c < spec.start_from->genomes.size(); ++c)
      for (std::size_t r = 0; r < spec.start_from->genomes[c].size(); ++r)
        w.numbers(fmt::format("start.{}.{}", c, r), spec.start_from->genomes[c][r].genome);
  return std::move(w).text();
}

}  // namespace esc::eval
