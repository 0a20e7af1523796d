#include "compiler/lower_objectives.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/units.hpp"

namespace esc::compiler {

std::optional<double> value_in_si(const ast::Quantity& q, Sink& sink) {
  if (!q.finite) return std::nullopt;
  if (q.unit.empty()) return q.value;
  const auto u = find_unit(q.unit);
  if (!u) {
    suggest(sink.error(q.unit_where, fmt::format("unknown unit `{}`", q.unit)), q.unit, unit_names());
    return std::nullopt;
  }
  return q.value * u->to_si;
}

namespace {

std::optional<eval::DeclaredRange> declared(const ast::DeclaredRange& r, std::string_view what, Sink& sink) {
  const auto lo = value_in_si(r.lo, sink), hi = value_in_si(r.hi, sink);
  if (!lo || !hi) return std::nullopt;
  if (!(*lo < *hi)) {
    sink.error(r.where, fmt::format("the range of {} is empty: {} is not below {}", what, r.lo.text, r.hi.text))
        .help.push_back("write `in [lower, upper]` with lower < upper");
    return std::nullopt;
  }
  // Archives, novelty distances, QD-scores and hypervolumes divide by or multiply widths: a
  // width that overflows would make every one of them inf or 0 after the run has started.
  if (!std::isfinite(*hi - *lo)) {
    sink.error(r.where, fmt::format("the range of {} is too wide: {} - {} overflows a double", what, r.hi.text,
                                    r.lo.text))
        .help.push_back("keep both bounds within +-1e300, the largest value an expression or a fitness takes");
    return std::nullopt;
  }
  return eval::DeclaredRange{*lo, *hi};
}

std::string range_text(const eval::DeclaredRange& r) {
  return fmt::format("in [{}, {}]", number_text(r.lower), number_text(r.upper));
}

}  // namespace

const std::vector<std::string>& reduction_names() {
  static const std::vector<std::string> names{"mean", "sum", "min", "max", "first", "last"};
  return names;
}

bool lower_objectives(const ObjectiveItems& items, const ast::ExperimentDecl& experiment,
                      const ast::ArenaDecl& arena, const ChoiceNames& choices, const Navigation& navigation,
                      Resolver& names, FitnessLowering& fitnesses, ArenaLowering& arenas, Sink& sink,
                      eval::ExperimentSpec& x) {
  const int errors = sink.errors();
  const bool declares = !items.objectives.empty() || (items.fitness != nullptr && items.fitness->range);
  if (declares && items.fitness != nullptr) {
    eval::ObjectiveSpec first{x.fitness.name, false, std::nullopt};
    if (items.fitness->range) first.range = declared(*items.fitness->range, "the fitness", sink);
    x.objectives.push_back(first);
  }
  std::map<std::string, const ast::ExpItem*> seen;
  if (items.fitness != nullptr) seen.emplace(x.fitness.name, items.fitness);
  for (const ast::ExpItem* item : items.objectives) {
    const ast::Name& ref = item->refs[0];
    if (const auto [it, fresh] = seen.emplace(ref.text, item); !fresh) {
      sink.error(ref.where, fmt::format("fitness `{}` is already an objective of this experiment", ref.text))
          .notes.emplace_back(it->second->refs[0].where, "first given here");
      continue;
    }
    const auto* decl = names.lookup<ast::FitnessDecl>(ref);
    if (decl == nullptr) continue;
    const auto& f = fitnesses.lower(*decl, &arena, &experiment, &choices, &navigation);
    if (!f) continue;
    if (!f->spec.stop_when.empty()) {
      sink.error(ref.where, fmt::format("objective `{}` has a `stop epoch when` condition", ref.text))
          .help.push_back("only the fitness ends an epoch early: move the condition to the fitness, or declare "
                          "a fitness without it for this objective");
      continue;
    }
    eval::ObjectiveSpec o{ref.text, item->minimize, std::nullopt};
    if (item->range) o.range = declared(*item->range, fmt::format("objective `{}`", ref.text), sink);
    x.objectives.push_back(o);
    x.further.push_back(f->spec);
  }

  ExprScope scope;
  scope.use = ExprScope::Use::End;
  scope.arena = &arenas.names(arena);
  scope.choices = &choices;
  scope.navigation = &navigation;
  std::map<std::string, const ast::ExpItem*> described;
  for (const ast::ExpItem* item : items.descriptors) {
    const ast::Name& name = item->refs[0];
    if (const auto [it, fresh] = described.emplace(name.text, item); !fresh) {
      sink.error(name.where, fmt::format("descriptor `{}` is already declared in this experiment", name.text))
          .notes.emplace_back(it->second->refs[0].where, "first declared here");
      continue;
    }
    // Exports and the report name a member's values by these names, objectives and
    // descriptors side by side.
    if (const auto it = seen.find(name.text); it != seen.end()) {
      sink.error(name.where, fmt::format("descriptor `{}` has the name of an objective of this experiment", name.text))
          .notes.emplace_back(it->second->refs[0].where, "the objective");
      continue;
    }
    eval::DescriptorSpec d;
    d.name = name.text;
    d.at_evaluation = item->at_evaluation;
    if (!item->reduce.text.empty()) {
      const auto& all = reduction_names();
      const auto r = std::find(all.begin(), all.end(), item->reduce.text);
      if (item->at_evaluation) {
        sink.error(item->reduce.where, "a descriptor evaluated once at the end of the evaluation has no epochs to reduce")
            .help.push_back("remove `by ...`, or remove `evaluation:` to evaluate it at the end of every epoch");
      } else if (r == all.end()) {
        Diagnostic& diag = sink.error(item->reduce.where, fmt::format("unknown reduction `{}`", item->reduce.text));
        suggest(diag, item->reduce.text, all, {{}, fmt::format("reductions: {}", quoted_list(all))});
      } else {
        d.reduce = static_cast<eval::Reduction>(r - all.begin());
      }
    }
    if (item->range) {
      if (const auto r = declared(*item->range, fmt::format("descriptor `{}`", name.text), sink)) d.range = *r;
    }
    if (item->expr) {
      if (auto p = lower_expr(*item->expr, scope, sink)) d.program = std::move(*p);
    }
    x.descriptors.push_back(std::move(d));
  }
  return sink.errors() == errors;
}

void resolve_objectives(eval::ExperimentSpec& x, const ObjectiveItems& items) {
  if (!x.objectives.empty()) {
    std::string text;
    for (const eval::ObjectiveSpec& o : x.objectives)
      text += fmt::format("{}{}{}{}{}", text.empty() ? "" : "; ", o.name, o.minimize ? " minimize" : "",
                          o.range ? " " : "", o.range ? range_text(*o.range) : std::string());
    x.resolved_settings["objectives"] = text;
  }
  std::string text;
  for (std::size_t i = 0; i < x.descriptors.size() && i < items.descriptors.size(); ++i) {
    const eval::DescriptorSpec& d = x.descriptors[i];
    text += fmt::format("{}{}: {}{} {}", text.empty() ? "" : "; ", d.name, d.at_evaluation ? "evaluation: " : "",
                        items.descriptors[i]->text, range_text(d.range));
    if (!d.at_evaluation && d.reduce != eval::Reduction::Mean)
      text += fmt::format(" by {}", reduction_names()[static_cast<std::size_t>(d.reduce)]);
  }
  if (!text.empty()) x.resolved_settings["descriptors"] = text;
}

}  // namespace esc::compiler
