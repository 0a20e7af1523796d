#include "runtime/tree_control/inline_actions.hpp"

#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace esc::tree_control {

namespace {

using genome::tree::Kind;
using genome::tree::Node;
using genome::tree::Primitive;
using genome::tree::PrimitiveId;
using genome::tree::PrimitiveSet;
using genome::tree::Tree;
using genome::tree::Type;
using expr::Op;
namespace prim = genome::tree::prim;

[[noreturn]] void fail(const std::string& why) { throw std::invalid_argument("inline_actions: " + why); }

// A behavior program as an expression tree (expr::Program is postfix code).
struct Expr {
  expr::Instr in;
  std::vector<Expr> args;
};

Expr expression(const expr::Program& p) {
  std::vector<Expr> stack;
  for (const expr::Instr& in : p.code()) {
    Expr e{in, {}};
    const auto n = static_cast<std::size_t>(in.op == Op::Const || in.op == Op::Load ? 0 : expr::arity(in.op));
    if (stack.size() < n) fail("a behavior program is incomplete");
    e.args.assign(std::make_move_iterator(stack.end() - static_cast<std::ptrdiff_t>(n)),
                  std::make_move_iterator(stack.end()));
    stack.resize(stack.size() - n);
    stack.push_back(std::move(e));
  }
  if (stack.size() != 1) fail("a behavior program is incomplete");
  return std::move(stack.front());
}

bool is_condition(Op op) noexcept {
  switch (op) {
    case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne:
    case Op::And: case Op::Or: case Op::Not: return true;
    default: return false;
  }
}

// Builds the new primitive list and the new tree's nodes (primitive id, value) in postfix.
class Inliner {
 public:
  Inliner(const Tree& tree, const PrimitiveSet& set, std::span<const control::Behavior> actions)
      : t_(tree), set_(set), actions_(actions), prims_(set.primitives().begin(), set.primitives().end()) {
    // Holds the behaviors' constants, any finite value: never drawn, so its range is only
    // the one any random constant must have.
    constant_ = add(prim::erc(-prim::kMaxErcBound, prim::kMaxErcBound));
    wheels_ = add(prim::wheels());
    if_wheels_ = add(prim::if_then_else(Type::Wheels));
    not_zero_ = function(Op::Ne, Type::Bool);
  }

  InlinedTree run() {
    action_tree(t_.root());
    PrimitiveSet set(std::move(prims_), Type::Wheels);
    Tree out;
    out.nodes.reserve(nodes_.size());
    for (const auto& [id, value] : nodes_) out.nodes.push_back(make_node(set, id, value));
    if (!update_lengths(out)) fail("internal error: the arities do not form one tree");
    if (const std::string why = check(out, set, Type::Wheels); !why.empty()) fail("internal error: " + why);
    return {std::move(set), std::move(out)};
  }

 private:
  PrimitiveId add(Primitive p) {
    prims_.push_back(std::move(p));
    return static_cast<PrimitiveId>(prims_.size() - 1);
  }

  // An operator taking Numbers, returning `result` (a Bool only as a condition).
  PrimitiveId function(Op op, Type result) {
    const auto key = std::make_pair(op, result);
    if (const auto it = functions_.find(key); it != functions_.end()) return it->second;
    Primitive p = op == Op::Select ? prim::if_then_else(Type::Number) : prim::function(op);
    if (op != Op::Select) {
      p.result = result;
      for (std::size_t k = 0; k < p.arity; ++k) p.args[k] = Type::Number;
    }
    return functions_[key] = add(std::move(p));
  }

  PrimitiveId observable(expr::Slot slot) {
    if (const auto it = observables_.find(slot); it != observables_.end()) return it->second;
    if (const std::optional<std::string> name = expr::observable_name(slot))
      return observables_[slot] = add(prim::observable(*name, slot, Type::Number));
    fail(fmt::format("a behavior reads frame slot {}, which has no name of its own in scripts", slot));
  }

  void copy_subtree(std::size_t i) {
    for (std::size_t k = t_.begin_of(i); k <= i; ++k) nodes_.emplace_back(t_.nodes[k].prim, t_.nodes[k].value);
  }

  // Expression `e` of a behavior, its parameters the subtrees `params` of the tree, as a
  // `want` (Number, or Bool for a condition).
  void emit(const Expr& e, std::span<const std::size_t> params, Type want) {
    const Op op = e.in.op;
    const bool condition = want == Type::Bool && !is_condition(op);
    if (op == Op::Const) {
      nodes_.emplace_back(constant_, e.in.value);
    } else if (op == Op::Load && e.in.slot >= expr::slot::param && e.in.slot < expr::slot::param + expr::kMaxParams) {
      const std::size_t k = e.in.slot - expr::slot::param;
      if (k >= params.size()) fail("a behavior reads a parameter its action does not pass");
      copy_subtree(params[k]);
    } else if (op == Op::Load) {
      nodes_.emplace_back(observable(e.in.slot), 0.0);
    } else {
      for (std::size_t k = 0; k < e.args.size(); ++k)
        emit(e.args[k], params, op == Op::Select && k == 0 ? Type::Bool : Type::Number);
      nodes_.emplace_back(function(op, is_condition(op) ? want : Type::Number), 0.0);
    }
    if (condition) {   // c != 0 selects what c selects
      nodes_.emplace_back(constant_, 0.0);
      nodes_.emplace_back(not_zero_, 0.0);
    }
  }

  // The Action subtree at node i, as a Wheels subtree.
  void action_tree(std::size_t i) {
    const Node& n = t_.nodes[i];
    const Primitive& p = set_[n.prim];
    const auto c = children(t_, i);
    if (p.kind == Kind::Function && p.op == Op::Select && p.result == Type::Action) {
      copy_subtree(c[0]);
      action_tree(c[1]);
      action_tree(c[2]);
      nodes_.emplace_back(if_wheels_, 0.0);
      return;
    }
    if (p.kind != Kind::Action) fail(fmt::format("`{}` is not an action", p.name));
    if (p.index >= actions_.size()) fail(fmt::format("action `{}` has no behavior", p.name));
    const control::Behavior& b = actions_[p.index];
    if (b.params.size() != p.arity)
      fail(fmt::format("action `{}` passes {} parameters, behavior `{}` takes {}", p.name, p.arity, b.name,
                       b.params.size()));
    const std::span<const std::size_t> params(c.data(), p.arity);
    emit(expression(b.left), params, Type::Number);
    emit(expression(b.right), params, Type::Number);
    nodes_.emplace_back(wheels_, 0.0);
  }

  const Tree& t_;
  const PrimitiveSet& set_;
  std::span<const control::Behavior> actions_;
  std::vector<Primitive> prims_;
  std::vector<std::pair<PrimitiveId, double>> nodes_;
  std::map<std::pair<Op, Type>, PrimitiveId> functions_;
  std::map<expr::Slot, PrimitiveId> observables_;
  PrimitiveId constant_ = 0, wheels_ = 0, if_wheels_ = 0, not_zero_ = 0;
};

}  // namespace

InlinedTree inline_actions(const Tree& tree, const PrimitiveSet& set, std::span<const control::Behavior> actions) {
  if (const std::string why = check(tree, set, Type::Action); !why.empty()) fail("not an Action tree: " + why);
  return Inliner(tree, set, actions).run();
}

}  // namespace esc::tree_control
