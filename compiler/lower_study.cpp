// Studies: the items of a `study` block -> eval::StudySpec.
#include "compiler/lower_study.hpp"

#include <algorithm>
#include <map>
#include <string_view>

#include <fmt/format.h>

#include "compiler/compiler.hpp"
#include "compiler/experiment_settings.hpp"
#include "compiler/names.hpp"
#include "compiler/setting_keys.hpp"
#include "compiler/setting_values.hpp"

namespace esc::compiler {

namespace {

using K = ast::StudyItem::Kind;

// Directories of a study's own files, which no condition may take.
constexpr std::string_view kReservedDirectories[] = {"sources", "deps", "figures"};

// A study value as one setting's value: a single value, or a range written as a list of
// two numbers; nullopt for any other list.
std::optional<ast::Value> single(const ast::StudyValue& v) {
  if (!v.list) return v.value;
  const auto number = [](const ast::StudyValue& x) { return !x.list && x.value.kind == ast::Value::Kind::Quantity; };
  if (v.items.size() != 2 || !number(v.items[0]) || !number(v.items[1])) return std::nullopt;
  ast::Value range;
  range.kind = ast::Value::Kind::Range;
  range.q = v.items[0].value.q;
  range.hi = v.items[1].value.q;
  range.text = v.text;
  range.where = v.where;
  return range;
}

// A value as a condition's name and settings show it: as written, without spaces.
std::string compact(std::string_view text) {
  std::string out;
  for (const char c : text)
    if (c != ' ' && c != '\t' && c != '\n' && c != '\r') out += c;
  return out;
}

// The key without its group (`robot.time_constant`: `time_constant`).
std::string_view short_key(std::string_view key) {
  const std::size_t dot = key.rfind('.');
  return dot == std::string_view::npos ? key : key.substr(dot + 1);
}

// A condition's name as a file name: `/` is `_per_`, `^` goes, and any character but
// letters, digits and `_.,=+-` is `_` (`max_accel=0.5m/s^2`: `max_accel=0.5m_per_s2`).
std::string directory_of(std::string_view name) {
  std::string out;
  for (const char c : name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       std::string_view("_.,=+-").find(c) != std::string_view::npos;
    if (plain) out += c;
    else if (c == '/') out += "_per_";
    else if (c != '^') out += '_';
  }
  return out;
}

// One axis of a sweep: a setting and its listed values.
struct Axis {
  const ast::StudySetting* setting = nullptr;
  std::vector<ast::Value> values;
  std::vector<std::string> texts;   // compact
};

// Whether a sweep's values go on a plot's x axis as numbers: all numbers in one unit.
bool numeric(const Axis& a) {
  return std::all_of(a.values.begin(), a.values.end(), [&](const ast::Value& x) {
    return x.kind == ast::Value::Kind::Quantity && x.q.unit == a.values.front().q.unit;
  });
}

}  // namespace

std::optional<eval::ExperimentSpec> StudyLowering::base(const ast::Name& ref, const Common& common) {
  const auto* xd = names_.lookup<ast::ExperimentDecl>(ref);
  const auto* lowered = xd == nullptr ? nullptr : &experiments_.lower(*xd);
  if (lowered == nullptr || !*lowered) {
    broken_reference_ = true;
    return std::nullopt;
  }
  eval::ExperimentSpec spec = **lowered;
  if (common.runs) spec.runs = *common.runs;
  spec.seed = common.seed;
  return spec;
}

bool StudyLowering::is_dependency_key(std::string_view key) const {
  const std::size_t dot = key.find('.');
  return dot != std::string_view::npos && !is_setting_group(key.substr(0, dot)) &&
         names_.find<ast::ExperimentDecl>(key.substr(0, dot)) != nullptr;
}

bool StudyLowering::apply(eval::ExperimentSpec& spec, const ast::StudySetting& setting, const ast::Value& value) {
  if (setting.key.text == "seed") {
    sink_.error(setting.key.where, "a condition cannot set `seed`: every condition of a study runs with the "
                                   "study's master seed (common random numbers)")
        .help.push_back("write `seed N` in the study itself");
    return false;
  }
  if (is_dependency_key(setting.key.text)) return apply_to_dependency(spec, setting, value);
  // `body2.KEY` is the group's second body's, whatever an experiment is called: one named
  // `body2` could not be told apart.
  const std::string_view word = std::string_view(setting.key.text).substr(0, setting.key.text.find('.'));
  if (const auto* named = names_.find<ast::ExperimentDecl>(word); named != nullptr && is_body_group(word)) {
    sink_.error(setting.key.where, fmt::format("`{}` sets a body of the group, and experiment `{}` cannot be told "
                                               "apart from it",
                                               setting.key.text, word))
        .help.push_back(fmt::format("rename experiment `{}`: `bodyN` begins the keys of a group's bodies", word));
    return false;
  }
  return set_setting(spec, setting.key, value, sink_);
}

bool StudyLowering::apply_to_dependency(eval::ExperimentSpec& spec, const ast::StudySetting& setting,
                                        const ast::Value& value, const std::string& written_above) {
  const std::string& key = setting.key.text;
  const std::string name = key.substr(0, key.find('.'));
  const std::vector<std::string> needs = spec.needs();
  if (std::find(needs.begin(), needs.end(), name) == needs.end()) {
    // Further down a nested key (`energy.stop.x`), the key as written says which step failed.
    const std::string where_in_key = written_above.empty() ? "" : fmt::format("in `{}{}`, ", written_above, key);
    sink_.error(setting.key.where, fmt::format("{}`{}` does not depend on experiment `{}`: a condition sets its own "
                                               "experiment's settings and those of the experiments it depends on",
                                               where_in_key, spec.name, name))
        .help.push_back(needs.empty() ? fmt::format("`{}` depends on no experiment", spec.name)
                                      : fmt::format("`{}` depends on {}", spec.name, quoted_list(needs, " and ")));
    return false;
  }
  const auto& lowered = experiments_.lower(*names_.find<ast::ExperimentDecl>(name));
  if (!lowered) return false;   // reported where it is declared
  // The value alone here, located; an experiment's settings are checked together once the
  // condition has given them all (check_dependency_settings). Its seed may change: common
  // random numbers concern the conditions, not what they depend on.
  eval::ExperimentSpec dependency = *lowered;
  ast::StudySetting inner = setting;
  inner.key.text = key.substr(name.size() + 1);
  const bool further = is_dependency_key(inner.key.text);
  const std::string scope = written_above + key.substr(0, key.size() - inner.key.text.size());
  if (further ? !apply_to_dependency(dependency, inner, value, scope)
              : !set_setting(dependency, inner.key, value, sink_, scope))
    return false;
  if (!further) {
    spec.dependency_settings.push_back({{name}, inner.key.text, compact(value.text)});
  } else {   // a setting further down (`energy.stop.generations`)
    eval::DependencySetting below = std::move(dependency.dependency_settings.back());
    below.path.insert(below.path.begin(), name);
    spec.dependency_settings.push_back(std::move(below));
  }
  return true;
}

bool StudyLowering::check_dependency_settings(const eval::ExperimentSpec& spec, const SourceRange& where) {
  std::map<std::vector<std::string>, std::vector<std::pair<std::string, std::string>>> given;
  for (const eval::DependencySetting& d : spec.dependency_settings) given[d.path].emplace_back(d.key, d.value);
  bool ok = true;
  for (const auto& [path, settings] : given) {
    const auto* decl = names_.find<ast::ExperimentDecl>(path.back());
    const auto& lowered = decl != nullptr ? experiments_.lower(*decl) : std::nullopt;
    if (!lowered) continue;   // reported where it is declared
    eval::ExperimentSpec dependency = *lowered;
    if (const std::string error = apply_settings(dependency, settings); !error.empty()) {
      sink_.error(where, fmt::format("experiment `{}` with the settings this condition gives it: {}",
                                     fmt::join(path, "."), error));
      ok = false;
    }
  }
  return ok;
}

bool StudyLowering::unique_keys(const std::vector<ast::StudySetting>& settings) {
  bool ok = true;
  std::map<std::string, const ast::StudySetting*> seen;
  for (const ast::StudySetting& s : settings) {
    if (s.key.text.empty()) continue;
    if (auto [it, fresh] = seen.try_emplace(s.key.text, &s); !fresh) {
      sink_.error(s.key.where, fmt::format("`{}` is already set here", s.key.text))
          .notes.emplace_back(it->second->key.where, "first set here");
      ok = false;
      continue;
    }
    for (const ast::StudySetting& before : settings) {
      if (&before == &s) break;
      // Both of one dependency (`d.robot.emission`, `d.body2.emission`) are its own keys.
      std::string_view a = before.key.text, b = s.key.text;
      while (is_dependency_key(a) && is_dependency_key(b) && a.substr(0, a.find('.')) == b.substr(0, b.find('.'))) {
        a.remove_prefix(a.find('.') + 1);
        b.remove_prefix(b.find('.') + 1);
      }
      if (auto m = overlapping_keys(a, b)) {
        Diagnostic& d = sink_.error(s.key.where, std::move(m->message));
        d.notes.emplace_back(before.key.where, fmt::format("`{}` is set here", before.key.text));
        d.help = std::move(m->help);
        ok = false;
        break;
      }
    }
  }
  return ok;
}

std::optional<eval::ConditionSpec> StudyLowering::condition(const ast::StudyItem& item, const Common& common) {
  auto spec = base(item.experiments.front(), common);
  bool ok = unique_keys(item.settings) && spec.has_value();
  eval::ConditionSpec c;
  c.name = item.name.text;
  const SourceRange* last = nullptr;
  for (const ast::StudySetting& st : item.settings) {
    const auto v = single(st.value);
    if (!v) {
      sink_.error(st.value.where, fmt::format("`{}` takes one value in a condition, found a list of {}", st.key.text,
                                              st.value.items.size()))
          .help.push_back(fmt::format("to vary `{}`, list its values in a `sweep`", st.key.text));
      ok = false;
      continue;
    }
    const int before = sink_.errors();
    if (spec && !apply(*spec, st, *v)) {
      if (st.value.list && sink_.errors() > before)
        sink_.items().back().help.push_back(fmt::format("to vary `{}`, list its values in a `sweep`", st.key.text));
      ok = false;
      continue;
    }
    c.settings.push_back({st.key.text, compact(st.value.text), false, std::nullopt, {}});
    last = &st.value.where;
  }
  if (!ok || !spec) return std::nullopt;
  if (last != nullptr && (!check_settings(*spec, *last, sink_) || !check_dependency_settings(*spec, *last)))
    return std::nullopt;
  resolve_settings(*spec);
  c.experiment = std::move(*spec);
  return c;
}

std::vector<eval::ConditionSpec> StudyLowering::sweep(const ast::StudyItem& item, const Common& common, int index) {
  const auto spec = base(item.experiments.front(), common);
  bool ok = unique_keys(item.settings) && spec.has_value();
  if (item.settings.empty()) {
    sink_.error(item.where, "a sweep varies at least one setting")
        .help.push_back("write `sweep EXPERIMENT { robot.time_constant [50ms, 100ms, 200ms] }`");
    return {};
  }
  std::vector<Axis> axes;
  for (const ast::StudySetting& st : item.settings) {
    const std::string& key = st.key.text;
    if (!st.value.list || st.value.items.empty()) {
      sink_.error(st.value.where, st.value.list ? fmt::format("`{}` lists no values", key)
                                                : fmt::format("a sweep lists the values of `{}`, found one value", key))
          .help.push_back(fmt::format("write `{} [{}, ...]`", key, st.value.list ? "VALUE" : compact(st.value.text)));
      ok = false;
      continue;
    }
    Axis a{&st, {}, {}};
    for (const ast::StudyValue& item_value : st.value.items) {
      if (setting_takes_range(key) && !item_value.list) {
        sink_.error(item_value.where, fmt::format("each value of `{}` is a range, found `{}`", key, item_value.text))
            .help.push_back(fmt::format("a sweep lists ranges: `{} [[-1, 1], [-2, 2]]`", key));
        ok = false;
        continue;
      }
      const auto v = single(item_value);
      if (!v) {
        sink_.error(item_value.where, fmt::format("`{}` takes one value per point, found a list of {}", key,
                                                  item_value.items.size()));
        ok = false;
        continue;
      }
      const std::string text = compact(item_value.text);
      if (std::find(a.texts.begin(), a.texts.end(), text) != a.texts.end()) {
        sink_.error(item_value.where, fmt::format("`{}` lists `{}` twice", key, text));
        ok = false;
        continue;
      }
      // Each value checked alone, once: a wrong one is reported at itself, not per point.
      eval::ExperimentSpec probe = spec.value_or(eval::ExperimentSpec{});
      const std::size_t before = sink_.items().size();
      if (spec && !apply(probe, st, *v)) {
        ok = false;
        // A wrong key (unknown, or an experiment not depended on) is wrong for every value:
        // said once, at the key.
        const auto& first = sink_.items().size() > before ? sink_.items()[before].where : SourceRange{};
        if (first.line == st.key.where.line && first.column == st.key.where.column) break;
        continue;
      }
      a.values.push_back(*v);
      a.texts.push_back(text);
    }
    axes.push_back(std::move(a));
  }
  if (!ok || !spec) return {};

  // Short keys in names, unless two axes share one (`generations`, `gp.generations`).
  // A setting of a dependency keeps its experiment (`energy.generations=60`): it is not the
  // condition's own; one body's keeps its body (`body2.emission=0`): it is not every body's.
  std::vector<std::string> labels;
  for (const Axis& a : axes) {
    const std::string& key = a.setting->key.text;
    labels.emplace_back(is_dependency_key(key) || body_key(key) ? std::string_view(key) : short_key(key));
  }
  for (std::size_t i = 0; i < axes.size(); ++i)
    if (std::count(labels.begin(), labels.end(), labels[i]) > 1)
      for (std::size_t j = 0; j < axes.size(); ++j) labels[j] = axes[j].setting->key.text;

  // The grid, the first axis varying slowest.
  std::vector<bool> on_axis;
  for (const Axis& a : axes) on_axis.push_back(numeric(a));
  std::vector<eval::ConditionSpec> points;
  bool all = true;
  std::vector<std::size_t> at(axes.size(), 0);
  for (bool more = true; more;) {
    eval::ConditionSpec c;
    eval::ExperimentSpec x = *spec;
    bool point_ok = true;
    for (std::size_t i = 0; i < axes.size(); ++i) {
      const ast::Value& v = axes[i].values[at[i]];
      point_ok = apply(x, *axes[i].setting, v) && point_ok;
      c.name += fmt::format("{}{}={}", i == 0 ? "" : ",", labels[i], axes[i].texts[at[i]]);
      c.settings.push_back({axes[i].setting->key.text, axes[i].texts[at[i]], true,
                            on_axis[i] ? std::optional<double>(v.q.value) : std::nullopt,
                            on_axis[i] ? v.q.unit : std::string()});
    }
    const std::size_t before = sink_.items().size();
    const SourceRange& where = axes.back().values[at.back()].where;
    if (point_ok && check_settings(x, where, sink_) && check_dependency_settings(x, where)) {
      resolve_settings(x);
      c.experiment = std::move(x);
      c.sweep = index;
      points.push_back(std::move(c));
    } else {
      all = false;
      for (std::size_t e = before; e < sink_.items().size(); ++e)
        sink_.items()[e].help.push_back(fmt::format("at the sweep's point `{}`", c.name));
    }
    more = false;
    for (std::size_t i = axes.size(); i-- > 0;) {
      if (++at[i] < axes[i].values.size()) {
        more = true;
        break;
      }
      at[i] = 0;
    }
  }
  if (!all) return {};
  return points;
}

std::optional<eval::StudySpec> StudyLowering::lower(const ast::StudyDecl& d) {
  if (d.poisoned) return std::nullopt;
  const int errors = sink_.errors();
  broken_reference_ = false;
  Common common;
  std::map<K, const ast::StudyItem*> once;
  for (const ast::StudyItem& item : d.items) {
    if (item.kind != K::Runs && item.kind != K::Seed) continue;
    const std::string_view key = item.kind == K::Runs ? "runs" : "seed";
    if (auto [it, fresh] = once.try_emplace(item.kind, &item); !fresh) {
      sink_.error(item.where, fmt::format("`{}` is already given in this study", key))
          .notes.emplace_back(it->second->where, "first given here");
      continue;
    }
    if (!item.number || !item.number->finite) continue;
    const ExperimentSetting& row = *find_experiment_setting(key);
    eval::ExperimentSpec scratch;
    if (!row.read(row, scratch, as_value(*item.number), sink_)) continue;
    if (item.kind == K::Runs) common.runs = scratch.runs;
    else common.seed = scratch.seed;
  }

  eval::StudySpec study;
  study.name = d.name.text;
  study.seed = common.seed;
  // Where each condition is declared, for the checks of names and directories.
  std::vector<SourceRange> declared;
  const auto add = [&](eval::ConditionSpec c, const SourceRange& where) {
    c.directory = directory_of(c.name);
    for (std::size_t i = 0; i < study.conditions.size(); ++i) {
      const eval::ConditionSpec& other = study.conditions[i];
      if (other.name != c.name && other.directory != c.directory) continue;
      sink_.error(where, other.name == c.name
                             ? fmt::format("condition `{}` is already in study `{}`", c.name, study.name)
                             : fmt::format("conditions `{}` and `{}` would share the directory `{}`", other.name,
                                           c.name, c.directory))
          .notes.emplace_back(declared[i], "first here");
      return;
    }
    if (std::find(std::begin(kReservedDirectories), std::end(kReservedDirectories), c.directory) !=
        std::end(kReservedDirectories)) {
      sink_.error(where, fmt::format("a condition cannot be called `{}`: the study's directory keeps its own `{}` "
                                     "there", c.name, c.directory))
          .help.push_back("write `condition NAME = EXPERIMENT` to give it another name");
      return;
    }
    study.conditions.push_back(std::move(c));
    declared.push_back(where);
  };
  int sweeps = 0;
  for (const ast::StudyItem& item : d.items) {
    switch (item.kind) {
      case K::Conditions:
        for (const ast::Name& ref : item.experiments) {
          auto spec = base(ref, common);
          if (!spec) continue;
          resolve_settings(*spec);
          add(eval::ConditionSpec{ref.text, {}, std::nullopt, {}, std::move(*spec)}, ref.where);
        }
        break;
      case K::Condition:
        if (auto c = condition(item, common)) add(std::move(*c), item.name.where);
        break;
      case K::Sweep:
        for (eval::ConditionSpec& c : sweep(item, common, sweeps)) add(std::move(c), item.where);
        ++sweeps;
        break;
      case K::Runs:
      case K::Seed: break;
    }
  }
  if (sink_.errors() != errors || broken_reference_) return std::nullopt;
  if (study.conditions.empty()) {
    sink_.error(d.name.where, fmt::format("study `{}` has no conditions", d.name.text))
        .help.push_back("add `conditions EXPERIMENT, EXPERIMENT` or `sweep EXPERIMENT { KEY [VALUE, VALUE] }`");
    return std::nullopt;
  }
  return study;
}

}  // namespace esc::compiler
