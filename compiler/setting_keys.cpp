#include "compiler/setting_keys.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>

#include <optional>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compiler/algorithm_options.hpp"
#include "compiler/arena_settings.hpp"
#include "compiler/compiler.hpp"
#include "compiler/experiment_settings.hpp"
#include "compiler/lower_evolution.hpp"
#include "compiler/names.hpp"
#include "compiler/robot_settings.hpp"
#include "compiler/rule_messages.hpp"
#include "compiler/sensor_uses.hpp"
#include "compiler/setting_values.hpp"
#include "compiler/text.hpp"
#include "runtime/sim/validate.hpp"
#include "runtime/sim/world.hpp"

namespace esc::compiler {

namespace {

std::vector<std::string> prefixed(std::string_view prefix, const std::vector<std::string>& names) {
  std::vector<std::string> v;
  for (const std::string& n : names) v.push_back(std::string(prefix) + n);
  return v;
}

// "unknown robot setting `robot.x`; did you mean `robot.y`?", listing the group's keys;
// `word` is the key without the group's prefix, `scope` what the script wrote before the key
// (`energy.` for a setting of a dependency), shown in the message and the suggestion.
void unknown(Sink& sink, const ast::Name& key, std::string_view what, std::string_view word, std::string_view prefix,
             const std::vector<std::string>& names, std::string_view scope) {
  const std::string shown = std::string(scope) + std::string(prefix);
  suggest(sink.error(key.where, fmt::format("unknown {} `{}{}`", what, scope, key.text)), word, names,
          {.prefix = shown, .otherwise = fmt::format("{}s: {}", what, fmt::join(prefixed(prefix, names), ", ")),
           .always = true});
}

void report(Sink& sink, const std::vector<sim::Problem>& problems, const RuleContext& context,
            const SourceRange& where) {
  for (const sim::Problem& p : problems) {
    RuleMessage m = rule_message(p, context);
    sink.error(where, std::move(m.message)).help = std::move(m.help);
  }
}

// "message (help; help)" for each error, joined: the one line `esc run` prints.
std::string flattened(const std::vector<Diagnostic>& ds) {
  std::string out;
  for (const Diagnostic& d : ds) {
    if (d.severity != Severity::Error) continue;
    if (!out.empty()) out += "; ";
    out += d.message;
    if (!d.help.empty()) out += fmt::format(" ({})", fmt::join(d.help, "; "));
  }
  return out;
}

// `key` without its group's prefix, when it is in `group`.
std::optional<std::string_view> in_group(std::string_view key, std::string_view group) {
  if (!key.starts_with(group)) return std::nullopt;
  return key.substr(group.size());
}

// `key` without algorithm a's group (`cmaes.`), when it is one of a's keys or, for a group of
// its own, names it (an unknown key of a group is reported as that group's).
std::optional<std::string_view> algorithm_key(const AlgorithmOptions& a, std::string_view key) {
  const auto name = in_group(key, a.group);
  if (!name || (a.group.empty() && !a.has_key(*name))) return std::nullopt;
  return name;
}

// "body 2 of the group (`lit`): ", before a message about body i of a group of several.
std::string body_label(const eval::ExperimentSpec& spec, std::size_t i) {
  return fmt::format("body {} of the group (`{}`): ", i + 1, spec.bodies[i].name);
}

// Body i's problems (0: the first body, `robot`), reported as the first's are, a further
// body's named; true when there are none.
bool report_body(const eval::ExperimentSpec& spec, std::size_t i, const std::vector<sim::Problem>& problems,
                 const SourceRange& where, Sink& sink) {
  const sim::RobotParams& body = i == 0 ? spec.robot : spec.bodies[i].params;
  const std::size_t before = sink.items().size();
  report(sink, problems, {&spec.arena, spec.arena_name, &body}, where);
  if (i > 0)
    for (std::size_t k = before; k < sink.items().size(); ++k)
      sink.items()[k].message = body_label(spec, i) + sink.items()[k].message;
  return problems.empty();
}

// Setting `s` of body i of the group (ExperimentSpec::bodies), its mistakes named by the body.
bool apply_to_body(eval::ExperimentSpec& spec, std::size_t i, const RobotSetting& s, const ast::Value& value,
                   Sink& sink) {
  Sink body;
  if (apply_robot_value(s, value, spec.bodies[i].params, body)) return true;
  for (Diagnostic& d : body.items()) sink.error(d.where, body_label(spec, i) + d.message).help = std::move(d.help);
  return false;
}

// `body2.KEY`: body 2 of the group alone; `body1.KEY`, the first (`robot`, whose copy the
// group's list holds too).
bool set_one_body(eval::ExperimentSpec& spec, const ast::Name& key, const BodyKey& body, const RobotSetting& s,
                  const ast::Value& value, Sink& sink, std::string_view scope) {
  const std::size_t bodies = std::max<std::size_t>(spec.bodies.size(), 1);
  if (body.leading_zero) {
    sink.error(key.where, fmt::format("`{}{}`: a body's number is written without leading zeros", scope, key.text))
        .help.push_back(fmt::format("write `{}body{}.{}`", scope, body.body + 1, body.name));
    return false;
  }
  if (body.body >= bodies) {
    std::vector<std::string> names;
    for (const eval::ExperimentSpec::GroupBody& b : spec.bodies) names.push_back(fmt::format("`{}`", b.name));
    Diagnostic& d = sink.error(
        key.where, bodies == 1 ? fmt::format("`{}{}`: the robots of experiment `{}` have one body", scope, key.text,
                                             spec.name)
                               : fmt::format("`{}{}`: the group of experiment `{}` has {} bodies ({}), `body1` to "
                                             "`body{}`",
                                             scope, key.text, spec.name, bodies, fmt::join(names, ", "), bodies));
    d.help.push_back(fmt::format("set every body's as `{}robot.{}`", scope, body.name));
    return false;
  }
  if (body.body > 0) return apply_to_body(spec, body.body, s, value, sink);
  if (!apply_robot_value(s, value, spec.robot, sink)) return false;
  if (!spec.bodies.empty()) spec.bodies[0].params = spec.robot;
  return true;
}

}  // namespace

std::string trimmed(std::string_view t) {
  while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
  while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.remove_suffix(1);
  return std::string(t);
}

std::vector<std::string> setting_keys() {
  std::vector<std::string> k;
  for (const ExperimentSetting& s : experiment_settings()) k.emplace_back(s.key);
  // The bare keys (the ES's), the arena's and the robot's, then every algorithm's group.
  for (const AlgorithmOptions& a : algorithm_options())
    if (a.group.empty()) {
      const auto keys = a.keys();
      k.insert(k.end(), keys.begin(), keys.end());
    }
  for (const auto& group : {prefixed(kArenaGroup, arena_setting_names()), prefixed(kRobotGroup, robot_setting_names())})
    k.insert(k.end(), group.begin(), group.end());
  for (const AlgorithmOptions& a : algorithm_options())
    if (!a.group.empty()) {
      const auto keys = prefixed(a.group, a.keys());
      k.insert(k.end(), keys.begin(), keys.end());
    }
  return k;
}

bool is_body_group(std::string_view word) {
  return word.size() > 4 && word.starts_with("body") &&
         std::all_of(word.begin() + 4, word.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

std::optional<BodyKey> body_key(std::string_view key) {
  const std::size_t dot = key.find('.');
  // A number of more digits than any group has bodies is no body's (and would not fit).
  if (dot == std::string_view::npos || dot > 4 + 6 || !is_body_group(key.substr(0, dot))) return std::nullopt;
  const std::size_t number = std::stoul(std::string(key.substr(4, dot - 4)));
  if (number == 0) return std::nullopt;
  return BodyKey{number - 1, key.substr(dot + 1), key[4] == '0'};
}

std::optional<RuleMessage> overlapping_keys(std::string_view a, std::string_view b) {
  for (const auto& [all, one] : {std::pair{a, b}, std::pair{b, a}}) {
    const auto name = in_group(all, kRobotGroup);
    const auto body = body_key(one);
    // A body misspelt (`body02`) is said as such where it is set.
    if (name && body && !body->leading_zero && *name == body->name)
      return RuleMessage{fmt::format("`{}` sets every body of the group and `{}` one of them: one would silently "
                                     "override the other",
                                     all, one),
                         {fmt::format("give `{}` alone, or a value for each body (`body1.{}`, `body2.{}`, ...)", all,
                                      *name, *name)}};
  }
  return std::nullopt;
}

bool is_setting_group(std::string_view word) {
  for (const std::string_view group : {kRobotGroup, kArenaGroup})
    if (group.substr(0, group.size() - 1) == word) return true;
  if (is_body_group(word)) return true;
  const AlgorithmOptions* a = find_algorithm_options(word);
  return a != nullptr && !a->group.empty();
}

bool setting_takes_range(std::string_view key) {
  for (const AlgorithmOptions& a : algorithm_options())
    if (const auto name = algorithm_key(a, key)) return a.takes_range(*name);
  return false;
}

bool set_setting(eval::ExperimentSpec& spec, const ast::Name& key, const ast::Value& value, Sink& sink,
                 std::string_view scope) {
  const std::string& k = key.text;
  if (const ExperimentSetting* s = find_experiment_setting(k)) return s->read(*s, spec, value, sink);
  for (const AlgorithmOptions& a : algorithm_options()) {
    const auto name = algorithm_key(a, k);
    if (!name) continue;
    if (!a.has_key(*name)) {
      unknown(sink, key, fmt::format("{} setting", a.what), *name, a.group, a.keys(), scope);
      return false;
    }
    // Settings only the script gives (GP's) are checked and dropped where there are none: the
    // experiments an experiment's evolved behaviors come from get the same `--set`.
    if (a.scope == evo::SettingsScope::Given && a.held_by(spec) == nullptr) {
      std::any scratch = a.defaults();
      return a.set(scratch, *name, value, sink);
    }
    // Kept even where the algorithm evolves nothing yet: `--set networks=cmaes` may follow.
    return a.set(a.settings_in(spec), *name, value, sink);
  }
  // `robot.KEY`, every body of a group alike; `body2.KEY`, one body alone.
  const std::optional<BodyKey> body = body_key(k);
  if (const auto name = body ? std::optional(body->name) : in_group(k, kRobotGroup)) {
    const std::string_view group = std::string_view(k).substr(0, k.size() - name->size());
    const RobotSetting* s = find_robot_setting(*name);
    if (s == nullptr) {
      unknown(sink, key, "robot setting", *name, group, robot_setting_names(), scope);
      return false;
    }
    if (!s->settable_later()) {
      sink.error(key.where, fmt::format("`{}{}` names the robot's sensors in scripts, which are resolved when the "
                                        "script compiles: it is set in a robot block, not with --set",
                                        scope, k))
          .help.push_back(fmt::format("declare `robot r = khepera {{ {} ... }}` and use it", *name));
      return false;
    }
    if (body) return set_one_body(spec, key, *body, *s, value, sink, scope);
    // Every body of a group alike (a study's `robot.time_constant` is the robots'): bodies of
    // other shapes take the one value too. A body the value does not suit is named.
    if (!apply_robot_value(*s, value, spec.robot, sink)) return false;
    bool ok = true;
    for (std::size_t i = 0; i < spec.bodies.size(); ++i) ok = apply_to_body(spec, i, *s, value, sink) && ok;
    return ok;
  }
  if (const auto name = in_group(k, kArenaGroup)) {
    const ArenaSetting* s = find_arena_setting(*name);
    if (s == nullptr) {
      unknown(sink, key, "arena setting", *name, kArenaGroup, arena_setting_names(), scope);
      return false;
    }
    const auto v = read_quantity(value, s->name, Dim::Length, sink);
    if (v) spec.arena.*s->value = *v;
    return v.has_value();
  }
  // Every key may be the one meant, but the help line names the plain keys and the groups
  // only: the hundred keys in full made a message no one reads (a mistyped key of a group
  // lists that group's keys, above).
  std::vector<std::string> plain, groups;
  for (const std::string& s : setting_keys()) {
    const std::size_t dot = s.find('.');
    if (dot == std::string::npos) plain.push_back(s);
    else if (const std::string g = s.substr(0, dot + 1) + "*"; std::find(groups.begin(), groups.end(), g) == groups.end())
      groups.push_back(g);
  }
  groups.emplace_back("bodyN.* (body N of a group alone)");
  suggest(sink.error(key.where, fmt::format("unknown setting `{}{}`", scope, k)), k, setting_keys(),
          {.prefix = scope,
           .otherwise = fmt::format("settings: {}; and the groups {}", fmt::join(plain, ", "), fmt::join(groups, ", "))});
  return false;
}

namespace {

void check_roles(const eval::ExperimentSpec& spec, const SourceRange& where, Sink& sink) {
  if (spec.roles == 1) return;
  if (spec.roles > spec.robots) {
    sink.error(where, fmt::format("{} roles need at least {} robots, and the group has {}", spec.roles, spec.roles,
                                  spec.robots))
        .help.push_back(spec.robots == 1     ? std::string("a robot alone has one role: make a group (`robot NAME x N`)")
                        : spec.bodies.size() > 1 ? fmt::format("use at most `roles {}`, or give the `robot` item's bodies "
                                                               "more robots",
                                                               spec.robots)
                                                 : fmt::format("use at most `roles {}`, or more robots (`robot NAME x {}`, "
                                                               "`--set robots={}`)",
                                                               spec.robots, spec.roles, spec.roles));
    return;
  }
  // A role is a slice of one vector genome: a tree or a NEAT graph has no fixed length to
  // slice, and their operators vary one individual.
  for (const control::ControllerSpec& c : spec.controllers)
    if (c.is_tree() || c.is_graph()) {
      sink.error(where, fmt::format("`{}` is a {}: roles are networks of fixed topology, whose weights make one genome "
                                    "for every role",
                                    c.name, c.is_tree() ? "tree" : "NEAT network"))
          .help.push_back("compare it in another experiment, with the clonal team (`roles 1`, the default)");
      return;
    }
  // Its networks are sliced by body already; roles within bodies are not built.
  for (const control::ControllerSpec& c : spec.controllers)
    if (c.per_body()) {
      sink.error(where, fmt::format("`{}` is a controller per body: its genome holds a network per body, not per role",
                                    c.name))
          .help.push_back("compare it with one role (`roles 1`, the default): each body's robots share its network");
      return;
    }
}

}  // namespace

void check_group(const eval::ExperimentSpec& spec, const SourceRange& where, Sink& sink, GroupItems items) {
  check_roles(spec, items.roles != nullptr ? *items.roles : where, sink);
  const SourceRange* formation = items.formation;
  std::vector<double> radii;
  for (const sim::RobotParams& r : spec.robot_params()) radii.push_back(r.body_radius_m);
  if (const std::string why = sim::formation_problem(spec.formation, spec.arena, radii, sim::kStartMargin_m);
      !why.empty()) {
    sink.error(formation != nullptr ? *formation : where, fmt::format("the group's `formation {}` cannot be taken in arena `{}`: {}",
                                  formation_words()[static_cast<std::size_t>(spec.formation.kind)], spec.arena_name, why))
        .help.push_back(spec.formation.kind == sim::FormationKind::At
                            ? "give one pose per robot, each clear of the walls, the obstacles and the others"
                            : "change the spacing, or use fewer robots or a larger arena");
    return;
  }
  if (spec.robots == 1) return;
  // A body set alone (`--set body2.control_step=0.2s`) must still agree with the first, as the
  // compiler requires of the group's list: in the world's step always, in the sensors unless
  // every compared controller has a network per body (whose reads unreadable_on_bodies checks).
  const bool per_body = std::all_of(spec.controllers.begin(), spec.controllers.end(),
                                    [](const control::ControllerSpec& c) { return c.per_body(); });
  for (std::size_t i = 1; i < spec.bodies.size(); ++i)
    if (const auto differ = group_difference(spec.robot, spec.bodies[i].params);
        differ && (!differ->sensors() || !per_body)) {
      sink.error(where, group_difference_message(*differ, spec.bodies[i].name, spec.bodies[0].name))
          .help.push_back(differ->sensors()
                              ? fmt::format("give every body the same `{}` (`robot.{}`), or compare controllers with a "
                                            "network per body (`per_body`, docs/groups.md)",
                                            differ->key, differ->key)
                              : fmt::format("give every body the same `{}`: `robot.{}`", differ->key, differ->key));
      return;
    }
  // Only robot 0 takes the arena's start; a further body must fit the arena.
  sim::ArenaSpec unplaced = spec.arena;
  unplaced.fixed_start.reset();
  for (std::size_t i = 1; i < spec.bodies.size(); ++i)
    if (!report_body(spec, i, sim::placement_problems(unplaced, spec.bodies[i].params), where, sink)) return;
  // Random starts place robot after robot by rejection: past about half the floor they jam, and
  // an epoch would fail to start hours into a run. Refused here instead, with room to spare.
  // A formation places them together, checked above.
  constexpr double kMaxCover = 0.4;
  const sim::ArenaSpec& a = spec.arena;
  double floor_m2 = a.width_m * a.height_m;
  for (const sim::BoxObstacle& b : a.boxes) floor_m2 -= b.size_m.x * b.size_m.y;
  for (const sim::CylinderObstacle& c : a.cylinders) floor_m2 -= std::numbers::pi * c.radius_m * c.radius_m;
  double discs_m2 = 0.0;
  for (const double r : radii) discs_m2 += std::numbers::pi * (r + sim::kStartMargin_m) * (r + sim::kStartMargin_m);
  const double cover = discs_m2 / std::max(floor_m2, 1e-12);
  if (cover > kMaxCover && spec.formation.kind == sim::FormationKind::Random) {
    const auto [small, large] = std::minmax_element(radii.begin(), radii.end());
    const std::string sizes = *small == *large ? fmt::format("of radius {:g} cm", *small * 100)
                                               : fmt::format("of radii {:g} to {:g} cm", *small * 100, *large * 100);
    sink.error(where, fmt::format("{} robots {} would cover {:.0f}% of the arena's free floor; random starts place "
                                  "them at most {:.0f}% of it",
                                  spec.robots, sizes, cover * 100, kMaxCover * 100))
        .help.push_back("use fewer robots or a larger arena");
  }
}

bool check_settings(const eval::ExperimentSpec& spec, const SourceRange& where, Sink& sink) {
  const int errors = sink.errors();
  check_group(spec, where, sink);
  for (const AlgorithmOptions& a : algorithm_options())
    if (const std::any* s = a.held_by(spec))
      if (const evo::OptionRefusal c = a.conflict(*s); !c.empty()) {
        Diagnostic& d = sink.error(where, c.message);
        if (!c.help.empty()) d.help.push_back(c.help);
      }
  if (std::string m = check_tree_operators(spec); !m.empty()) sink.error(where, m);
  check_algorithm_settings(spec, where, sink);
  const RuleContext context{&spec.arena, spec.arena_name, &spec.robot};
  // The first body's problems, then each further body's as the first's (`--set robot.KEY`
  // changes them all alike), up to the first body that has some. True when none has.
  bool robot = true;
  for (std::size_t i = 0; i < std::max<std::size_t>(spec.bodies.size(), 1) && robot; ++i)
    robot = report_body(spec, i, sim::robot_problems(i == 0 ? spec.robot : spec.bodies[i].params), where, sink);
  const auto arena = sim::arena_problems(spec.arena);
  report(sink, arena, context, where);
  if (robot && arena.empty()) {
    report(sink, sim::placement_problems(spec.arena, spec.robot), context, where);
    // A setting may take a sensor away (`robot.radars=0` under a fitness that reads `radar[0]`).
    if (auto m = unreadable_on_bodies(spec)) sink.error(where, std::move(m->message)).help = std::move(m->help);
  }
  return sink.errors() == errors;
}

namespace {

// A group of several bodies: `bodies` lists them with their counts ("khepera x 2, lit x 3"),
// and `body2.KEY` ... each further body's settings where they differ from the first's (the
// first's are `robot.KEY`). Only for several bodies, so that every other run keeps its settings.
void resolve_bodies(eval::ExperimentSpec& spec) {
  auto& r = spec.resolved_settings;
  std::erase_if(r, [](const auto& kv) {
    const std::string& k = kv.first;
    return k == "bodies" || (k.starts_with("body") && k.size() > 4 && std::isdigit(static_cast<unsigned char>(k[4])));
  });
  if (spec.bodies.size() <= 1) return;
  std::string listed;
  for (const eval::ExperimentSpec::GroupBody& b : spec.bodies)
    listed += fmt::format("{}{} x {}", listed.empty() ? "" : ", ", b.name, b.count);
  r["bodies"] = listed;
  for (std::size_t i = 1; i < spec.bodies.size(); ++i)
    for (const RobotSetting& s : robot_settings())
      if (std::string t = robot_value_text(s, spec.bodies[i].params); t != robot_value_text(s, spec.robot))
        r[fmt::format("body{}.{}", i + 1, s.name)] = std::move(t);
}

}  // namespace

void resolve_settings(eval::ExperimentSpec& spec) {
  auto& r = spec.resolved_settings;
  r["experiment"] = spec.name;
  for (const ExperimentSetting& s : experiment_settings()) {
    const std::string t = s.text(spec);
    if (t.empty()) r.erase(std::string(s.key));   // left at its default (`networks`)
    else r[std::string(s.key)] = t;
  }
  if (spec.start_from)
    r["start_from"] = fmt::format("{} from experiment {}", spec.start_from->evaluate_only ? "evaluate" : "start",
                                  spec.start_from->experiment);
  resolve_arena_settings(spec);
  for (const RobotSetting& s : robot_settings())
    r[std::string(kRobotGroup).append(s.name)] = robot_value_text(s, spec.robot);
  resolve_bodies(spec);
  r["fitness"] = spec.fitness.name;
  std::string names;
  for (const auto& c : spec.controllers)
    names += (names.empty() ? "" : ", ") + c.name + (c.evolved_by.empty() ? "" : " by " + c.evolved_by);
  r["compare"] = names;
  // Each algorithm's settings where the experiment holds them, and one held where it is used
  // only where it evolves a compared controller: a run from before it keeps its settings, and
  // its dependencies theirs.
  for (const AlgorithmOptions& a : algorithm_options()) {
    a.unresolve(r);
    const std::any* s = a.held_by(spec);
    if (s != nullptr && (a.scope != evo::SettingsScope::InUse || in_use(spec, a.name))) a.resolve(*s, r);
  }
  for (const eval::DependencySetting& d : spec.dependency_settings)
    r[fmt::format("{}.{}", fmt::join(d.path, "."), d.key)] = d.value;
}

namespace {

// Whether `text` is a number too large for a double (`1e400`), rather than no number at all.
bool out_of_range(const std::string& text) {
  if (text.empty()) return false;
  errno = 0;
  char* end = nullptr;
  (void)std::strtod(text.c_str(), &end);
  return errno == ERANGE && end == text.c_str() + text.size();
}

}  // namespace

SettingsRefusal apply_settings_together(eval::ExperimentSpec& experiment,
                                        const std::vector<std::pair<std::string, std::string>>& settings) {
  SettingsRefusal refusal;
  const SourceRange where{"--set", 0, 0, 0};
  eval::ExperimentSpec spec = experiment;   // commit only when everything checks
  for (std::size_t i = 0; i < settings.size(); ++i) {
    const auto& [key, value] = settings[i];
    Sink sink;
    const ast::Name name{trimmed(key), where};
    std::optional<RuleMessage> overlap;
    for (std::size_t j = 0; j < i && !overlap; ++j) overlap = overlapping_keys(trimmed(settings[j].first), name.text);
    if (overlap) {
      sink.error(where, std::move(overlap->message)).help = std::move(overlap->help);
    } else if (const auto v = value_from_text(value, where)) {
      (void)set_setting(spec, name, *v, sink);
    } else if (out_of_range(trimmed(value))) {
      sink.error(where, fmt::format("`{}` cannot take `{}`: the number is out of range (a number is at most about "
                                    "1.8e308 in size)",
                                    name.text, trimmed(value)));
    } else {
      sink.error(where, fmt::format("`{}` cannot take `{}`: a value is a number with its unit (`50ms`), `on` or "
                                    "`off`, a word, or a range `[-1, 1]`",
                                    name.text, trimmed(value)));
    }
    if (sink.errors() != 0) refusal.settings.emplace_back(i, shorten_names(flattened(sink.items())));
  }
  if (!refusal.settings.empty()) return refusal;
  // Together, as a script's items are: `mu 40  lambda 60` checks lambda >= mu once both hold.
  Sink sink;
  if (!check_settings(spec, where, sink)) {
    refusal.together = shorten_names(flattened(sink.items()));
    return refusal;
  }
  resolve_settings(spec);
  experiment = std::move(spec);
  return refusal;
}

std::string apply_settings(eval::ExperimentSpec& experiment,
                           const std::vector<std::pair<std::string, std::string>>& settings) {
  const SettingsRefusal refusal = apply_settings_together(experiment, settings);
  std::string text;
  for (const auto& [i, why] : refusal.settings) text += (text.empty() ? "" : "; ") + why;
  return text.empty() ? refusal.together : text;
}

std::string apply_setting(eval::ExperimentSpec& experiment, std::string_view key, std::string_view value) {
  return apply_settings(experiment, {{std::string(key), std::string(value)}});
}

}  // namespace esc::compiler
