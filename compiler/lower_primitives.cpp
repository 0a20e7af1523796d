// Primitive sets: `primitives NAME { functions ... terminals ... }` -> GP primitives, and the
// primitive set of each `tree(...)` controller.
#include "compiler/lower_primitives.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/quantities.hpp"
#include "compiler/sensor_uses.hpp"
#include "compiler/units.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::compiler {

namespace {

using expr::Op;

struct FunctionName {
  std::string_view name;
  Op op;
};

// `if` is not here: it is if-then-else over Numbers and over the tree's result.
constexpr FunctionName kFunctions[] = {
    {"+", Op::Add},         {"-", Op::Sub},      {"*", Op::Mul},   {"/", Op::Div},   {"^", Op::Pow},
    {"pow", Op::Pow},       {"min", Op::Min},    {"max", Op::Max}, {"abs", Op::Abs}, {"sqrt", Op::Sqrt},
    {"exp", Op::Exp},       {"log", Op::Log},    {"tanh", Op::Tanh}, {"sigmoid", Op::Sigmoid},
    {"clamp", Op::Clamp},   {"neg", Op::Neg},    {"<", Op::Lt},    {"<=", Op::Le},   {">", Op::Gt},
    {">=", Op::Ge},         {"==", Op::Eq},      {"!=", Op::Ne},   {"and", Op::And}, {"or", Op::Or},
    {"not", Op::Not},
};

std::vector<std::string> function_words() {
  std::vector<std::string> v;
  for (const FunctionName& f : kFunctions) v.emplace_back(f.name);
  v.emplace_back("if");
  return v;
}

std::string function_help() {
  std::string s;
  for (const std::string& w : function_words()) s += (s.empty() ? "" : " ") + w;
  return "functions: " + s;
}

genome::tree::Type root_of(control::Head h) {
  return h == control::Head::Symbolic ? genome::tree::Type::Action
         : h == control::Head::Supervisor ? genome::tree::Type::Behavior
                                          : genome::tree::Type::Wheels;
}

std::string_view use_of(genome::tree::Type root) {
  return root == genome::tree::Type::Action ? "an Action tree" : root == genome::tree::Type::Behavior ? "a Behavior tree" : "a Wheels tree";
}

}  // namespace

const std::optional<PrimitiveList>& PrimitivesLowering::lower(const ast::PrimitivesDecl& d) {
  if (auto it = lists_.find(&d); it != lists_.end()) return it->second;
  auto& slot = lists_[&d];
  if (d.poisoned) return slot;
  const int errors = sink_.errors();
  PrimitiveList list;
  std::map<std::string, SourceRange> seen;
  const auto once = [&](const std::string& text, const SourceRange& where) {
    if (auto [it, fresh] = seen.try_emplace(text, where); !fresh) {
      sink_.error(where, fmt::format("`{}` is listed twice", text)).notes.emplace_back(it->second, "first listed here");
      return false;
    }
    return true;
  };

  for (const ast::PrimFunction& f : d.functions) {
    if (!once(f.text, f.where)) continue;
    if (f.text == "if") {
      list.branches = true;
      list.items.push_back(genome::tree::prim::if_then_else(genome::tree::Type::Number));
      continue;
    }
    const auto* fn = std::find_if(std::begin(kFunctions), std::end(kFunctions),
                                  [&](const FunctionName& k) { return k.name == f.text; });
    if (fn == std::end(kFunctions)) {
      suggest(sink_.error(f.where, fmt::format("unknown function `{}`", f.text)), f.text, function_words(),
              {.otherwise = function_help(), .always = true});
      continue;
    }
    list.items.push_back(genome::tree::prim::function(fn->op));
  }

  const std::vector<std::string> observables = expr::observable_names();
  for (const ast::PrimTerminal& t : d.terminals) {
    using TK = ast::PrimTerminal::Kind;
    if (t.kind == TK::Bool) {
      if (once(t.flag ? "true" : "false", t.where))
        list.items.push_back(genome::tree::prim::constant(genome::tree::Type::Bool, t.flag ? 1 : 0));
      continue;
    }
    if (t.kind == TK::Constant) {
      if (!t.value.finite) continue;
      double v = t.value.value;
      if (!t.value.unit.empty()) {
        const auto u = find_unit(t.value.unit);
        if (!u) {
          sink_.error(t.value.unit_where, fmt::format("unknown unit `{}`", t.value.unit));
          continue;
        }
        v *= u->to_si;
      }
      if (once(number_text(v), t.where)) list.items.push_back(genome::tree::prim::constant(genome::tree::Type::Number, v));
      continue;
    }
    if (t.kind == TK::Erc) {
      if (t.name.text != "erc") {
        sink_.error(t.name.where, fmt::format("unknown terminal `{}(...)`", t.name.text))
            .help.push_back("the terminal with arguments is `erc(LO, HI)`, an ephemeral random constant");
        continue;
      }
      const auto lo = to_si(*t.lo, Dim::None, sink_), hi = to_si(*t.hi, Dim::None, sink_);
      if (!lo || !hi) continue;
      if (!(*lo < *hi)) {
        sink_.error(t.where, fmt::format("empty range: `erc({}, {})` needs its first bound below the second",
                                         number_text(*lo), number_text(*hi)));
        continue;
      }
      if (std::abs(*lo) > genome::tree::prim::kMaxErcBound || std::abs(*hi) > genome::tree::prim::kMaxErcBound) {
        sink_.error(t.where, fmt::format("`erc({0}, {1})` must lie within [-{2}, {2}]", number_text(*lo), number_text(*hi),
                                         number_text(genome::tree::prim::kMaxErcBound)))
            .help.push_back("beyond that the random constants' steps lose their precision and can overflow");
        continue;
      }
      list.items.push_back(genome::tree::prim::erc(*lo, *hi));
      continue;
    }
    // An observable, all of an array, or a range of it.
    const std::string& name = t.name.text;
    if (name.empty()) continue;
    const auto o = find_observable(name, &names_.sensor_names());
    if (!o) {
      if (names_.find<ast::BehaviorDecl>(name) != nullptr) {
        sink_.error(t.name.where, fmt::format("`{}` is a behavior, not a terminal", name))
            .help.push_back("a tree controller lists its actions or behaviors itself: "
                            "`tree(actions [forward, left, right], primitives P)`");
        continue;
      }
      if (name == "erc") {
        sink_.error(t.where, "`erc` needs its range").help.push_back("write `erc(-1, 1)`");
        continue;
      }
      suggest(sink_.error(t.name.where, fmt::format("unknown observable `{}`", name)), name, observables,
              {.otherwise = "terminals are observables (`ir[0..7]`, `speed`, ...), numbers, `true`, `false` and "
                            "`erc(LO, HI)`"});
      continue;
    }
    if (t.lo && !o->indexed) {
      sink_.error(t.where, fmt::format("`{}` is a single value and cannot be indexed", name));
      continue;
    }
    long long first = 0, last = o->indexed ? o->count - 1 : 0;
    if (t.lo) {
      const auto lo = to_whole(*t.lo, "an index", 0, o->count - 1, sink_);
      std::optional<long long> hi = lo;
      if (t.hi) hi = to_whole(*t.hi, "an index", 0, o->count - 1, sink_);
      if (!lo || !hi) continue;
      if (*hi < *lo) {
        sink_.error(t.where, fmt::format("empty range `{}[{}..{}]`: the first index must not exceed the last", name,
                                         *lo, *hi));
        continue;
      }
      first = *lo;
      last = *hi;
    }
    for (long long i = first; i <= last; ++i) {
      const std::string shown = o->indexed ? fmt::format("{}[{}]", name, i) : name;
      if (!once(shown, t.where)) continue;
      list.items.push_back(genome::tree::prim::observable(shown, o->first + static_cast<expr::Slot>(i)));
    }
  }
  if (sink_.errors() == errors) slot = std::move(list);
  return slot;
}

bool PrimitivesLowering::tree(const ast::ControllerDecl& d, control::ControllerSpec& c) {
  if (!d.symbolic && !d.supervisor && d.tree_result.text != "wheels") {
    if (d.tree_result.text.empty()) return false;   // a syntax error, reported
    suggest(
        sink_.error(d.tree_result.where, fmt::format("unknown tree result `{}`", d.tree_result.text)),
        d.tree_result.text, {"wheels"},
        {.otherwise = "a tree returns `wheels`, one of `actions [A, B, ...]` or one of `behaviors [A, B(0.5), ...]`",
         .always = true});
    return false;
  }
  const auto* pd = names_.lookup<ast::PrimitivesDecl>(d.primitives);
  if (pd == nullptr) return false;
  const auto& list = lower(*pd);
  if (!list) return false;
  const genome::tree::Type root = root_of(c.head);
  std::vector<genome::tree::Primitive> items = list->items;
  if (list->branches) items.push_back(genome::tree::prim::if_then_else(root));
  if (root == genome::tree::Type::Wheels) items.push_back(genome::tree::prim::wheels());
  for (std::size_t k = 0; k < c.actions.size(); ++k)
    items.push_back(genome::tree::prim::action(c.actions[k].name, static_cast<std::uint32_t>(k),
                                     static_cast<std::uint8_t>(c.actions[k].params.size())));
  for (std::size_t k = 0; k < c.behaviors.size(); ++k)
    items.push_back(genome::tree::prim::behavior(c.behaviors[k].name, static_cast<std::uint32_t>(k)));
  try {
    c.primitives = std::make_shared<const genome::tree::PrimitiveSet>(std::move(items), root);
  } catch (const std::invalid_argument& e) {
    std::string why = e.what();
    if (why.rfind("primitive set: ", 0) == 0) why.erase(0, 15);
    const std::string msg = fmt::format("primitive set `{}` cannot build {}: {}", pd->name.text, use_of(root), why);
    if (reported_sets_.insert(msg).second)
      sink_.error(pd->name.where, msg)
          .notes.emplace_back(d.primitives.where,
                              fmt::format("used by tree controller `{}` here, which needs {}", d.name.text,
                                          use_of(root)));
    return false;
  }
  c.primitives_name = pd->name.text;
  return true;
}

}  // namespace esc::compiler
