#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/core/rng.hpp"
#include "runtime/evo/pareto/fronts.hpp"
#include "runtime/evo/pareto/hypervolume.hpp"
#include "runtime/evo/pareto/selection.hpp"

namespace esc::evo {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::nan("");

using Fronts = std::vector<std::vector<std::size_t>>;

// Two objectives, minimised: 3 is dominated by 1, 6 by 2, 4 by 0, 1, 3 and 6; 5 is a copy
// of 1 (neither dominates the other).
const ObjectiveRows kPlane{{1, 5}, {2, 3}, {4, 1}, {3, 4}, {5, 5}, {2, 3}, {4, 2}};

TEST(Pareto, DominatesNeedsNoWorseEverywhereAndBetterSomewhere) {
  EXPECT_TRUE(dominates(std::vector<double>{1, 2}, std::vector<double>{1, 3}));
  EXPECT_FALSE(dominates(std::vector<double>{1, 3}, std::vector<double>{1, 2}));
  EXPECT_FALSE(dominates(std::vector<double>{1, 2}, std::vector<double>{1, 2}));
  EXPECT_FALSE(dominates(std::vector<double>{0, 3}, std::vector<double>{1, 2}));
  EXPECT_FALSE(dominates(std::vector<double>{0, kNaN}, std::vector<double>{1, 2}));
  EXPECT_FALSE(dominates(std::vector<double>{1, 2}, std::vector<double>{kNaN, 3}));
  EXPECT_TRUE(dominates(std::vector<double>{1, 2}, std::vector<double>{kInf, 2}));
}

TEST(Pareto, FrontsOfAHandExampleInOrderIndicesAscending) {
  EXPECT_EQ(nondominated_fronts(kPlane), (Fronts{{0, 1, 2, 5}, {3, 6}, {4}}));
  // Three objectives: 3 is dominated by 0 and 2, the rest by nobody.
  EXPECT_EQ(nondominated_fronts(ObjectiveRows{{1, 2, 3}, {2, 1, 3}, {1, 1, 4}, {2, 2, 4}}), (Fronts{{0, 1, 2}, {3}}));
  // A chain: one front per point, the best last in the input.
  EXPECT_EQ(nondominated_fronts(ObjectiveRows{{3}, {2}, {1}}), (Fronts{{2}, {1}, {0}}));
  EXPECT_TRUE(nondominated_fronts(ObjectiveRows{}).empty());
}

TEST(Pareto, NanPointsFormTheLastFront) {
  // Point 1 would dominate everything on its first objective; with a NaN it goes last.
  const ObjectiveRows f{{1, 5}, {0, kNaN}, {2, 3}, {3, 4}, {kNaN, kNaN}};
  EXPECT_EQ(nondominated_fronts(f), (Fronts{{0, 2}, {3}, {1, 4}}));
  EXPECT_EQ(nondominated_fronts(ObjectiveRows{{kNaN}}), (Fronts{{0}}));
}

// Deb's sort as he wrote it (2002, section III-A), with the lists of dominated points that
// nondominated_fronts no longer keeps: the reference its fronts must equal, order and all.
Fronts deb_fronts(const ObjectiveRows& f) {
  std::vector<std::size_t> measured, unmeasured;
  for (std::size_t i = 0; i < f.size(); ++i)
    (std::any_of(f[i].begin(), f[i].end(), [](double x) { return std::isnan(x); }) ? unmeasured : measured).push_back(i);
  std::vector<std::vector<std::size_t>> dominated(f.size());
  std::vector<std::size_t> dominators(f.size(), 0);
  for (const std::size_t p : measured)
    for (const std::size_t q : measured)
      if (dominates(f[p], f[q])) {
        dominated[p].push_back(q);
        ++dominators[q];
      }
  Fronts fronts;
  std::vector<std::size_t> current;
  for (const std::size_t p : measured)
    if (dominators[p] == 0) current.push_back(p);
  while (!current.empty()) {
    std::vector<std::size_t> next;
    for (const std::size_t p : current)
      for (const std::size_t q : dominated[p])
        if (--dominators[q] == 0) next.push_back(q);
    std::sort(next.begin(), next.end());
    fronts.push_back(std::move(current));
    current = std::move(next);
  }
  if (!unmeasured.empty()) fronts.push_back(std::move(unmeasured));
  return fronts;
}

TEST(Pareto, FrontsEqualDebsSortOnRandomPointsWithTiesInfinitiesAndNans) {
  // Values from a few levels, so that ties and copies are common; some infinite, some NaN.
  const std::vector<double> levels{-kInf, -1.0, -0.0, 0.0, 0.5, 1.0, 2.0, 3.0, kInf};
  for (const std::size_t m : {1U, 2U, 3U, 4U})
    for (std::uint64_t seed = 0; seed < 60; ++seed) {
      Rng rng(seed, {m});
      ObjectiveRows f(1 + rng.below(300));
      const bool with_nan = seed % 3 == 0;
      const std::size_t spread = 2 + rng.below(levels.size() - 1);   // fewer levels: more ties
      for (auto& row : f)
        for (std::size_t k = 0; k < m; ++k)
          row.push_back(with_nan && rng.below(40) == 0 ? kNaN
                        : seed % 2 == 0            ? levels[rng.below(spread)]
                                                   : rng.uniform(-1.0, 1.0));
      EXPECT_EQ(nondominated_fronts(f), deb_fronts(f)) << m << " objectives, seed " << seed;
    }
}

TEST(Pareto, TwoObjectiveFrontsOfAMillionPointsInLinearMemory) {
  // 200 fronts of 5,000 points each, shuffled: Deb's lists would hold about 5e11 indices.
  constexpr std::size_t kFronts = 200, kEach = 5'000;
  ObjectiveRows f;
  for (std::size_t k = 0; k < kFronts; ++k)
    for (std::size_t i = 0; i < kEach; ++i) f.push_back({static_cast<double>(i + k), static_cast<double>(kEach - i + k)});
  Rng rng(7);
  for (std::size_t i = f.size() - 1; i > 0; --i) std::swap(f[i], f[rng.below(i + 1)]);
  const Fronts fronts = nondominated_fronts(f);
  ASSERT_EQ(fronts.size(), kFronts);
  for (std::size_t k = 0; k < kFronts; ++k) {
    ASSERT_EQ(fronts[k].size(), kEach) << k;
    EXPECT_TRUE(std::is_sorted(fronts[k].begin(), fronts[k].end())) << k;
    for (const std::size_t p : fronts[k]) EXPECT_EQ(f[p][0] + f[p][1], static_cast<double>(kEach + 2 * k)) << k;
  }
}

TEST(Pareto, FrontsRefuseRowsOfDifferentLengths) {
  EXPECT_THROW((void)nondominated_fronts(ObjectiveRows{{1, 2}, {1}}), std::invalid_argument);
  EXPECT_THROW((void)nondominated_fronts(ObjectiveRows{{}, {}}), std::invalid_argument);
}

TEST(Pareto, CrowdingDistanceOfAHandExample) {
  // A (0, 8), B (1, 6), C (4, 3), D (6, 1), E (10, 0), among points of other fronts.
  // f1 (range 10): B (4 - 0) / 10, C (6 - 1) / 10, D (10 - 4) / 10;
  // f2 (range 8):  B (8 - 3) / 8,  C (6 - 1) / 8,  D (3 - 0) / 8.
  const ObjectiveRows f{{9, 9}, {0, 8}, {1, 6}, {4, 3}, {6, 1}, {10, 0}, {20, 20}};
  const std::vector<std::size_t> front{5, 3, 1, 4, 2};  // E, C, A, D, B
  const std::vector<double> d = crowding_distance(f, front);
  ASSERT_EQ(d.size(), 5u);
  EXPECT_EQ(d[0], kInf);
  EXPECT_DOUBLE_EQ(d[1], 0.5 + 0.625);
  EXPECT_EQ(d[2], kInf);
  EXPECT_DOUBLE_EQ(d[3], 0.6 + 0.375);
  EXPECT_DOUBLE_EQ(d[4], 0.4 + 0.625);
}

TEST(Pareto, CrowdingDistanceOfEachPointDoesNotDependOnTheFrontsOrder) {
  // Equal values in both objectives (points 1 and 2): ties are broken by index, not by
  // where the points sit in `front`; the first of the two gets other gaps than the second.
  const ObjectiveRows f{{0, 1}, {0.5, 0.5}, {0.5, 0.5}, {0.25, 0.9}, {1, 0}};
  const std::vector<std::size_t> ascending{0, 1, 2, 3, 4};
  const std::vector<std::size_t> shuffled{2, 4, 1, 0, 3};
  const std::vector<double> a = crowding_distance(f, ascending);
  const std::vector<double> b = crowding_distance(f, shuffled);
  for (std::size_t pos = 0; pos < shuffled.size(); ++pos) EXPECT_EQ(b[pos], a[shuffled[pos]]) << "point " << shuffled[pos];
  // f1 sorted 0, 3, 1, 2, 4 and f2 sorted 4, 1, 2, 3, 0: point 1 gets (0.5 - 0.25) + (0.5 - 0),
  // point 2 (1 - 0.5) + (0.9 - 0.5), point 3 (0.5 - 0) + (1 - 0.5).
  EXPECT_DOUBLE_EQ(a[1], 0.75);
  EXPECT_DOUBLE_EQ(a[2], 0.9);
  EXPECT_DOUBLE_EQ(a[3], 1.0);
}

TEST(Pareto, CrowdingDistanceOfAZeroOrInfiniteRangeAddsNothingInside) {
  // Three objectives, the first equal everywhere: its extremes (by index, 0 and 3) are
  // infinite, the others get 2/3 from each of the two other objectives, and no 0 / 0.
  const ObjectiveRows flat{{0, 1, 4}, {0, 2, 3}, {0, 3, 2}, {0, 4, 1}};
  const std::vector<double> d = crowding_distance(flat, std::vector<std::size_t>{0, 1, 2, 3});
  EXPECT_EQ(d[0], kInf);
  EXPECT_DOUBLE_EQ(d[1], 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(d[2], 4.0 / 3.0);
  EXPECT_EQ(d[3], kInf);
  // An infinite f2 makes f2's range infinite: only f1 (range 3) measures the inner points.
  const ObjectiveRows wide{{0, kInf}, {1, 5}, {2, 3}, {3, 1}};
  const std::vector<double> w = crowding_distance(wide, std::vector<std::size_t>{0, 1, 2, 3});
  EXPECT_EQ(w[0], kInf);
  EXPECT_DOUBLE_EQ(w[1], 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(w[2], 2.0 / 3.0);
  EXPECT_EQ(w[3], kInf);
}

TEST(Pareto, CrowdingDistanceOfSmallFrontsAndNanPoints) {
  const ObjectiveRows f{{0, 1}, {1, 0}, {kNaN, 0}, {0.5, 0.5}};
  EXPECT_EQ(crowding_distance(f, std::vector<std::size_t>{3}), (std::vector<double>{kInf}));
  EXPECT_EQ(crowding_distance(f, std::vector<std::size_t>{0, 1}), (std::vector<double>{kInf, kInf}));
  // The NaN point gets 0; the other two are measured alone, so both are extremes.
  EXPECT_EQ(crowding_distance(f, std::vector<std::size_t>{0, 2, 1}), (std::vector<double>{kInf, 0.0, kInf}));
  EXPECT_TRUE(crowding_distance(f, std::vector<std::size_t>{}).empty());
  EXPECT_THROW((void)crowding_distance(f, std::vector<std::size_t>{0, 4}), std::invalid_argument);
}

TEST(Pareto, CrowdedComparisonIsRankThenCrowdingThenIndex) {
  const Ranking r{{0, 1, 0, 0}, {1.0, kInf, 2.0, 1.0}};
  EXPECT_TRUE(crowded_before(r, 0, 1));   // a better front beats any crowding
  EXPECT_FALSE(crowded_before(r, 1, 0));
  EXPECT_TRUE(crowded_before(r, 2, 0));   // same front: the larger distance
  EXPECT_TRUE(crowded_before(r, 0, 3));   // equal in both: the lower index
  EXPECT_FALSE(crowded_before(r, 3, 0));
  EXPECT_FALSE(crowded_before(r, 0, 0));
  EXPECT_EQ(crowded_tournament(r, 1, 0), 0u);
  EXPECT_EQ(crowded_tournament(r, 0, 2), 2u);
  EXPECT_EQ(crowded_tournament(r, 3, 0), 0u);
  EXPECT_EQ(crowded_tournament(r, 0, 3), 0u);
}

TEST(Pareto, RankAndCrowdOfTheHandExample) {
  const Ranking r = rank_and_crowd(kPlane);
  EXPECT_EQ(r.rank, (std::vector<std::size_t>{0, 0, 0, 1, 2, 0, 1}));
  // Front 0 is 0 (1, 5), 1 and 5 (2, 3), 2 (4, 1): f1 sorted 0, 1, 5, 2 (range 3), f2
  // sorted 2, 1, 5, 0 (range 4). Point 1: (2 - 1) / 3 + (3 - 1) / 4; point 5: (4 - 2) / 3 +
  // (5 - 3) / 4.
  EXPECT_EQ(r.crowding[0], kInf);
  EXPECT_DOUBLE_EQ(r.crowding[1], 1.0 / 3.0 + 0.5);
  EXPECT_DOUBLE_EQ(r.crowding[5], 2.0 / 3.0 + 0.5);
  EXPECT_EQ(r.crowding[2], kInf);
  EXPECT_EQ(r.crowding[3], kInf);  // fronts of one or two points
  EXPECT_EQ(r.crowding[4], kInf);
  EXPECT_EQ(r.crowding[6], kInf);
}

TEST(Pareto, SurvivorsAreWholeFrontsThenTheLeastCrowded) {
  // Point 0 dominates the five others, which form the crowding example's front
  // (A..E = 1..5; distances inf, 1.025, 1.125, 0.975, inf).
  const ObjectiveRows f{{-1, -1}, {0, 8}, {1, 6}, {4, 3}, {6, 1}, {10, 0}};
  EXPECT_EQ(select_survivors(f, 4), (std::vector<std::size_t>{0, 1, 3, 5}));
  EXPECT_EQ(select_survivors(f, 5), (std::vector<std::size_t>{0, 1, 2, 3, 5}));
  EXPECT_EQ(select_survivors(f, 1), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(select_survivors(f, 0).empty());
  EXPECT_EQ(select_survivors(f, 6).size(), 6u);
  // The hand example: front 0 (4 points), then one of {3, 6}, both infinite: the lower index.
  EXPECT_EQ(select_survivors(kPlane, 5), (std::vector<std::size_t>{0, 1, 2, 3, 5}));
  EXPECT_THROW((void)select_survivors(f, 7), std::invalid_argument);
  EXPECT_THROW((void)select_survivors(Ranking{{0, 0}, {1.0}}, 1), std::invalid_argument);
}

TEST(Pareto, HypervolumeTwoObjectivesByHand) {
  const std::vector<double> ref{4, 4};
  // A staircase: 3 x 1 + 2 x 1 + 1 x 1.
  ObjectiveRows f{{1, 3}, {2, 2}, {3, 1}};
  EXPECT_DOUBLE_EQ(hypervolume(f, ref), 6.0);
  // A dominated point, a copy, a point beyond the reference, one on its boundary and a NaN
  // add nothing.
  f.insert(f.end(), {{2.5, 2.5}, {2, 2}, {5, 0}, {4, 0}, {0, 4}, {kNaN, 0}});
  EXPECT_DOUBLE_EQ(hypervolume(f, ref), 6.0);
  EXPECT_DOUBLE_EQ(hypervolume(ObjectiveRows{{0, 0}}, ref), 16.0);
  EXPECT_EQ(hypervolume(ObjectiveRows{}, ref), 0.0);
  EXPECT_EQ(hypervolume(ObjectiveRows{{4, 5}}, ref), 0.0);
}

// Points far below a reference far above: the volume saturates at the largest double.
TEST(Pareto, HypervolumeStaysFinite) {
  constexpr double largest = std::numeric_limits<double>::max();
  EXPECT_EQ(hypervolume(ObjectiveRows{{-1e300, -1e300}}, std::vector<double>{1e308, 1e308}), largest);
  EXPECT_EQ(hypervolume(ObjectiveRows{{-1e300, -1e300, -1e300}, {0, 0, 0}}, std::vector<double>{1e200, 1e200, 1e200}),
            largest);
  EXPECT_DOUBLE_EQ(hypervolume(ObjectiveRows{{-1e150, 0}}, std::vector<double>{0, 1e150}), 1e300);
}

TEST(Pareto, HypervolumeThreeObjectivesByHand) {
  const std::vector<double> ref{2, 2, 2};
  EXPECT_DOUBLE_EQ(hypervolume(ObjectiveRows{{1, 1, 1}}, ref), 1.0);
  // Two boxes, 4 and 2, overlapping in [1, 2]^3.
  EXPECT_DOUBLE_EQ(hypervolume(ObjectiveRows{{0, 0, 1}, {1, 1, 0}}, ref), 5.0);
  // Three boxes of 4, pairwise overlaps of 2, all three of 1: 12 - 6 + 1. A dominated point
  // and one beyond the reference add nothing.
  EXPECT_DOUBLE_EQ(hypervolume(ObjectiveRows{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {3, 0, 0}}, ref), 7.0);
  // Equal third objectives: one slice of depth 1, area 2 + 2 - 1.
  EXPECT_DOUBLE_EQ(hypervolume(ObjectiveRows{{0, 1, 1}, {1, 0, 1}}, ref), 3.0);
}

// The union's volume by inclusion-exclusion over every subset of the points inside the
// reference: an independent method, exponential, for a few points only.
double inclusion_exclusion(const ObjectiveRows& points, const std::vector<double>& ref) {
  ObjectiveRows inside;
  for (const auto& p : points) {
    bool below = true;
    for (std::size_t k = 0; k < ref.size(); ++k) below = below && p[k] < ref[k];
    if (below) inside.push_back(p);
  }
  double total = 0.0;
  for (std::uint32_t subset = 1; subset < (1U << inside.size()); ++subset) {
    std::vector<double> corner(ref.size(), -kInf);
    int size = 0;
    for (std::size_t i = 0; i < inside.size(); ++i) {
      if ((subset & (1U << i)) == 0) continue;
      ++size;
      for (std::size_t k = 0; k < ref.size(); ++k) corner[k] = std::max(corner[k], inside[i][k]);
    }
    double box = 1.0;
    for (std::size_t k = 0; k < ref.size(); ++k) box *= ref[k] - corner[k];
    total += size % 2 == 1 ? box : -box;
  }
  return total;
}

TEST(Pareto, HypervolumeAgreesWithInclusionExclusionOnRandomSets) {
  for (const std::size_t m : {2u, 3u}) {
    const std::vector<double> ref(m, 1.0);
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
      Rng rng(seed);
      ObjectiveRows points(1 + rng.below(10), std::vector<double>(m));
      for (auto& p : points)
        for (double& v : p) v = seed % 2 == 0 ? std::round(rng.uniform(0.0, 1.2) * 5.0) / 5.0 : rng.uniform(0.0, 1.2);
      EXPECT_NEAR(hypervolume(points, ref), inclusion_exclusion(points, ref), 1e-12) << m << " objectives, seed " << seed;
    }
  }
}

TEST(Pareto, HypervolumeRefusesOtherDimensionsAndBadPoints) {
  EXPECT_THROW((void)hypervolume(ObjectiveRows{{0}}, std::vector<double>{1}), std::invalid_argument);
  EXPECT_THROW((void)hypervolume(ObjectiveRows{{0, 0, 0, 0}}, std::vector<double>{1, 1, 1, 1}), std::invalid_argument);
  EXPECT_THROW((void)hypervolume(ObjectiveRows{{0, 0, 0}}, std::vector<double>{1, 1}), std::invalid_argument);
  EXPECT_THROW((void)hypervolume(ObjectiveRows{{0, 0}}, std::vector<double>{1, kNaN}), std::invalid_argument);
  EXPECT_THROW((void)hypervolume(ObjectiveRows{{0, 0}}, std::vector<double>{kInf, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace esc::evo
