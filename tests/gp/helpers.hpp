#pragma once
// Primitive sets and random frames shared by the GP tests.
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/genome/tree/primitive_set.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::genome::tree::test {

inline std::vector<Primitive> numeric_primitives() {
  using expr::Op;
  std::vector<Primitive> p;
  for (Op op : {Op::Add, Op::Sub, Op::Mul, Op::Div, Op::Pow, Op::Min, Op::Max, Op::Neg, Op::Abs,
                Op::Sqrt, Op::Exp, Op::Log, Op::Tanh, Op::Sigmoid, Op::Clamp, Op::Lt, Op::Le,
                Op::Gt, Op::Ge, Op::Eq, Op::Ne, Op::And, Op::Or, Op::Not})
    p.push_back(prim::function(op));
  p.push_back(prim::if_then_else(Type::Number));
  p.push_back(prim::if_then_else(Type::Bool));
  p.push_back(prim::constant(Type::Bool, 1.0));
  p.push_back(prim::constant(Type::Bool, 0.0));
  p.push_back(prim::constant(Type::Number, 0.0));
  p.push_back(prim::erc(-1.0, 1.0));
  for (const char* name : {"ir[0]", "ir[1]", "ir[2]", "ir[3]", "ir[4]", "ir[5]", "speed", "collision"})
    p.push_back(*prim::observable(name));
  return p;
}

inline PrimitiveSet number_set() { return PrimitiveSet(numeric_primitives(), Type::Number); }

inline PrimitiveSet wheels_set() {
  auto p = numeric_primitives();
  p.push_back(prim::wheels());
  p.push_back(prim::if_then_else(Type::Wheels));
  return PrimitiveSet(std::move(p), Type::Wheels);
}

// forward(p), left(p), right(p), backward(p) as actions 0..3, and stop() as action 4.
inline PrimitiveSet action_set() {
  auto p = numeric_primitives();
  p.push_back(prim::action("forward", 0));
  p.push_back(prim::action("left", 1));
  p.push_back(prim::action("right", 2));
  p.push_back(prim::action("backward", 3));
  p.push_back(prim::action("stop", 4, 0));
  p.push_back(prim::if_then_else(Type::Action));
  return PrimitiveSet(std::move(p), Type::Action);
}

inline PrimitiveSet behavior_set() {
  auto p = numeric_primitives();
  p.push_back(prim::behavior("avoid", 0));
  p.push_back(prim::behavior("explore", 1));
  p.push_back(prim::behavior("home", 2));
  p.push_back(prim::if_then_else(Type::Behavior));
  return PrimitiveSet(std::move(p), Type::Behavior);
}

inline std::vector<PrimitiveSet> all_sets() {
  return {number_set(), wheels_set(), action_set(), behavior_set()};
}

// Mostly uniform in [-1, 1], with exact zeros, ones and large values mixed in so that
// protected division, comparisons and if-then-else take every path.
inline expr::Frame random_frame(Rng& rng) {
  expr::Frame f{};
  for (double& v : f) {
    const double u = rng.uniform();
    v = u < 0.1 ? 0.0 : u < 0.15 ? 1.0 : u < 0.2 ? rng.uniform(-1e6, 1e6) : rng.uniform(-1.0, 1.0);
  }
  f[expr::slot::collision] = rng.uniform() < 0.5 ? 1.0 : 0.0;
  return f;
}

}  // namespace esc::genome::tree::test

#include <initializer_list>
#include <stdexcept>
#include <string>

#include "runtime/genome/tree/tree.hpp"

namespace esc::genome::tree::test {

struct Tok {
  std::string name;   // primitive name; "neg" for unary minus; "erc" with a value
  double value = 0.0;
  Tok(const char* n) : name(n) {}  // NOLINT: implicit for brevity in tests
  Tok(const char* n, double v) : name(n), value(v) {}
};

// A tree from postfix tokens. Among primitives of that name, the one of greatest arity whose
// argument types match the top of the type stack is used, so "-" is binary minus, "if"
// picks its type from its branches.
inline Tree postfix(const PrimitiveSet& set, std::initializer_list<Tok> toks) {
  Tree t;
  std::vector<Type> types;
  for (const Tok& tok : toks) {
    int best = -1;
    for (std::size_t id = 0; id < set.size(); ++id) {
      const Primitive& p = set[static_cast<PrimitiveId>(id)];
      const bool named = tok.name == "neg" ? (p.kind == Kind::Function && p.op == expr::Op::Neg)
                                           : p.name == tok.name;
      if (!named || p.arity > types.size()) continue;
      bool match = true;
      for (std::size_t k = 0; k < p.arity; ++k)
        match = match && types[types.size() - p.arity + k] == p.args[k];
      if (match && (best < 0 || p.arity > set[static_cast<PrimitiveId>(best)].arity))
        best = static_cast<int>(id);
    }
    if (best < 0) throw std::invalid_argument("postfix: no primitive for " + tok.name);
    const auto id = static_cast<PrimitiveId>(best);
    t.nodes.push_back(make_node(set, id, tok.value));
    types.resize(types.size() - set[id].arity);
    types.push_back(set[id].result);
  }
  if (!update_lengths(t)) throw std::invalid_argument("postfix: not one tree");
  return t;
}

}  // namespace esc::genome::tree::test

#include "runtime/control/behavior.hpp"

namespace esc::genome::tree::test {

// behavior NAME(p) { wheels(sl * p, sr * p) } with sl, sr in {-1, 1}.
inline control::Behavior signed_behavior(const char* name, double sl, double sr) {
  control::Behavior b;
  b.name = name;
  b.params = {"p"};
  b.left.push_load(expr::slot::param);
  if (sl < 0) b.left.push_op(expr::Op::Neg);
  b.right.push_load(expr::slot::param);
  if (sr < 0) b.right.push_op(expr::Op::Neg);
  return b;
}

// forward, left, right, backward (one parameter each) and stop (none): action_set()'s list.
inline std::vector<control::Behavior> standard_actions() {
  control::Behavior stop;
  stop.name = "stop";
  stop.left = expr::Program::constant(0.0);
  stop.right = expr::Program::constant(0.0);
  return {signed_behavior("forward", 1, 1), signed_behavior("left", -1, 1),
          signed_behavior("right", 1, -1), signed_behavior("backward", -1, -1), stop};
}

}  // namespace esc::genome::tree::test
