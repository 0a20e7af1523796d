// A study's table and its one family of comparisons: within each condition every pair of
// its controllers, then for each controller every pair of conditions that have it, Holm's
// correction over them all; and the labels the end table and the report print.
#include "runtime/report/study_table.hpp"

#include <algorithm>

#include <gtest/gtest.h>

namespace esc::report {
namespace {

TEST(StudyTable, OneFamilyWithinThenAcrossConditions) {
  const StudyTable t = study_table({{"off", {{"SC", {10, 11, 12}}, {"CC", {5, 6, 7}}}},
                                    {"on", {{"SC", {3, 4, 5}}, {"CC", {5, 6, 8}}, {"GS", {1, 2, 3}}}}});
  EXPECT_EQ(t.controllers, (std::vector<std::string>{"SC", "CC", "GS"}));
  ASSERT_EQ(t.cells.size(), 5u);
  ASSERT_NE(t.cell(1, 2), nullptr);
  EXPECT_EQ(t.cell(0, 2), nullptr);
  // off: 1 pair; on: 3 pairs; SC: 1; CC: 1; GS in one condition only: 0.
  ASSERT_EQ(t.comparisons.size(), 6u);
  std::vector<std::string> labels;
  for (const Comparison& c : t.comparisons) labels.push_back(t.label(c));
  EXPECT_EQ(labels, (std::vector<std::string>{"off: SC vs CC", "on: SC vs CC", "on: SC vs GS", "on: CC vs GS",
                                              "SC: off vs on", "CC: off vs on"}));
  // Holm over the six: the smallest raw p times six (or 1).
  const auto smallest = std::min_element(t.comparisons.begin(), t.comparisons.end(), [](const auto& a, const auto& b) {
    return a.welch.p_value < b.welch.p_value;
  });
  EXPECT_DOUBLE_EQ(smallest->welch_p_holm, std::min(1.0, 6 * smallest->welch.p_value));
  // The same test as the pair alone, before the correction.
  const std::vector<std::vector<double>> alone = {{10, 11, 12}, {3, 4, 5}};
  const auto single = compare(alone, all_pairs(2));
  EXPECT_EQ(t.comparisons[4].welch.p_value, single[0].welch.p_value);
  EXPECT_EQ(t.comparisons[4].mann_whitney.p_value, single[0].mann_whitney.p_value);
  EXPECT_EQ(t.comparisons[4].a12, 1.0);
}

}  // namespace
}  // namespace esc::report
