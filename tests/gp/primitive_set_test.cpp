#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "runtime/genome/tree/primitive_set.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::genome::tree {
namespace {

using expr::Op;

std::string error_of(std::vector<Primitive> p, Type root) {
  try {
    PrimitiveSet set(std::move(p), root);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(PrimitiveSet, SignaturesFollowTheOperator) {
  EXPECT_EQ(prim::function(Op::Add).result, Type::Number);
  EXPECT_EQ(prim::function(Op::Lt).result, Type::Bool);
  EXPECT_EQ(prim::function(Op::Lt).args[0], Type::Number);
  EXPECT_EQ(prim::function(Op::And).args[1], Type::Bool);
  EXPECT_EQ(prim::function(Op::Clamp).arity, 3);
  const Primitive ite = prim::if_then_else(Type::Action);
  EXPECT_EQ(ite.result, Type::Action);
  EXPECT_EQ(ite.args[0], Type::Bool);
  EXPECT_EQ(ite.args[2], Type::Action);
  EXPECT_THROW((void)prim::function(Op::Select), std::invalid_argument);
  EXPECT_THROW((void)prim::function(Op::Load), std::invalid_argument);
}

TEST(PrimitiveSet, ObservablesByScriptName) {
  const auto ir3 = prim::observable("ir[3]");
  ASSERT_TRUE(ir3);
  EXPECT_EQ(ir3->slot, expr::slot::ir + 3);
  EXPECT_EQ(ir3->result, Type::Number);
  EXPECT_EQ(prim::observable("collision")->result, Type::Bool);
  EXPECT_EQ(prim::observable("wheels[1]")->slot, expr::slot::wheels + 1);
  EXPECT_FALSE(prim::observable("ir[8]"));
  EXPECT_FALSE(prim::observable("ir"));
  EXPECT_FALSE(prim::observable("speed[0]"));
  EXPECT_FALSE(prim::observable("ir[x]"));
  EXPECT_FALSE(prim::observable("nope"));
  std::size_t count = 0;
  for (const auto& o : expr::kObservables) count += o.count;
  EXPECT_EQ(prim::all_observables().size(), count);
  EXPECT_EQ(prim::all_observables()[0].name, "speed");
}

TEST(PrimitiveSet, MinimumDepthsAndSizes) {
  const PrimitiveSet w = test::wheels_set();
  EXPECT_EQ(w.min_depth(Type::Number), 1);
  EXPECT_EQ(w.min_depth(Type::Wheels), 2);
  EXPECT_EQ(w.min_size(Type::Wheels), 3);
  const PrimitiveSet a = test::action_set();
  EXPECT_EQ(a.min_depth(Type::Action), 1);  // stop() takes no parameter
  EXPECT_EQ(a.min_size(Type::Action), 1);
  EXPECT_EQ(a.root(), Type::Action);
}

TEST(PrimitiveSet, RejectsATypeWithoutTerminals) {
  // Number can branch on a Bool, but the only Bool primitive needs a Bool.
  const std::string e = error_of({prim::erc(-1, 1), prim::if_then_else(Type::Number),
                                  prim::function(Op::Not), prim::function(Op::Add)},
                                 Type::Number);
  EXPECT_NE(e.find("no finite tree of type Bool"), std::string::npos) << e;
  EXPECT_NE(e.find("add a Bool terminal"), std::string::npos) << e;

  const std::string n = error_of({prim::function(Op::Add), prim::wheels()}, Type::Wheels);
  EXPECT_NE(n.find("type Number"), std::string::npos) << n;
}

TEST(PrimitiveSet, RejectsAMissingType) {
  const std::string e = error_of({prim::erc(-1, 1), prim::function(Op::Add)}, Type::Wheels);
  EXPECT_NE(e.find("no primitive returns Wheels, needed by the root"), std::string::npos) << e;
  const std::string b = error_of({prim::erc(-1, 1), prim::if_then_else(Type::Number)}, Type::Number);
  EXPECT_NE(b.find("no primitive returns Bool, needed by `if`"), std::string::npos) << b;
  EXPECT_NE(error_of({}, Type::Number).find("empty"), std::string::npos);
}

TEST(PrimitiveSet, IgnoresUnreachableTypes) {
  // `not` can never be used (no Number primitive takes a Bool), which is no error.
  EXPECT_EQ(error_of({prim::erc(-1, 1), prim::function(Op::Add), prim::function(Op::Not)},
                     Type::Number),
            "");
}

TEST(PrimitiveSet, RejectsBadPrimitives) {
  EXPECT_NE(error_of({prim::erc(1, -1)}, Type::Number).find("range"), std::string::npos);
  EXPECT_NE(error_of({prim::observable("far", 999)}, Type::Number).find("outside the frame"),
            std::string::npos);
  Primitive many = prim::action("big", 0, 4);
  many.arity = 5;
  EXPECT_NE(error_of({prim::erc(0, 1), many}, Type::Action).find("at most"), std::string::npos);
  Primitive bad_if = prim::if_then_else(Type::Number);
  bad_if.args[1] = Type::Bool;
  EXPECT_NE(error_of({prim::erc(0, 1), prim::constant(Type::Bool, 1), bad_if}, Type::Number)
                .find("(Bool, T, T -> T)"),
            std::string::npos);
}

TEST(PrimitiveSet, SameSignature) {
  const PrimitiveSet s = test::number_set();
  PrimitiveId add = 0, sub = 1, neg = 7, lt = 15;
  ASSERT_EQ(s[add].name, "+");
  ASSERT_EQ(s[neg].op, Op::Neg);
  ASSERT_EQ(s[lt].op, Op::Lt);
  EXPECT_TRUE(s.same_signature(add, sub));
  EXPECT_FALSE(s.same_signature(add, neg));
  EXPECT_FALSE(s.same_signature(add, lt));
}

}  // namespace
}  // namespace esc::genome::tree
