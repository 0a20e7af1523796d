// Trees as doubles (codec.hpp): exact, and bad input refused.
#include <gtest/gtest.h>

#include "runtime/genome/tree/codec.hpp"
#include "runtime/genome/tree/init.hpp"
#include "tests/gp/helpers.hpp"

namespace esc::genome::tree {
namespace {

TEST(Codec, EveryTreeOfEveryRootRoundTrips) {
  Rng rng(17);
  for (const PrimitiveSet& set : test::all_sets()) {
    for (int i = 0; i < 50; ++i) {
      const Tree t = i % 2 == 0 ? full(set, set.root(), 1 + i % 6, rng) : grow(set, set.root(), 8, rng);
      const std::vector<double> genes = encode(t);
      EXPECT_EQ(genes.size(), kCodedNodeWidth * t.size());
      EXPECT_EQ(decode(genes, set), t);
    }
  }
}

TEST(Codec, WhatIsNotATreeOfTheSetIsRefused) {
  const PrimitiveSet set = test::wheels_set();
  Rng rng(3);
  const std::vector<double> genes = encode(full(set, Type::Wheels, 3, rng));
  EXPECT_THROW((void)decode({}, set), std::invalid_argument);
  EXPECT_THROW((void)decode(std::span(genes).first(genes.size() - 1), set), std::invalid_argument);
  EXPECT_THROW((void)decode(std::span(genes).first(genes.size() - 2), set), std::invalid_argument);   // no root
  std::vector<double> bad = genes;
  bad[0] = static_cast<double>(set.size());
  EXPECT_THROW((void)decode(bad, set), std::invalid_argument);
  bad[0] = 0.5;
  EXPECT_THROW((void)decode(bad, set), std::invalid_argument);
  EXPECT_THROW((void)decode(genes, test::number_set()), std::invalid_argument);   // another root
}

}  // namespace
}  // namespace esc::genome::tree
