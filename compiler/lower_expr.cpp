#include "compiler/lower_expr.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/units.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::compiler {

namespace {

using expr::Op;

struct Function {
  std::string_view name;
  int arity;
  Op op;
};

constexpr std::array kFunctions = {
    Function{"min", 2, Op::Min},      Function{"max", 2, Op::Max},     Function{"abs", 1, Op::Abs},
    Function{"sqrt", 1, Op::Sqrt},    Function{"exp", 1, Op::Exp},     Function{"log", 1, Op::Log},
    Function{"tanh", 1, Op::Tanh},    Function{"sigmoid", 1, Op::Sigmoid}, Function{"clamp", 3, Op::Clamp},
    Function{"pow", 2, Op::Pow},
};

std::optional<Op> binary_op(const std::string& s) {
  if (s == "+") return Op::Add;
  if (s == "-") return Op::Sub;
  if (s == "*") return Op::Mul;
  if (s == "/") return Op::Div;
  if (s == "^") return Op::Pow;
  if (s == "<") return Op::Lt;
  if (s == "<=") return Op::Le;
  if (s == ">") return Op::Gt;
  if (s == ">=") return Op::Ge;
  if (s == "==") return Op::Eq;
  if (s == "!=") return Op::Ne;
  if (s == "and") return Op::And;
  if (s == "or") return Op::Or;
  return std::nullopt;
}

// A lowered subexpression: a constant, or postfix code.
struct Node {
  bool ok = true;
  std::optional<double> constant;
  std::vector<expr::Instr> code;
};

// What reads the acting choice: `using(B)`, 1 on a step when B acts (step terms, stop
// conditions, end terms), and the aggregates of an end term, `count(B)` (steps B acted),
// `share(B)` (count(B) / steps) and `steps`.
enum class ChoiceReader { Using, Count, Share };
struct ChoiceFunction {
  std::string_view name;
  ChoiceReader reader;
};
constexpr std::array kChoiceFunctions = {ChoiceFunction{"using", ChoiceReader::Using},
                                         ChoiceFunction{"count", ChoiceReader::Count},
                                         ChoiceFunction{"share", ChoiceReader::Share}};
constexpr std::string_view kStepsAggregate = "steps";

// Step aggregates, read by end terms: a step expression folded over the steps of the epoch
// (the evaluation). `min` and `max` fold with one argument; with two they are the functions.
struct AggregateFunction {
  std::string_view name;
  expr::StepAggregate::Kind kind;
};
using AggregateKind = expr::StepAggregate::Kind;
constexpr std::array kAggregateFunctions = {
    AggregateFunction{"mean", AggregateKind::Mean}, AggregateFunction{"sum", AggregateKind::Sum},
    AggregateFunction{"min", AggregateKind::Min},   AggregateFunction{"max", AggregateKind::Max},
    AggregateFunction{"fraction", AggregateKind::Fraction}, AggregateFunction{"last", AggregateKind::At}};

Node constant(double v) {
  Node n;
  n.constant = v;
  return n;
}

void append(std::vector<expr::Instr>& out, const Node& n) {
  if (n.constant) out.push_back({Op::Const, 0, *n.constant});
  else out.insert(out.end(), n.code.begin(), n.code.end());
}

// Applies `op` to constant operands with the runtime's own semantics.
double fold(Op op, const std::vector<double>& args) {
  expr::Program p;
  for (double a : args) p.push_const(a);
  p.push_op(op);
  const expr::Frame frame{};
  return p.eval(frame);
}

class Lowerer {
 public:
  Lowerer(const ExprScope& scope, Sink& sink) : scope_(scope), sink_(sink) {}

  Node lower(const ast::Expr& e) {
    using K = ast::Expr::Kind;
    switch (e.kind) {
      case K::Error: return failed();
      case K::Number: return number(e);
      case K::Bool: return constant(e.number);
      case K::Name: return name(e);
      case K::Index: return index(e);
      case K::Call: return call(e);
      case K::Unary: return apply(e.text == "not" ? Op::Not : Op::Neg, e.args);
      case K::Binary: {
        const auto op = binary_op(e.text);
        if (!op) return failed();
        return apply(*op, e.args);
      }
      case K::If: {
        if (e.args.size() != 3) return failed();
        Node c = lower(*e.args[0]), a = lower(*e.args[1]), b = lower(*e.args[2]);
        if (!c.ok || !a.ok || !b.ok) return failed();
        if (c.constant) return *c.constant != 0.0 ? a : b;
        return combine(Op::Select, {c, a, b});
      }
    }
    return failed();
  }

 private:
  static Node failed() {
    Node n;
    n.ok = false;
    return n;
  }

  Node number(const ast::Expr& e) {
    if (e.unit.empty()) return constant(e.number);
    const auto u = find_unit(e.unit);
    if (!u) {
      Diagnostic& d = sink_.error(e.unit_where, fmt::format("unknown unit `{}`", e.unit));
      suggest(d, e.unit, unit_names());
      if (e.unit.find('/') != std::string::npos)
        d.help.push_back("to divide by a name, put the quantity in parentheses: `(2cm) / speed`");
      return failed();
    }
    return constant(e.number * u->to_si);
  }

  std::vector<std::string> known_names() const {
    std::vector<std::string> v = scope_.params;
    const std::vector<std::string> observables = expr::observable_names();
    v.insert(v.end(), observables.begin(), observables.end());
    if (scope_.use == ExprScope::Use::End) v.emplace_back(kStepsAggregate);
    return v;
  }

  // Where end terms are written, for the help lines of aggregates used elsewhere.
  static constexpr const char* kEndTermHelp =
      "aggregates are read once per epoch or evaluation: write them in the fitness's `epoch:` or `evaluation:` "
      "term, e.g. `epoch: -100 * abs(share(follow) - 0.1)`";

  Node name(const ast::Expr& e) {
    for (std::size_t i = 0; i < scope_.params.size(); ++i)
      if (scope_.params[i] == e.text) return load(expr::slot::param + static_cast<expr::Slot>(i));
    if (const auto o = find_observable(e.text, scope_.sensor_names)) {
      if (o->indexed) {
        sink_.error(e.where, fmt::format("`{}` holds {} values; pick one with an index", e.text, o->count))
            .help.push_back(fmt::format("write `{}[0]` .. `{}[{}]`", e.text, e.text, o->count - 1));
        return failed();
      }
      return observable(o->first, e.where);
    }
    if (e.text == "true" || e.text == "false") return constant(e.text == "true" ? 1.0 : 0.0);
    if (e.text == kStepsAggregate && scope_.use == ExprScope::Use::End) return load(expr::aggregate::steps);
    if (e.text == kStepsAggregate) {
      sink_.error(e.where, "`steps` counts the steps of an epoch or an evaluation; it is read at their end")
          .help.push_back(kEndTermHelp);
      return failed();
    }
    unknown_name(e.text, e.where);
    return failed();
  }

  // `using(B)`, `count(B)`, `share(B)`: B names actions or behaviors of the compared
  // controllers (ChoiceNames), each an experiment-wide id.
  Node choice(const ast::Expr& e, const ChoiceFunction& f) {
    if (f.reader == ChoiceReader::Using && scope_.use == ExprScope::Use::Behavior) {
      sink_.error(e.unit_where, "`using(B)` can be read only by a fitness: a behavior does not see which behavior acts")
          .help.push_back("write `using(B)` in the fitness's `step:`, `stop epoch when`, `epoch:` or `evaluation:`");
      return failed();
    }
    if (f.reader != ChoiceReader::Using && scope_.use != ExprScope::Use::End) {
      sink_.error(e.unit_where, fmt::format("`{}(B)` is an aggregate over an epoch or an evaluation", f.name))
          .help.push_back(kEndTermHelp);
      return failed();
    }
    const auto named = [](const ast::Expr* a) {
      return a != nullptr && (a->kind == ast::Expr::Kind::Name || a->kind == ast::Expr::Kind::Call);
    };
    if (e.args.size() != 1 || !named(e.args[0].get())) {
      sink_.error(e.where, fmt::format("`{}` takes the name of an action or behavior of the compared controllers, "
                                       "as in `{}(avoid)` or `{}(library.avoid)`",
                                       f.name, f.name, f.name));
      return failed();
    }
    const ast::Expr& arg = *e.args[0];
    // The name usage tables print: `forward` or, for a behavior listed with arguments, also
    // `forward(0.5)` (as copied from a table; constants printed as the tables print them).
    std::string key = arg.text;
    if (arg.kind == ast::Expr::Kind::Call) {
      std::vector<std::string> shown;
      for (const auto& a : arg.args) {
        const Node v = a ? lower(*a) : failed();
        if (!v.ok) return failed();
        if (!v.constant) {
          sink_.error(a->where, fmt::format("`{}({}(...))` takes the arguments the behavior was listed with: "
                                            "constants, as usage tables print them",
                                            f.name, arg.text));
          return failed();
        }
        shown.push_back(number_text(*v.constant));
      }
      key = fmt::format("{}({})", arg.text, fmt::join(shown, ", "));
    }
    std::vector<int> ids;
    if (scope_.choices != nullptr) {
      const auto it = scope_.choices->ids.find(key);
      if (it == scope_.choices->ids.end()) {
        std::vector<std::string> names;
        for (const auto& [n, _] : scope_.choices->ids) names.push_back(n);
        const std::string otherwise =
            names.empty() ? fmt::format("no controller compared by experiment `{}` chooses among actions or "
                                        "behaviors (symbolic controllers and supervisors do)",
                                        scope_.choices->experiment)
                          : fmt::format("the actions and behaviors of experiment `{}`: {}", scope_.choices->experiment,
                                        quoted_list(names, ", "));
        suggest(sink_.error(arg.where, fmt::format("`{}` is not an action or behavior of the controllers compared by "
                                                   "experiment `{}`",
                                                   key, scope_.choices->experiment)),
                key, names, {.otherwise = otherwise, .always = names.size() <= 12});
        return failed();
      }
      ids = it->second;
    } else {
      ids = {0};   // checked again in each experiment, with its controllers
    }
    Node out;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const auto id = static_cast<std::uint32_t>(ids[k]);
      if (f.reader == ChoiceReader::Using) {
        out.code.push_back({Op::Load, expr::slot::acting, 0.0});
        out.code.push_back({Op::Const, 0, static_cast<double>(ids[k])});
        out.code.push_back({Op::Eq, 0, 0.0});
        if (k > 0) out.code.push_back({Op::Or, 0, 0.0});
      } else {
        out.code.push_back({Op::Load, expr::aggregate::count + id, 0.0});
        if (k > 0) out.code.push_back({Op::Add, 0, 0.0});
      }
    }
    if (f.reader == ChoiceReader::Share) {
      out.code.push_back({Op::Load, expr::aggregate::steps, 0.0});
      out.code.push_back({Op::Div, 0, 0.0});
    }
    return out;
  }

  // `mean(x)` & co.: x is lowered as a step term and folded by the evaluator; the end term
  // reads the folded value from its slot.
  Node step_aggregate(const ast::Expr& e, const AggregateFunction& f) {
    if (e.args.size() != 1 || !e.args[0]) {
      sink_.error(e.where, fmt::format("`{}` takes 1 argument, the step expression to fold over the steps, found {}",
                                       f.name, e.args.size()));
      return failed();
    }
    if (scope_.use != ExprScope::Use::End || scope_.step_aggregates == nullptr) {
      sink_.error(e.unit_where, fmt::format("`{}(x)` folds x over the steps of an epoch or an evaluation; it is read "
                                            "at their end",
                                            f.name))
          .help.push_back("write it in the fitness's `epoch:` or `evaluation:` term or in a descriptor, e.g. "
                          "`descriptor moving: mean(speed) in [0, 1]`");
      return failed();
    }
    ExprScope each = scope_;
    each.use = ExprScope::Use::Step;
    each.step_aggregates = nullptr;
    auto of = lower_expr(*e.args[0], each, sink_);
    if (!of) return failed();
    const auto k = static_cast<expr::Slot>(scope_.step_aggregates->size());
    scope_.step_aggregates->push_back({f.kind, std::move(*of), 0, 1});
    return load(step_aggregate_slot(scope_.choices) + k);
  }

  void unknown_name(const std::string& text, const SourceRange& where) {
    suggest(sink_.error(where, fmt::format("unknown name `{}`", text)), text, known_names(),
            {.otherwise = "observables are listed in docs/language.md (`speed`, `forward_speed`, `wheel_diff`, "
                          "`wheels[i]`, `ir[i]`, `light[i]`, `energy`, `collision`, `step`, `time`, `epoch`, "
                          "`in(zone)`, `reached(light)`, ...)"});
  }

  Node index(const ast::Expr& e) {
    const auto o = find_observable(e.text, scope_.sensor_names);
    if (!o) {
      unknown_name(e.text, e.unit_where);
      return failed();
    }
    if (scope_.navigation != nullptr)
      if (auto m = misnamed(e.text, *scope_.navigation, scope_.sensor_names)) {
        sink_.error(e.where, std::move(m->message)).help = std::move(m->help);
        return failed();
      }
    if (!o->indexed) {
      sink_.error(e.where, fmt::format("`{}` is a single value and cannot be indexed", e.text))
          .help.push_back(fmt::format("write `{}`", e.text));
      return failed();
    }
    if (e.args.size() != 1) return failed();
    const Node i = lower(*e.args[0]);
    if (!i.ok) return failed();
    if (!i.constant) {
      sink_.error(e.args[0]->where, "an index must be a constant");
      return failed();
    }
    const double v = *i.constant;
    if (v != std::floor(v) || v < 0 || v >= o->count) {
      sink_.error(e.args[0]->where, fmt::format("index {} is out of range: `{}` has {} values, {}[0] .. {}[{}]",
                                                fmt::format("{}", v), e.text, o->count, e.text, e.text,
                                                o->count - 1));
      return failed();
    }
    return observable(o->first + static_cast<expr::Slot>(v), e.where);
  }

  // An observable's slot, unless the experiment lacks its sensor.
  Node observable(expr::Slot s, const SourceRange& where) {
    if (scope_.navigation != nullptr)
      if (auto m = unavailable(s, *scope_.navigation)) {
        sink_.error(where, std::move(m->message)).help = std::move(m->help);
        return failed();
      }
    return load(s);
  }

  // `clusters(15cm)`: the slot of the radius among the experiment's (added when new).
  Node within_radius(const ast::Expr& e, const expr::ParametrisedObservable& o) {
    if (scope_.use == ExprScope::Use::Behavior) {
      sink_.error(e.where, fmt::format("`{}(...)` is the group's, read by fitness terms, objectives and descriptors, "
                                       "not by a behavior", o.name));
      return failed();
    }
    // A length written with its unit: the radius is the experiment's, fixed when it compiles.
    const ast::Expr* arg = e.args.size() == 1 ? e.args[0].get() : nullptr;
    const auto unit = arg != nullptr && arg->kind == ast::Expr::Kind::Number ? find_unit(arg->unit) : std::nullopt;
    if (!unit || unit->dim != Dim::Length || !(arg->number > 0.0) || !std::isfinite(arg->number * unit->to_si)) {
      sink_.error(arg != nullptr ? arg->where : e.where,
                  fmt::format("`{}` takes a radius, a positive length with its unit, as in `{}(15cm)`", o.name, o.name));
      return failed();
    }
    const Node r = constant(arg->number * unit->to_si);
    if (scope_.cluster_radii == nullptr) return load(o.first);
    std::vector<double>& radii = *scope_.cluster_radii;
    auto at = std::find(radii.begin(), radii.end(), *r.constant);
    if (at == radii.end()) {
      if (radii.size() == o.count) {
        std::string listed;
        for (const double v : radii) listed += fmt::format("{}{} m", listed.empty() ? "" : ", ", v);
        sink_.error(e.args[0]->where, fmt::format("an experiment counts clusters within at most {} radii; it reads {} "
                                                  "already", o.count, listed));
        return failed();
      }
      at = radii.insert(radii.end(), *r.constant);
    }
    return load(o.first + static_cast<expr::Slot>(at - radii.begin()));
  }

  Node parametrised(const ast::Expr& e, const expr::ParametrisedObservable& o) {
    if (o.argument == "radius") return within_radius(e, o);
    if (e.args.size() != 1 || !e.args[0] || e.args[0]->kind != ast::Expr::Kind::Name) {
      sink_.error(e.where, fmt::format("`{}` takes the name of a {} of the arena, as in `{}(NAME)`", o.name,
                                       o.argument, o.name));
      return failed();
    }
    const ast::Expr& arg = *e.args[0];
    if (scope_.arena == nullptr) return load(o.first);
    const bool zone = o.argument == "zone";
    const std::vector<std::string>& names = zone ? scope_.arena->zones : scope_.arena->lights;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == arg.text) return load(o.first + static_cast<expr::Slot>(i));
    const std::string otherwise =
        names.empty()
            ? fmt::format("arena `{}` declares no {}; add one, as in `{}`", scope_.arena->arena, o.argument,
                          zone ? "zone base circle radius 10cm at (30cm, 30cm)" : "light lamp at (30cm, 30cm)")
            : fmt::format("{}s of arena `{}`: {}", o.argument, scope_.arena->arena, quoted_list(names, ", "));
    suggest(sink_.error(arg.where, fmt::format("unknown {} `{}` in arena `{}`", o.argument, arg.text,
                                               scope_.arena->arena)),
            arg.text, names, {.otherwise = otherwise});
    return failed();
  }

  Node call(const ast::Expr& e) {
    if (const auto p = expr::find_parametrised(e.text)) return parametrised(e, *p);
    for (const ChoiceFunction& f : kChoiceFunctions)
      if (f.name == e.text) return choice(e, f);
    for (const AggregateFunction& a : kAggregateFunctions)
      if (a.name == e.text && (e.args.size() == 1 || (a.kind != AggregateKind::Min && a.kind != AggregateKind::Max)))
        return step_aggregate(e, a);
    const Function* f = nullptr;
    for (const Function& k : kFunctions)
      if (k.name == e.text) f = &k;
    if (f == nullptr) {
      if (find_observable(e.text, scope_.sensor_names)) {
        sink_.error(e.unit_where, fmt::format("`{}` is an observable, not a function", e.text))
            .help.push_back(fmt::format("index an array with brackets: `{}[0]`", e.text));
        return failed();
      }
      std::vector<std::string> functions = function_names();
      for (const ChoiceFunction& c : kChoiceFunctions) functions.emplace_back(c.name);
      for (const AggregateFunction& a : kAggregateFunctions)
        if (a.kind != AggregateKind::Min && a.kind != AggregateKind::Max) functions.emplace_back(a.name);
      suggest(sink_.error(e.unit_where, fmt::format("unknown function `{}`", e.text)), e.text, functions,
              {.otherwise = "functions: min, max, abs, sqrt, exp, log, tanh, sigmoid, clamp, pow; in a fitness "
                            "also using(B), and in its end terms and descriptors count(B), share(B) and the step "
                            "aggregates mean(x), sum(x), min(x), max(x), fraction(c), last(x)"});
      // Still check the arguments.
      for (const auto& a : e.args) (void)lower(*a);
      return failed();
    }
    if (static_cast<int>(e.args.size()) != f->arity) {
      sink_.error(e.where, fmt::format("`{}` takes {} argument{}, found {}", f->name, f->arity,
                                       f->arity == 1 ? "" : "s", e.args.size()));
      return failed();
    }
    return apply(f->op, e.args);
  }

  Node apply(Op op, const std::vector<ast::ExprPtr>& args) {
    std::vector<Node> nodes;
    bool ok = true;
    for (const auto& a : args) {
      nodes.push_back(a ? lower(*a) : failed());
      ok = ok && nodes.back().ok;
    }
    if (!ok || static_cast<int>(nodes.size()) != expr::arity(op)) return failed();
    return combine(op, nodes);
  }

  static Node combine(Op op, const std::vector<Node>& nodes) {
    bool all_const = true;
    std::vector<double> values;
    for (const Node& n : nodes) {
      all_const = all_const && n.constant.has_value();
      if (n.constant) values.push_back(*n.constant);
    }
    if (all_const) return constant(fold(op, values));
    Node out;
    for (const Node& n : nodes) append(out.code, n);
    out.code.push_back({op, 0, 0.0});
    return out;
  }

  static Node load(expr::Slot s) {
    Node n;
    n.code.push_back({Op::Load, s, 0.0});
    return n;
  }

  const ExprScope& scope_;
  Sink& sink_;
};

}  // namespace

expr::Slot step_aggregate_slot(const ChoiceNames* choices) noexcept {
  return expr::aggregate::count + static_cast<expr::Slot>(choices != nullptr ? choices->count : 0);
}

std::vector<std::string> function_names() {
  std::vector<std::string> v;
  for (const Function& f : kFunctions) v.emplace_back(f.name);
  return v;
}

std::optional<expr::Program> lower_expr(const ast::Expr& e, const ExprScope& scope, Sink& sink) {
  Lowerer l(scope, sink);
  const Node n = l.lower(e);
  if (!n.ok) return std::nullopt;
  expr::Program p;
  try {
    if (n.constant) {
      p.push_const(*n.constant);
    } else {
      for (const expr::Instr& in : n.code) {
        if (in.op == Op::Const) p.push_const(in.value);
        else if (in.op == Op::Load) p.push_load(in.slot);
        else p.push_op(in.op);
      }
    }
  } catch (const std::exception&) {
    sink.error(e.where, "internal error: could not compile this expression");
    return std::nullopt;
  }
  if (p.max_depth() > expr::Program::kMaxStack) {
    sink.error(e.where, fmt::format("expression too deep to evaluate: it needs a stack of {} values, at most {}",
                                    p.max_depth(), expr::Program::kMaxStack))
        .help.push_back("simplify it; a left-to-right sum `a + b + c` needs less stack than `a + (b + c)`");
    return std::nullopt;
  }
  if (!p.complete()) {
    sink.error(e.where, "internal error: incomplete expression program");
    return std::nullopt;
  }
  return p;
}

}  // namespace esc::compiler
