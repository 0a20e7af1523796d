#pragma once
// Typed primitives and the set a GP run draws from. A script declares the set (functions,
// observables, constants, ephemeral random constants, actions of a list, behaviors of a
// list) and the root type; the compiler builds one Primitive per item with the factory
// functions below and hands the list to PrimitiveSet, whose constructor checks that a
// finite tree of every type reachable from the root can be built (so initialisation and
// mutation always finish at any depth limit) and throws std::invalid_argument with a
// message naming the type otherwise: the compiler reports that message as a compile error.
//
//   std::vector<Primitive> p = {prim::function(expr::Op::Add), prim::function(expr::Op::Mul),
//                               prim::if_then_else(Type::Number), prim::erc(-1, 1),
//                               *prim::observable("ir[0]"), prim::wheels()};
//   PrimitiveSet set(std::move(p), Type::Wheels);
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/genome/tree/types.hpp"
#include "runtime/expr/observables.hpp"
#include "runtime/expr/program.hpp"

namespace esc::genome::tree {

enum class Kind : std::uint8_t {
  Function,    // an expr operator over Number/Bool (op), or if-then-else (op Select) of any type
  Observable,  // terminal: frame[slot]
  Constant,    // terminal: a fixed value (true, false, 0.5)
  Erc,         // terminal: ephemeral random constant, uniform in [lo, hi] when created
  Action,      // action `index` of the controller's action list, with arity Number parameters
  Behavior,    // terminal: behavior `index` of the controller's behavior list
  Wheels,      // wheels(left, right): two Numbers, the root of a tree controller
};

using PrimitiveId = std::uint16_t;
inline constexpr std::size_t kMaxArity = 4;  // clamp and if-then-else take 3, actions up to 4

struct Primitive {
  std::string name;   // printed text: "min", "+", "ir[0]", "forward", "true", "erc", "wheels"
  Kind kind = Kind::Function;
  Type result = Type::Number;
  std::uint8_t arity = 0;
  std::array<Type, kMaxArity> args{};
  expr::Op op = expr::Op::Const;  // Function
  expr::Slot slot = 0;            // Observable
  double value = 0.0;             // Constant
  double lo = -1.0, hi = 1.0;     // Erc
  std::uint32_t index = 0;        // Action, Behavior

  [[nodiscard]] bool terminal() const noexcept { return arity == 0; }
  [[nodiscard]] std::span<const Type> arg_types() const noexcept { return {args.data(), arity}; }
};

// Factories for the primitives a script can declare.
namespace prim {
// An expr operator with its natural signature: + - * / ^ min max (Number, Number -> Number),
// - abs sqrt exp log tanh sigmoid (Number -> Number), clamp (3 Numbers), < <= > >= == !=
// (Number, Number -> Bool), and or (Bool, Bool -> Bool), not (Bool -> Bool). Div is
// protected (x / 0 = 0) like every expr operator. Throws std::invalid_argument for
// Const, Load and Select (use if_then_else).
[[nodiscard]] Primitive function(expr::Op op);
// if c then a else b, of type t: (Bool, t, t) -> t. One per type that should branch.
[[nodiscard]] Primitive if_then_else(Type t);
// A frame slot read as a terminal; `name` is how it is printed ("ir[3]", "speed").
[[nodiscard]] Primitive observable(std::string name, expr::Slot slot, Type t = Type::Number);
// A script observable by its script name, "speed" or "ir[3]"; nullopt if unknown, out of
// range, an array without index or a scalar with one. Observables whose unit is "boolean"
// (collision, ...) are typed Bool, the others Number.
[[nodiscard]] std::optional<Primitive> observable(std::string_view script_name);
// Every script observable, arrays expanded (speed, forward_speed, ..., ir[0] .. ir[7], ...).
[[nodiscard]] std::vector<Primitive> all_observables();
[[nodiscard]] Primitive constant(Type t, double value);  // Bool constants print true/false
// LO and HI within +-kMaxErcBound: HI - LO and the point mutations' steps stay finite.
inline constexpr double kMaxErcBound = 1e6;
[[nodiscard]] Primitive erc(double lo, double hi);
// Action `index` of the action list, printed `name(p1, ...)`, with `params` Number arguments
// (0 .. expr::kMaxParams), which the controller stores in frame[slot::param + k].
[[nodiscard]] Primitive action(std::string name, std::uint32_t index, std::uint8_t params = 1);
[[nodiscard]] Primitive behavior(std::string name, std::uint32_t index);
[[nodiscard]] Primitive wheels();
// + - * protected / min max abs, < >, and or not, if-then-else over Number, true, false.
[[nodiscard]] std::vector<Primitive> standard_functions();
}  // namespace prim

class PrimitiveSet {
 public:
  // Validates the set for trees rooted at `root`; see the file comment.
  PrimitiveSet(std::vector<Primitive> primitives, Type root);

  [[nodiscard]] Type root() const noexcept { return root_; }
  [[nodiscard]] std::size_t size() const noexcept { return prims_.size(); }
  [[nodiscard]] const Primitive& operator[](PrimitiveId id) const noexcept { return prims_[id]; }
  [[nodiscard]] std::span<const Primitive> primitives() const noexcept { return prims_; }

  // Ids of the primitives returning `t`.
  [[nodiscard]] std::span<const PrimitiveId> of_type(Type t) const noexcept {
    return by_type_[index_of(t)];
  }
  // Depth of the shallowest tree of type t (a terminal has depth 1); kUnbuildable if none.
  [[nodiscard]] int min_depth(Type t) const noexcept { return type_depth_[index_of(t)]; }
  // Depth of the shallowest tree rooted at primitive `id`.
  [[nodiscard]] int min_depth_of(PrimitiveId id) const noexcept { return prim_depth_[id]; }
  // Size (node count) of the smallest tree of type t / rooted at `id`.
  [[nodiscard]] int min_size(Type t) const noexcept { return type_size_[index_of(t)]; }
  [[nodiscard]] int min_size_of(PrimitiveId id) const noexcept { return prim_size_[id]; }
  // Whether primitive a may replace b in place (same result and argument types).
  [[nodiscard]] bool same_signature(PrimitiveId a, PrimitiveId b) const noexcept;

  static constexpr int kUnbuildable = 1 << 20;

 private:
  std::vector<Primitive> prims_;
  Type root_;
  std::array<std::vector<PrimitiveId>, kTypeCount> by_type_;
  std::array<int, kTypeCount> type_depth_{};
  std::array<int, kTypeCount> type_size_{};
  std::vector<int> prim_depth_;
  std::vector<int> prim_size_;
};

}  // namespace esc::genome::tree
