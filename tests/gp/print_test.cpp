// Printed script code for hand-built trees, exactly.
#include <charconv>
#include <cmath>
#include <regex>

#include <gtest/gtest.h>

#include "runtime/genome/tree/print.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::genome::tree {
namespace {

using test::postfix;

std::string num(std::initializer_list<test::Tok> toks) {
  const PrimitiveSet set = test::number_set();
  return to_script(postfix(set, toks), set);
}

TEST(Print, TheIssueExample) {
  EXPECT_EQ(num({"ir[0]", {"erc", 0.5}, ">", {"erc", -0.3}, "ir[2]", {"erc", 0.1}, "max", "if"}),
            "if ir[0] > 0.5 then -0.3 else max(ir[2], 0.1)");
}

TEST(Print, ParenthesesOnlyWhereNeeded) {
  EXPECT_EQ(num({"ir[0]", "ir[1]", {"erc", 0.5}, "-", "*"}), "ir[0] * (ir[1] - 0.5)");
  EXPECT_EQ(num({"ir[0]", "ir[1]", "*", {"erc", 0.5}, "-"}), "ir[0] * ir[1] - 0.5");
  EXPECT_EQ(num({"ir[0]", "ir[1]", "ir[2]", "-", "-"}), "ir[0] - (ir[1] - ir[2])");
  EXPECT_EQ(num({"ir[0]", "ir[1]", "-", "ir[2]", "-"}), "ir[0] - ir[1] - ir[2]");
  EXPECT_EQ(num({"ir[0]", "ir[1]", "ir[2]", "/", "/"}), "ir[0] / (ir[1] / ir[2])");
  EXPECT_EQ(num({"ir[0]", "ir[1]", "^", "ir[2]", "^"}), "(ir[0] ^ ir[1]) ^ ir[2]");
  EXPECT_EQ(num({"ir[0]", "ir[1]", "ir[2]", "^", "^"}), "ir[0] ^ ir[1] ^ ir[2]");
  EXPECT_EQ(num({"ir[0]", "ir[1]", "neg", "^"}), "ir[0] ^ (-ir[1])");
  EXPECT_EQ(num({"ir[0]", {"erc", 2.0}, "^", "neg"}), "-ir[0] ^ 2");
  EXPECT_EQ(num({"ir[0]", "neg", {"erc", 2.0}, "^"}), "(-ir[0]) ^ 2");
  EXPECT_EQ(num({{"erc", -0.5}, {"erc", 2.0}, "^"}), "(-0.5) ^ 2");
  EXPECT_EQ(num({"ir[0]", {"erc", -0.5}, "-"}), "ir[0] - -0.5");
  EXPECT_EQ(num({"ir[0]", "neg", "neg"}), "-(-ir[0])");
  EXPECT_EQ(num({"ir[0]", "ir[1]", "+", "neg"}), "-(ir[0] + ir[1])");
  EXPECT_EQ(num({"collision", {"erc", 1.0}, {"erc", 2.0}, "if", {"erc", 3.0}, "+"}),
            "(if collision then 1 else 2) + 3");
  EXPECT_EQ(num({"collision", {"erc", 1.0}, "collision", {"erc", 2.0}, {"erc", 3.0}, "if", "if"}),
            "if collision then 1 else if collision then 2 else 3");
  EXPECT_EQ(num({"ir[0]", "ir[1]", "ir[2]", "clamp", "abs", "speed", "min"}),
            "min(abs(clamp(ir[0], ir[1], ir[2])), speed)");
}

TEST(Print, Booleans) {
  const PrimitiveSet set = test::number_set();
  const auto text = [&](std::initializer_list<test::Tok> t) { return to_script(postfix(set, t), set); };
  EXPECT_EQ(text({"ir[0]", {"erc", 0.5}, ">", "not", "collision", "and"}),
            "not ir[0] > 0.5 and collision");
  EXPECT_EQ(text({"collision", "true", "or", "false", "and"}), "(collision or true) and false");
  EXPECT_EQ(text({"collision", "true", "and", "false", "or"}), "collision and true or false");
  EXPECT_EQ(text({"collision", "true", "and", "not"}), "not (collision and true)");
  EXPECT_EQ(text({"ir[0]", "ir[1]", "<=", "ir[2]", "speed", "!=", "or"}),
            "ir[0] <= ir[1] or ir[2] != speed");
}

TEST(Print, WheelsTreesAsBehaviorBodies) {
  const PrimitiveSet set = test::wheels_set();
  const Tree t = postfix(set, {"ir[0]", {"erc", 0.1}, "wheels"});
  EXPECT_EQ(to_script(t, set), "wheels(ir[0], 0.1)");
  EXPECT_EQ(behavior_script(t, set, "evolved"), "behavior evolved() { wheels(ir[0], 0.1) }");
  const Tree b = postfix(set, {"collision", {"erc", -0.5}, {"erc", 0.5}, "wheels", {"erc", 1.0},
                               "speed", "wheels", "if"});
  EXPECT_EQ(to_script(b, set),
            "wheels(if collision then -0.5 else 1, if collision then 0.5 else speed)");
  const PrimitiveSet num = test::number_set();
  EXPECT_THROW((void)behavior_script(postfix(num, {"ir[0]"}), num, "x"), std::invalid_argument);
}

TEST(Print, ActionAndBehaviorTrees) {
  const PrimitiveSet a = test::action_set();
  EXPECT_EQ(to_script(postfix(a, {"ir[1]", {"erc", 0.5}, ">", "ir[1]", "left", {"erc", 0.25},
                                  "forward", "if"}),
                      a),
            "if ir[1] > 0.5 then left(ir[1]) else forward(0.25)");
  EXPECT_EQ(to_script(postfix(a, {"stop"}), a), "stop()");
  const PrimitiveSet b = test::behavior_set();
  EXPECT_EQ(to_script(postfix(b, {"collision", "avoid", "ir[0]", {"erc", 0.2}, "<", "explore", "home",
                                  "if", "if"}),
                      b),
            "if collision then avoid else if ir[0] < 0.2 then explore else home");
}

TEST(Print, NumbersReadBackExactly) {
  EXPECT_EQ(number_text(0.1), "0.1");
  EXPECT_EQ(number_text(3.0), "3");
  EXPECT_EQ(number_text(-0.25), "-0.25");
  EXPECT_EQ(number_text(1e-5), "1e-05");
  const std::regex number("[0-9]+(\\.[0-9]+)?([eE][+-]?[0-9]+)?");
  Rng rng(4);
  for (int k = 0; k < 10000; ++k) {
    const double v = k % 2 == 0 ? rng.uniform(-1.0, 1.0) : rng.normal() * std::pow(10.0, rng.uniform(-12, 12));
    const std::string s = number_text(std::abs(v));  // the script reads the digits, then negates
    ASSERT_TRUE(std::regex_match(s, number)) << s;  // grammar/Esc.g4 NUMBER
    double back = 0.0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), back);
    ASSERT_EQ(r.ec, std::errc());
    ASSERT_EQ(r.ptr, s.data() + s.size());
    ASSERT_EQ(back, std::abs(v)) << s;
  }
}

}  // namespace
}  // namespace esc::genome::tree
