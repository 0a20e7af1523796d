#include "compiler/lower_objectives.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/units.hpp"
#include "runtime/expr/observables.hpp"

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

// The most positions a `positions(K)` descriptor samples: 2K values, within what a CVT takes.
constexpr int kMaxPositions = 512;

// `positions(K)` as a whole descriptor's expression: its call, else null.
const ast::Expr* positions_call(const ast::ExpItem& item) {
  const ast::Expr* e = item.expr.get();
  return e != nullptr && e->kind == ast::Expr::Kind::Call && e->text == "positions" ? e : nullptr;
}

// K of `positions(K)`: a whole number 1 .. kMaxPositions written plainly; none (reported when
// `sink` is given) otherwise.
std::optional<int> positions_count(const ast::Expr& call, Sink* sink) {
  const ast::Expr* k = call.args.size() == 1 ? call.args[0].get() : nullptr;
  if (k != nullptr && k->kind == ast::Expr::Kind::Number && k->unit.empty() && k->number == std::floor(k->number) &&
      k->number >= 1 && k->number <= kMaxPositions)
    return static_cast<int>(k->number);
  if (sink != nullptr)
    sink->error(k != nullptr ? k->where : call.where,
                fmt::format("`positions(K)` samples K positions of the robot: K is a whole number from 1 to {}",
                            kMaxPositions))
        .help.push_back("write `descriptor path: positions(5) in [0, 60cm]`: x and y at 5 evenly spaced steps");
  return std::nullopt;
}

// An observable slot as a script names it (`wheel_diff`, `wheels[1]`), for messages.
std::string slot_name(expr::Slot s) {
  if (s == expr::slot::acting) return "using(...)";
  if (s >= expr::slot::reached && s < expr::slot::reached + expr::kMaxLights) return "reached(...)";
  return expr::observable_name(s).value_or(fmt::format("slot {}", s));
}

// A descriptor that reads what describes only the last step (`wheel_diff`) outside a step
// aggregate measures one step per epoch: a warning with the forms that say what is meant.
void warn_last_step(const eval::DescriptorSpec& d, const ast::ExpItem& item, Sink& sink) {
  for (const expr::Instr& in : d.program.code()) {
    if (in.op != expr::Op::Load || !expr::describes_last_step(in.slot)) continue;
    const std::string name = slot_name(in.slot);
    Diagnostic& w = sink.warning(item.expr->where,
                                 fmt::format("descriptor `{}` reads `{}` on the last step of {} only", d.name, name,
                                             d.at_evaluation ? "the evaluation" : "each epoch"));
    w.help.push_back(fmt::format("for its mean over the steps write `mean({})`; `last({})` says that the last step's "
                                 "value is meant",
                                 name, name));
    return;
  }
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
    const auto& f = fitnesses.lower(*decl, &arena, &experiment, &choices, &navigation, &x.cluster_radii);
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
  scope.sensor_names = &names.sensor_names();
  scope.cluster_radii = &x.cluster_radii;
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
    if (const auto over = lower_over_robots(item->overs, sink)) d.over_robots = *over;
    if (item->range) {
      if (const auto r = declared(*item->range, fmt::format("descriptor `{}`", name.text), sink)) d.range = *r;
    }
    if (const ast::Expr* call = positions_call(*item)) {
      // 2K descriptors, NAME_x0, NAME_y0, NAME_x1, ...: x and y on sampled steps, one range.
      const auto k = positions_count(*call, &sink);
      if (!k) continue;
      for (int i = 0; i < *k; ++i)
        for (const auto& [axis, slot] : {std::pair{"x", expr::slot::x}, std::pair{"y", expr::slot::y}}) {
          eval::DescriptorSpec p = d;
          p.name = fmt::format("{}_{}{}", name.text, axis, i);
          if (seen.contains(p.name) || !described.emplace(p.name, item).second) {
            sink.error(name.where, fmt::format("descriptor `{}` names its positions `{}`, the name of another "
                                               "objective or descriptor of this experiment",
                                               name.text, p.name));
            break;
          }
          expr::Program read;
          read.push_load(slot);
          p.aggregates.push_back({expr::StepAggregate::Kind::At, std::move(read), i, *k});
          p.program.push_load(step_aggregate_slot(&choices));
          x.descriptors.push_back(std::move(p));
        }
      continue;
    }
    if (item->expr) {
      ExprScope own = scope;
      own.step_aggregates = &d.aggregates;
      if (auto p = lower_expr(*item->expr, own, sink)) {
        d.program = std::move(*p);
        warn_last_step(d, *item, sink);
      }
    }
    x.descriptors.push_back(std::move(d));
  }
  return sink.errors() == errors;
}

void resolve_objectives(eval::ExperimentSpec& x, const ObjectiveItems& items) {
  if (!x.objectives.empty()) {
    std::string text;
    for (std::size_t i = 0; i < x.objectives.size(); ++i) {
      const eval::ObjectiveSpec& o = x.objectives[i];
      const eval::FitnessSpec& f = i == 0 ? x.fitness : x.further[i - 1];
      text += fmt::format("{}{}{}{}{}", text.empty() ? "" : "; ", o.name, o.minimize ? " minimize" : "",
                          o.range ? " " : "", o.range ? range_text(*o.range) : std::string());
      // Only where given, so that objectives without it resolve as they always did.
      if (f.over_robots != eval::Reduction::Mean)
        text += fmt::format(" over robots {}", reduction_names()[static_cast<std::size_t>(f.over_robots)]);
    }
    x.resolved_settings["objectives"] = text;
  }
  std::string text;
  // Item by item: a `positions(K)` item made 2K descriptors.
  std::size_t i = 0;
  for (const ast::ExpItem* item : items.descriptors) {
    if (i >= x.descriptors.size()) break;
    const eval::DescriptorSpec& d = x.descriptors[i];
    text += fmt::format("{}{}: {}{} {}", text.empty() ? "" : "; ", item->refs[0].text,
                        d.at_evaluation ? "evaluation: " : "", item->text, range_text(d.range));
    if (!d.at_evaluation && d.reduce != eval::Reduction::Mean)
      text += fmt::format(" by {}", reduction_names()[static_cast<std::size_t>(d.reduce)]);
    // Only where given, so that descriptors without it resolve as they always did.
    if (d.over_robots != eval::Reduction::Mean)
      text += fmt::format(" over robots {}", reduction_names()[static_cast<std::size_t>(d.over_robots)]);
    const ast::Expr* call = positions_call(*item);
    const auto k = call != nullptr ? positions_count(*call, nullptr) : std::nullopt;
    i += k ? 2 * static_cast<std::size_t>(*k) : 1;
  }
  if (!text.empty()) x.resolved_settings["descriptors"] = text;
}

}  // namespace esc::compiler
