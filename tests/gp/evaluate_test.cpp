// The flat evaluator against the recursive one and against expr::Program, bit for bit.
#include <bit>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "runtime/genome/tree/convert.hpp"
#include "runtime/genome/tree/init.hpp"
#include "runtime/genome/tree/program.hpp"
#include "runtime/genome/tree/recursive.hpp"
#include "runtime/genome/tree/semantics.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::genome::tree {
namespace {

using expr::Op;
using test::postfix;

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

bool same_bits(const Output& a, const Output& b) {
  bool ok = same_bits(a.value, b.value) && same_bits(a.left, b.left) && same_bits(a.right, b.right) &&
            a.index == b.index && a.param_count == b.param_count;
  for (std::size_t k = 0; k < a.params.size(); ++k) ok = ok && same_bits(a.params[k], b.params[k]);
  return ok;
}

TEST(Semantics, MatchExprProgramForEveryOperator) {
  const double special[] = {0.0, -0.0, 1.0, -1.0, 0.5, 2.0, -3.5, 1e300, -1e300, 1e-300, 710.0, -745.0};
  Rng rng(1);
  std::vector<double> xs(std::begin(special), std::end(special));
  for (int k = 0; k < 40; ++k) xs.push_back(rng.uniform(-5.0, 5.0));
  for (int o = static_cast<int>(Op::Neg); o <= static_cast<int>(Op::Clamp); ++o) {
    const auto op = static_cast<Op>(o);
    const int n = expr::arity(op);
    for (double a : xs)
      for (double b : xs) {
        expr::Program p;
        p.push_const(a);
        if (n >= 2) p.push_const(b);
        if (n >= 3) p.push_const(0.25);
        p.push_op(op);
        const double want = p.eval(expr::Frame{});
        const double got = n == 1 ? sem::unary(op, a) : n == 2 ? sem::binary(op, a, b) : sem::clamp(a, b, 0.25);
        ASSERT_TRUE(same_bits(want, got)) << "op " << o << " a " << a << " b " << b;
        if (n == 1) break;
      }
  }
}

TEST(FlatProgram, HandBuiltTrees) {
  const PrimitiveSet set = test::number_set();
  expr::Frame f{};
  f[expr::slot::ir + 0] = 0.7;
  f[expr::slot::ir + 2] = 0.2;
  const Tree t = postfix(set, {"ir[0]", {"erc", 0.5}, ">", {"erc", -0.3}, "ir[2]", {"erc", 0.1}, "max", "if"});
  EXPECT_EQ(compile(t, set).run(f).value, -0.3);
  f[expr::slot::ir + 0] = 0.1;
  EXPECT_EQ(compile(t, set).run(f).value, 0.2);
  // Protected division.
  const Tree d = postfix(set, {"ir[0]", {"erc", 0.0}, "/"});
  EXPECT_EQ(compile(d, set).run(f).value, 0.0);
  EXPECT_EQ(evaluate_recursive(d, set, f).value, 0.0);
  // Only the chosen branch runs: the code jumps over the other.
  EXPECT_NE(compile(t, set).disassemble().find("jz"), std::string::npos);
}

TEST(FlatProgram, TypedRoots) {
  expr::Frame f{};
  f[expr::slot::ir + 1] = 0.9;
  const PrimitiveSet a = test::action_set();
  const Tree act = postfix(a, {"ir[1]", {"erc", 0.5}, ">", "ir[1]", "left", {"erc", 0.25}, "forward", "if"});
  const Output o = compile(act, a).run(f);
  EXPECT_EQ(o.index, 1);
  EXPECT_EQ(o.param_count, 1);
  EXPECT_EQ(o.params[0], 0.9);
  f[expr::slot::ir + 1] = 0.1;
  EXPECT_EQ(compile(act, a).run(f).index, 0);
  EXPECT_EQ(compile(act, a).run(f).params[0], 0.25);

  const PrimitiveSet b = test::behavior_set();
  const Tree sup = postfix(b, {"collision", "avoid", "home", "if"});
  f[expr::slot::collision] = 1.0;
  EXPECT_EQ(compile(sup, b).run(f).index, 0);
  f[expr::slot::collision] = 0.0;
  EXPECT_EQ(compile(sup, b).run(f).index, 2);

  const PrimitiveSet w = test::wheels_set();
  const Tree wh = postfix(w, {"ir[1]", {"erc", 2.0}, "*", {"erc", -0.5}, "wheels"});
  const Output ow = compile(wh, w).run(f);
  EXPECT_EQ(ow.left, 0.2);
  EXPECT_EQ(ow.right, -0.5);
}

TEST(FlatProgram, RejectsIllTypedTrees) {
  const PrimitiveSet set = test::number_set();
  Tree t = postfix(set, {"ir[0]", "ir[1]", "+"});
  t.nodes[2].length = 7;
  EXPECT_THROW((void)compile(t, set), std::invalid_argument);
  EXPECT_THROW((void)compile(Tree{}, set), std::invalid_argument);
}

// Thousands of random trees of every root type, each on several random frames.
TEST(FlatProgram, EqualsRecursiveBitForBit) {
  std::size_t trees = 0;
  for (const PrimitiveSet& set : test::all_sets()) {
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
      Rng rng(seed, {31, index_of(set.root())});
      const Tree t = (seed % 2 == 0) ? grow(set, set.root(), 2 + static_cast<int>(seed % 9), rng)
                                     : full(set, set.root(), 2 + static_cast<int>(seed % 6), rng);
      const FlatProgram p = compile(t, set);
      FlatProgram::Stack stack{};
      for (int k = 0; k < 8; ++k) {
        const expr::Frame f = test::random_frame(rng);
        const Output flat = p.run(f, stack);
        const Output rec = evaluate_recursive(t, set, f);
        ASSERT_TRUE(same_bits(flat, rec)) << "seed " << seed << " root " << name_of(set.root());
      }
      ++trees;
    }
  }
  EXPECT_EQ(trees, 4000U);
}

// A Number tree and its expr::Program (what the compiler makes of the printed text) agree.
TEST(FlatProgram, EqualsExprProgramBitForBit) {
  const PrimitiveSet set = test::number_set();
  for (std::uint64_t seed = 0; seed < 1000; ++seed) {
    Rng rng(seed, {32});
    const Tree t = grow(set, Type::Number, 2 + static_cast<int>(seed % 8), rng);
    const FlatProgram p = compile(t, set);
    const expr::Program e = to_expr_program(t, set, t.root());
    for (int k = 0; k < 8; ++k) {
      const expr::Frame f = test::random_frame(rng);
      ASSERT_TRUE(same_bits(p.run(f).value, e.eval(f))) << "seed " << seed;
    }
  }
}

}  // namespace
}  // namespace esc::genome::tree
