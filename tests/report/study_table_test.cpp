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

// Success is compared over the family's pairs whose cells both declare a test: a condition
// without one drops out of those comparisons, and nothing else changes.
TEST(StudyTable, SuccessOverThePairsThatDeclareIt) {
  const SuccessSample solved{{10.0, 20.0, std::nullopt}, 60.0}, unsolved{{std::nullopt, std::nullopt, 50.0}, 60.0};
  ConditionSamples off{"off", {{"SC", {10, 11, 12}}, {"CC", {5, 6, 7}}}, {solved, unsolved}};
  ConditionSamples on{"on", {{"SC", {3, 4, 5}}, {"CC", {5, 6, 8}}}, {unsolved, solved}};
  ConditionSamples none{"none", {{"SC", {1, 2, 3}}, {"CC", {2, 3, 4}}}};
  const StudyTable t = study_table({off, on, none});
  const StudyTable plain = study_table({ConditionSamples{"off", off.controllers}, ConditionSamples{"on", on.controllers},
                                        none});
  ASSERT_EQ(t.comparisons.size(), plain.comparisons.size());
  for (std::size_t k = 0; k < t.comparisons.size(); ++k)
    EXPECT_EQ(t.comparisons[k].welch_p_holm, plain.comparisons[k].welch_p_holm);
  EXPECT_TRUE(plain.success_comparisons.empty());
  EXPECT_FALSE(t.cell(2, 0)->success.has_value());
  std::vector<std::string> labels;
  for (const SuccessComparison& c : t.success_comparisons) labels.push_back(t.label(c.a, c.b));
  EXPECT_EQ(labels, (std::vector<std::string>{"off: SC vs CC", "on: SC vs CC", "SC: off vs on", "CC: off vs on"}));
  EXPECT_EQ(t.success_comparisons[0].successes_a, 2u);
  EXPECT_EQ(t.success_comparisons[0].successes_b, 1u);
  EXPECT_EQ(t.success_comparisons[0].censored_at, 61.0);
}

}  // namespace
}  // namespace esc::report
