#include "runtime/genome/tree/primitive_set.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace esc::genome::tree {

namespace {

using expr::Op;

[[noreturn]] void fail(const std::string& message) {
  throw std::invalid_argument("primitive set: " + message);
}

Primitive make(std::string name, Kind kind, Type result, std::initializer_list<Type> args) {
  Primitive p;
  p.name = std::move(name);
  p.kind = kind;
  p.result = result;
  p.arity = static_cast<std::uint8_t>(args.size());
  std::copy(args.begin(), args.end(), p.args.begin());
  return p;
}

std::string signature(const Primitive& p) {
  std::string s = "`" + p.name + "` (";
  for (std::size_t k = 0; k < p.arity; ++k) {
    if (k > 0) s += ", ";
    s += name_of(p.args[k]);
  }
  return s + (p.arity > 0 ? " -> " : "-> ") + std::string(name_of(p.result)) + ")";
}

}  // namespace

namespace prim {

Primitive function(Op op) {
  constexpr Type N = Type::Number, B = Type::Bool;
  const auto f = [op](const char* name, Type r, std::initializer_list<Type> a) {
    Primitive p = make(name, Kind::Function, r, a);
    p.op = op;
    return p;
  };
  switch (op) {
    case Op::Neg: return f("-", N, {N});
    case Op::Abs: return f("abs", N, {N});
    case Op::Sqrt: return f("sqrt", N, {N});
    case Op::Exp: return f("exp", N, {N});
    case Op::Log: return f("log", N, {N});
    case Op::Tanh: return f("tanh", N, {N});
    case Op::Sigmoid: return f("sigmoid", N, {N});
    case Op::Add: return f("+", N, {N, N});
    case Op::Sub: return f("-", N, {N, N});
    case Op::Mul: return f("*", N, {N, N});
    case Op::Div: return f("/", N, {N, N});
    case Op::Pow: return f("^", N, {N, N});
    case Op::Min: return f("min", N, {N, N});
    case Op::Max: return f("max", N, {N, N});
    case Op::Clamp: return f("clamp", N, {N, N, N});
    case Op::Lt: return f("<", B, {N, N});
    case Op::Le: return f("<=", B, {N, N});
    case Op::Gt: return f(">", B, {N, N});
    case Op::Ge: return f(">=", B, {N, N});
    case Op::Eq: return f("==", B, {N, N});
    case Op::Ne: return f("!=", B, {N, N});
    case Op::And: return f("and", B, {B, B});
    case Op::Or: return f("or", B, {B, B});
    case Op::Not: return f("not", B, {B});
    case Op::Const:
    case Op::Load:
    case Op::Select: break;
  }
  fail("const, load and select are not function primitives (use constant, observable, "
       "if_then_else)");
}

Primitive if_then_else(Type t) {
  Primitive p = make("if", Kind::Function, t, {Type::Bool, t, t});
  p.op = Op::Select;
  return p;
}

Primitive observable(std::string name, expr::Slot slot, Type t) {
  Primitive p = make(std::move(name), Kind::Observable, t, {});
  p.slot = slot;
  return p;
}

std::optional<Primitive> observable(std::string_view script_name) {
  std::string_view base = script_name;
  std::optional<std::size_t> index;
  if (const auto open = script_name.find('['); open != std::string_view::npos) {
    if (script_name.back() != ']' || open + 2 > script_name.size() - 1) return std::nullopt;
    base = script_name.substr(0, open);
    std::size_t i = 0;
    for (char c : script_name.substr(open + 1, script_name.size() - open - 2)) {
      if (c < '0' || c > '9') return std::nullopt;
      i = i * 10 + static_cast<std::size_t>(c - '0');
      if (i > 1000) return std::nullopt;
    }
    index = i;
  }
  const auto o = expr::find_observable(base);
  if (!o || o->indexed != index.has_value()) return std::nullopt;
  if (index && *index >= o->count) return std::nullopt;
  const Type t = o->unit.starts_with("boolean") ? Type::Bool : Type::Number;
  return observable(std::string(script_name), o->first + static_cast<expr::Slot>(index.value_or(0)), t);
}

std::vector<Primitive> all_observables() {
  std::vector<Primitive> out;
  for (const auto& o : expr::kObservables) {
    if (!o.indexed) {
      out.push_back(*observable(o.name));
      continue;
    }
    for (expr::Slot i = 0; i < o.count; ++i)
      out.push_back(*observable(fmt::format("{}[{}]", o.name, i)));
  }
  return out;
}

Primitive constant(Type t, double value) {
  std::string name = t == Type::Bool ? (value != 0.0 ? "true" : "false") : fmt::format("{}", value);
  Primitive p = make(std::move(name), Kind::Constant, t, {});
  p.value = t == Type::Bool ? (value != 0.0 ? 1.0 : 0.0) : value;
  return p;
}

Primitive erc(double lo, double hi) {
  Primitive p = make("erc", Kind::Erc, Type::Number, {});
  p.lo = lo;
  p.hi = hi;
  return p;
}

Primitive action(std::string name, std::uint32_t index, std::uint8_t params) {
  Primitive p = make(std::move(name), Kind::Action, Type::Action, {});
  p.index = index;
  p.arity = params;
  for (std::size_t k = 0; k < kMaxArity; ++k) p.args[k] = Type::Number;
  return p;
}

Primitive behavior(std::string name, std::uint32_t index) {
  Primitive p = make(std::move(name), Kind::Behavior, Type::Behavior, {});
  p.index = index;
  return p;
}

Primitive wheels() { return make("wheels", Kind::Wheels, Type::Wheels, {Type::Number, Type::Number}); }

std::vector<Primitive> standard_functions() {
  return {function(Op::Add), function(Op::Sub), function(Op::Mul), function(Op::Div),
          function(Op::Min), function(Op::Max), function(Op::Abs), function(Op::Lt),
          function(Op::Gt),  function(Op::And), function(Op::Or),  function(Op::Not),
          if_then_else(Type::Number), constant(Type::Bool, 1.0), constant(Type::Bool, 0.0)};
}

}  // namespace prim

PrimitiveSet::PrimitiveSet(std::vector<Primitive> primitives, Type root)
    : prims_(std::move(primitives)), root_(root) {
  if (prims_.empty()) fail("it is empty");
  if (prims_.size() > 0xFFFF) fail(fmt::format("{} primitives, at most 65535", prims_.size()));

  for (std::size_t id = 0; id < prims_.size(); ++id) {
    const Primitive& p = prims_[id];
    if (p.arity > kMaxArity)
      fail(fmt::format("{} takes {} arguments, at most {}", signature(p), p.arity, kMaxArity));
    switch (p.kind) {
      case Kind::Function: {
        if (p.op == Op::Const || p.op == Op::Load) fail(signature(p) + " has no operator");
        const int want = p.op == Op::Select ? 3 : expr::arity(p.op);
        if (p.arity != want)
          fail(fmt::format("{} must take {} arguments", signature(p), want));
        if (p.op == Op::Select && (p.args[0] != Type::Bool || p.args[1] != p.result ||
                                   p.args[2] != p.result))
          fail(signature(p) + ": if-then-else must be (Bool, T, T -> T)");
        if (p.op != Op::Select &&
            (p.result == Type::Action || p.result == Type::Behavior || p.result == Type::Wheels))
          fail(signature(p) + ": an operator returns a Number or a Bool");
        break;
      }
      case Kind::Observable:
        if (p.slot >= expr::kFrameSize)
          fail(fmt::format("observable `{}` reads slot {}, outside the frame ({} slots)", p.name,
                           p.slot, expr::kFrameSize));
        [[fallthrough]];
      case Kind::Constant:
        if (p.arity != 0) fail(signature(p) + ": a terminal takes no arguments");
        if (p.result != Type::Number && p.result != Type::Bool)
          fail(signature(p) + ": a terminal value is a Number or a Bool");
        if (!std::isfinite(p.value)) fail("constant `" + p.name + "` is not finite");
        break;
      case Kind::Erc:
        if (!(std::abs(p.lo) <= prim::kMaxErcBound && std::abs(p.hi) <= prim::kMaxErcBound && p.lo < p.hi))
          fail(fmt::format("random constant range [{}, {}] must be non-empty and within +-1e6", p.lo, p.hi));
        if (p.arity != 0 || p.result != Type::Number) fail("a random constant is a Number terminal");
        break;
      case Kind::Action:
        if (p.result != Type::Action) fail(signature(p) + ": an action returns Action");
        if (p.arity > expr::kMaxParams)
          fail(fmt::format("action `{}` takes {} parameters, at most {}", p.name, p.arity,
                           expr::kMaxParams));
        for (Type t : p.arg_types())
          if (t != Type::Number) fail(signature(p) + ": action parameters are Numbers");
        break;
      case Kind::Behavior:
        if (p.result != Type::Behavior || p.arity != 0)
          fail(signature(p) + ": a behavior is a terminal of type Behavior");
        break;
      case Kind::Wheels:
        if (p.result != Type::Wheels || p.arity != 2 || p.args[0] != Type::Number ||
            p.args[1] != Type::Number)
          fail(signature(p) + ": wheels is (Number, Number -> Wheels)");
        break;
    }
    by_type_[index_of(p.result)].push_back(static_cast<PrimitiveId>(id));
  }

  // Shallowest and smallest trees by fixed point (Bellman-Ford style; at most |prims| rounds).
  type_depth_.fill(kUnbuildable);
  type_size_.fill(kUnbuildable);
  prim_depth_.assign(prims_.size(), kUnbuildable);
  prim_size_.assign(prims_.size(), kUnbuildable);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t id = 0; id < prims_.size(); ++id) {
      const Primitive& p = prims_[id];
      int d = 1, s = 1;
      for (Type t : p.arg_types()) {
        d = std::max(d, std::min(kUnbuildable, type_depth_[index_of(t)] + 1));
        s = std::min(kUnbuildable, s + type_size_[index_of(t)]);
      }
      if (d < prim_depth_[id] || s < prim_size_[id]) {
        prim_depth_[id] = std::min(prim_depth_[id], d);
        prim_size_[id] = std::min(prim_size_[id], s);
        auto& td = type_depth_[index_of(p.result)];
        auto& ts = type_size_[index_of(p.result)];
        td = std::min(td, prim_depth_[id]);
        ts = std::min(ts, prim_size_[id]);
        changed = true;
      }
    }
  }

  // Every type reachable from the root must be buildable.
  std::array<bool, kTypeCount> reached{};
  std::array<std::string, kTypeCount> needed_by;
  std::vector<Type> todo = {root_};
  std::vector<Type> order;  // reachable types, root first
  reached[index_of(root_)] = true;
  needed_by[index_of(root_)] = "the root";
  while (!todo.empty()) {
    const Type t = todo.front();
    todo.erase(todo.begin());
    order.push_back(t);
    if (by_type_[index_of(t)].empty())
      fail(fmt::format("no primitive returns {}, needed by {}", name_of(t), needed_by[index_of(t)]));
    for (PrimitiveId id : by_type_[index_of(t)])
      for (Type a : prims_[id].arg_types())
        if (!reached[index_of(a)]) {
          reached[index_of(a)] = true;
          needed_by[index_of(a)] = signature(prims_[id]);
          todo.push_back(a);
        }
  }
  // Of the unbuildable types, name the cause: one whose every primitive needs an argument
  // of its own type (a type lacking terminals), else the first one found.
  std::optional<Type> culprit;
  for (Type t : order) {
    if (type_depth_[index_of(t)] < kUnbuildable) continue;
    bool self_only = true;
    for (PrimitiveId id : by_type_[index_of(t)]) {
      const auto args = prims_[id].arg_types();
      self_only = self_only && std::find(args.begin(), args.end(), t) != args.end();
    }
    if (!culprit || self_only) culprit = t;
    if (self_only) break;
  }
  if (culprit) {
    const Type t = *culprit;
    fail(fmt::format("no finite tree of type {} can be built (needed by {}): every primitive "
                     "returning {} needs an argument that cannot be built; add a {} terminal",
                     name_of(t), needed_by[index_of(t)], name_of(t), name_of(t)));
  }
}

bool PrimitiveSet::same_signature(PrimitiveId a, PrimitiveId b) const noexcept {
  const Primitive& x = prims_[a];
  const Primitive& y = prims_[b];
  if (x.result != y.result || x.arity != y.arity) return false;
  for (std::size_t k = 0; k < x.arity; ++k)
    if (x.args[k] != y.args[k]) return false;
  return true;
}

}  // namespace esc::genome::tree
