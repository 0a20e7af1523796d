#include "compiler/setting_keys.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compiler/algorithm_options.hpp"
#include "compiler/arena_settings.hpp"
#include "compiler/compiler.hpp"
#include "compiler/es_options.hpp"
#include "compiler/experiment_settings.hpp"
#include "compiler/gp_settings.hpp"
#include "compiler/lower_evolution.hpp"
#include "compiler/names.hpp"
#include "compiler/robot_settings.hpp"
#include "compiler/rule_messages.hpp"
#include "compiler/sensor_uses.hpp"
#include "compiler/setting_values.hpp"
#include "compiler/text.hpp"
#include "runtime/sim/validate.hpp"

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

// `cmaes.`: the prefix of an algorithm's `--set` keys.
std::string group_of(const AlgorithmOptions& a) { return std::string(a.name) + "."; }

// What the experiment reads has its goal and sensors: a setting may take one away
// (`robot.radars=0` under a fitness that reads `radar[0]`). One error says it.
void check_navigation(const eval::ExperimentSpec& spec, const SourceRange& where, Sink& sink) {
  const Navigation n = navigation_of(spec);
  std::set<expr::Slot> read = slots_read_by_measures(spec);
  for (const control::ControllerSpec& c : spec.controllers) read.merge(slots_read(c));
  for (const expr::Slot s : read)
    if (auto m = unavailable(s, n)) {
      sink.error(where, std::move(m->message)).help = std::move(m->help);
      return;
    }
}

std::string trimmed(std::string_view t) {
  while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
  while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.remove_suffix(1);
  return std::string(t);
}

}  // namespace

std::vector<std::string> setting_keys() {
  std::vector<std::string> k;
  for (const ExperimentSetting& s : experiment_settings()) k.emplace_back(s.key);
  for (const auto& group : {option_keys(es_options()), prefixed(kArenaGroup, arena_setting_names()),
                            prefixed(kRobotGroup, robot_setting_names()), option_keys(gp_options(), kGpGroup)})
    k.insert(k.end(), group.begin(), group.end());
  for (const AlgorithmOptions& a : further_algorithms()) {
    const auto keys = prefixed(group_of(a), a.keys());
    k.insert(k.end(), keys.begin(), keys.end());
  }
  return k;
}

bool is_setting_group(std::string_view word) {
  for (const std::string_view group : {kRobotGroup, kArenaGroup, kGpGroup})
    if (group.substr(0, group.size() - 1) == word) return true;
  return find_further_algorithm(word) != nullptr;
}

bool setting_takes_range(std::string_view key) {
  if (const EsOption* o = find_option_key(es_options(), key)) return o->shape == OptionShape::Range;
  for (const AlgorithmOptions& a : further_algorithms())
    if (const auto name = in_group(key, group_of(a))) return a.takes_range(*name);
  const auto name = in_group(key, kGpGroup);
  if (!name) return false;
  const GpOption* o = find_option_key(gp_options(), *name);
  return o != nullptr && o->shape == OptionShape::Range;
}

bool set_setting(eval::ExperimentSpec& spec, const ast::Name& key, const ast::Value& value, Sink& sink,
                 std::string_view scope) {
  const std::string& k = key.text;
  if (const ExperimentSetting* s = find_experiment_setting(k)) return s->read(*s, spec, value, sink);
  if (const EsOption* o = find_option_key(es_options(), k)) return o->read(*o, spec.es, value, sink);
  if (const auto name = in_group(k, kGpGroup)) {
    const GpOption* o = find_option_key(gp_options(), *name);
    if (o == nullptr) {
      unknown(sink, key, "GP setting", *name, kGpGroup, option_keys(gp_options()), scope);
      return false;
    }
    // An experiment without GP settings checks the value and ignores it: the experiments
    // its evolved behaviors come from get the same `--set`.
    evo::gp::GpSettings scratch = spec.gp.value_or(evo::gp::GpSettings{});
    if (!o->read(*o, scratch, value, sink)) return false;
    if (spec.gp) spec.gp = scratch;
    return true;
  }
  for (const AlgorithmOptions& a : further_algorithms()) {
    const std::string group = group_of(a);
    const auto name = in_group(k, group);
    if (!name) continue;
    if (!a.has_key(*name)) {
      unknown(sink, key, fmt::format("{} setting", a.what), *name, group, a.keys(), scope);
      return false;
    }
    // Kept even where the algorithm evolves nothing yet: `--set networks=cmaes` may follow.
    return a.set(a.settings_in(spec), *name, value, sink);
  }
  if (const auto name = in_group(k, kRobotGroup)) {
    const RobotSetting* s = find_robot_setting(*name);
    if (s == nullptr) {
      unknown(sink, key, "robot setting", *name, kRobotGroup, robot_setting_names(), scope);
      return false;
    }
    return apply_robot_value(*s, value, spec.robot, sink);
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
  suggest(sink.error(key.where, fmt::format("unknown setting `{}{}`", scope, k)), k, setting_keys(),
          {.prefix = scope,
           .otherwise = fmt::format("settings: {}; and the groups {}", fmt::join(plain, ", "), fmt::join(groups, ", "))});
  return false;
}

bool check_settings(const eval::ExperimentSpec& spec, const SourceRange& where, Sink& sink) {
  const int errors = sink.errors();
  if (const auto p = es_problem(spec.es)) sink.error(where, p->message).help.push_back(p->help);
  if (std::string m = check_gp(spec); !m.empty()) sink.error(where, m);
  check_further_settings(spec, where, sink);
  const RuleContext context{&spec.arena, spec.arena_name, &spec.robot};
  const auto robot = sim::robot_problems(spec.robot);
  const auto arena = sim::arena_problems(spec.arena);
  report(sink, robot, context, where);
  report(sink, arena, context, where);
  if (robot.empty() && arena.empty()) {
    report(sink, sim::placement_problems(spec.arena, spec.robot), context, where);
    check_navigation(spec, where, sink);
  }
  return sink.errors() == errors;
}

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
  for (const EsOption& o : es_options())
    if (o.own_key) r[std::string(o.key)] = o.text(o, spec.es);
  resolve_arena_settings(spec);
  for (const RobotSetting& s : robot_settings())
    r[std::string(kRobotGroup).append(s.name)] = robot_value_text(s, spec.robot);
  r["fitness"] = spec.fitness.name;
  std::string names;
  for (const auto& c : spec.controllers)
    names += (names.empty() ? "" : ", ") + c.name + (c.evolved_by.empty() ? "" : " by " + c.evolved_by);
  r["compare"] = names;
  resolve_gp_settings(spec);
  // Another algorithm's settings where it evolves a compared controller, only: a run from
  // before it keeps its settings, and its dependencies theirs.
  for (const AlgorithmOptions& a : further_algorithms()) {
    const std::string group = group_of(a);
    for (auto it = r.begin(); it != r.end();) it = it->first.starts_with(group) ? r.erase(it) : std::next(it);
    if (const auto s = spec.algorithm_settings.find(std::string(a.name));
        s != spec.algorithm_settings.end() && in_use(spec, a.name))
      a.resolve(s->second, r);
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

std::string apply_settings(eval::ExperimentSpec& experiment,
                           const std::vector<std::pair<std::string, std::string>>& settings) {
  Sink sink;
  const SourceRange where{"--set", 0, 0, 0};
  eval::ExperimentSpec spec = experiment;   // commit only when everything checks
  bool all_set = true;
  for (const auto& [key, value] : settings) {
    const ast::Name name{trimmed(key), where};
    if (const auto v = value_from_text(value, where)) {
      all_set = set_setting(spec, name, *v, sink) && all_set;
    } else if (out_of_range(trimmed(value))) {
      sink.error(where, fmt::format("`{}` cannot take `{}`: the number is out of range (a number is at most about "
                                    "1.8e308 in size)",
                                    name.text, trimmed(value)));
      all_set = false;
    } else {
      sink.error(where, fmt::format("`{}` cannot take `{}`: a value is a number with its unit (`50ms`), `on` or "
                                    "`off`, a word, or a range `[-1, 1]`",
                                    name.text, trimmed(value)));
      all_set = false;
    }
  }
  // Together, as a script's items are: `mu 40  lambda 60` checks lambda >= mu once both hold.
  if (all_set) (void)check_settings(spec, where, sink);
  if (sink.errors() != 0) return shorten_names(flattened(sink.items()));
  resolve_settings(spec);
  experiment = std::move(spec);
  return {};
}

std::string apply_setting(eval::ExperimentSpec& experiment, std::string_view key, std::string_view value) {
  return apply_settings(experiment, {{std::string(key), std::string(value)}});
}

}  // namespace esc::compiler
