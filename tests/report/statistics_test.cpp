#include "runtime/report/statistics.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace esc::report {
namespace {

TEST(Statistics, MatchesHandComputedValues) {
  const std::vector<double> x = {2, 4, 4, 4, 5, 5, 7, 9};
  const Summary s = summarise(x);
  EXPECT_EQ(s.n, 8U);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_NEAR(s.sd, 2.138089935299395, 1e-12);   // sqrt(32 / 7)
  EXPECT_DOUBLE_EQ(s.median, 4.5);
  EXPECT_DOUBLE_EQ(s.min, 2.0);
  EXPECT_DOUBLE_EQ(s.max, 9.0);
}

TEST(Statistics, SmallSamples) {
  EXPECT_EQ(summarise(std::vector<double>{}).n, 0U);
  const Summary one = summarise(std::vector<double>{3.5});
  EXPECT_DOUBLE_EQ(one.mean, 3.5);
  EXPECT_DOUBLE_EQ(one.sd, 0.0);
  EXPECT_DOUBLE_EQ(one.median, 3.5);
}

}  // namespace
}  // namespace esc::report
