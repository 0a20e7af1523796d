// MAP-Elites and CVT-MAP-Elites: the descriptor space, grid and CVT cells, the archive
// (insert, QD-score, changes and replay, state), uniform selection, Iso+LineDD and the
// MapElites value type.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/evo/map_elites/archive.hpp"
#include "runtime/evo/map_elites/iso_line_dd.hpp"
#include "runtime/evo/map_elites/map_elites.hpp"
#include "runtime/evo/map_elites/point_tree.hpp"
#include "runtime/evo/map_elites/selection.hpp"

namespace esc::evo::qd {
namespace {

Rng generation_rng(std::uint64_t seed, std::uint64_t g) {
  return Rng(seed, {static_cast<std::uint64_t>(Stream::Breed), g});
}

DescriptorSpace unit_square() { return DescriptorSpace({{0.0, 1.0}, {0.0, 1.0}}); }

// A 4 x 2 grid over [0, 8] x [-1, 1]: bins of width 2 and 1.
Archive small_grid(double offset = 0.0) { return Archive(DescriptorSpace({{0.0, 8.0}, {-1.0, 1.0}}), Grid({4, 2}), offset); }

Cvt small_cvt(std::uint64_t seed, std::size_t k = 32) {
  Rng rng(seed, {static_cast<std::uint64_t>(Stream::Init)});
  return Cvt::compute(2, k, rng, {.samples = 10'000, .iterations = 300});
}

template <class F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

// ---- descriptor space and grid ----

TEST(DescriptorSpace, MapsOntoTheUnitCubeAndClampsOutside) {
  const DescriptorSpace space({{-2.0, 2.0}, {10.0, 20.0}});
  EXPECT_EQ(space.to_unit(std::vector<double>{-2.0, 20.0}), (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(space.to_unit(std::vector<double>{1.0, 12.5}), (std::vector<double>{0.75, 0.25}));
  EXPECT_EQ(space.to_unit(std::vector<double>{-7.0, 99.0}), (std::vector<double>{0.0, 1.0}));
  EXPECT_THROW((void)space.to_unit(std::vector<double>{0.0}), std::invalid_argument);
  EXPECT_THROW((void)space.to_unit(std::vector<double>{0.0, std::nan("")}), std::invalid_argument);
  EXPECT_NE(message_of([] { DescriptorSpace({{1.0, 1.0}}); }).find("descriptor 0"), std::string::npos);
  EXPECT_THROW(DescriptorSpace({}), std::invalid_argument);
  EXPECT_THROW(DescriptorSpace({{-1e308, 1e308}}), std::invalid_argument);  // the width overflows
}

TEST(Grid, CellsAreRowMajorWithBoundsInTheEdgeBins) {
  const Archive a = small_grid();
  ASSERT_EQ(a.cells(), 8u);
  const auto cell = [&](double x, double y) { return a.cell_of(std::vector<double>{x, y}); };
  EXPECT_EQ(cell(0.0, -1.0), 0u);   // both lower bounds
  EXPECT_EQ(cell(8.0, 1.0), 7u);    // both upper bounds: the last bins
  EXPECT_EQ(cell(2.0, 0.0), 3u);    // on inner edges: the upper bin, (1, 1) -> 1 * 2 + 1
  EXPECT_EQ(cell(1.999, -0.001), 0u);
  EXPECT_EQ(cell(5.0, -0.5), 4u);   // (2, 0)
  EXPECT_EQ(cell(-5.0, 7.0), 1u);   // outside: clamped to (0, 1)
  EXPECT_EQ(cell(100.0, -3.0), 6u); // (3, 0)
  EXPECT_EQ(Archive(DescriptorSpace({{0.0, 1.0}}), Grid({10}), 0.0).cell_of(std::vector<double>{0.3}), 3u);
}

TEST(Grid, RefusesImpossibleBinsNamingTheSetting) {
  EXPECT_NE(message_of([] { Grid({}); }).find("bins"), std::string::npos);
  EXPECT_NE(message_of([] { Grid({2, 0}); }).find("bins"), std::string::npos);
  EXPECT_NE(message_of([] { Grid({2, 2, 2, 2}); }).find("bins"), std::string::npos);
  EXPECT_NE(message_of([] { Grid({100'000, 100'000}); }).find("10^8"), std::string::npos);
  EXPECT_NE(message_of([] { Archive(unit_square(), Grid({4}), 0.0); }).find("bins"), std::string::npos);
  EXPECT_NE(message_of([] { Archive(unit_square(), Grid({4, 4}), std::nan("")); }).find("fitness_offset"), std::string::npos);
}

// ---- kd-tree ----

TEST(PointTree, KNearestSquaredDistancesEqualABruteForceSearch) {
  Rng rng(17);
  for (const std::size_t dims : {1u, 3u, 8u}) {
    std::vector<double> values(900 * dims);
    for (double& v : values) v = rng.uniform();
    std::copy_n(values.begin(), 10 * dims, values.begin() + 10 * dims);  // ten twins
    const PointTree tree(values, dims);
    std::vector<std::uint32_t> indices;
    std::vector<double> squared;
    for (int q = 0; q < 200; ++q) {
      std::vector<double> query(dims);
      for (double& v : query) v = q < 20 ? values[static_cast<std::size_t>(q) * dims] : rng.uniform(-0.2, 1.2);
      std::vector<double> all;
      for (std::size_t i = 0; i < tree.size(); ++i) all.push_back(squared_distance(query, tree.point(i)));
      std::sort(all.begin(), all.end());
      for (const std::size_t k : {1u, 16u, 1000u}) {
        tree.nearest(query, k, indices, squared);
        ASSERT_EQ(squared, std::vector<double>(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(std::min(k, all.size()))))
            << "dims " << dims << " query " << q << " k " << k;
        for (std::size_t j = 0; j < indices.size(); ++j) EXPECT_EQ(squared_distance(query, tree.point(indices[j])), squared[j]);
      }
    }
  }
}

// ---- CVT ----

TEST(Cvt, CentroidsAreDeterministicDistinctInsideAndEvenlySpread) {
  const Cvt a = small_cvt(1), b = small_cvt(1), other = small_cvt(2);
  EXPECT_EQ(a.centroids(), b.centroids());
  EXPECT_NE(a.centroids(), other.centroids());
  ASSERT_EQ(a.cells(), 32u);
  std::set<std::vector<double>> distinct;
  for (std::size_t c = 0; c < a.cells(); ++c) {
    const auto p = a.centroid(c);
    for (const double v : p) {
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, 1.0);
    }
    distinct.emplace(p.begin(), p.end());
  }
  EXPECT_EQ(distinct.size(), 32u);
  // A centroidal tessellation cuts the square into cells of similar area: fresh uniform
  // points fall about evenly into them. The counts' coefficient of variation is 0.11 here;
  // after one Lloyd iteration it is 0.35, and for 32 random centroids 0.58.
  Rng rng(99);
  std::vector<double> count(a.cells());
  const int draws = 64'000;
  for (int i = 0; i < draws; ++i) ++count[a.cell_of(std::vector<double>{rng.uniform(), rng.uniform()})];
  const double mean = draws / 32.0;
  double variance = 0.0;
  for (const double c : count) {
    EXPECT_GT(c, 0.6 * mean);
    EXPECT_LT(c, 1.4 * mean);
    variance += (c - mean) * (c - mean) / 32.0;
  }
  EXPECT_LT(std::sqrt(variance) / mean, 0.15);
}

TEST(Cvt, RefusesImpossibleSettingsNamingThem) {
  Rng rng(1);
  EXPECT_NE(message_of([&] { (void)Cvt::compute(2, 0, rng); }).find("cells"), std::string::npos);
  EXPECT_NE(message_of([&] { (void)Cvt::compute(2, 11, rng, {.samples = 10, .iterations = 5}); }).find("cells"), std::string::npos);
  EXPECT_NE(message_of([&] { (void)Cvt::compute(0, 4, rng); }).find("descriptors"), std::string::npos);
  EXPECT_NE(message_of([&] { (void)Cvt::compute(2, 4, rng, {.samples = 100, .iterations = 0}); }).find("iterations"), std::string::npos);
  EXPECT_THROW(Cvt(std::vector<double>{0.5, 1.5}, 2), std::invalid_argument);
  EXPECT_THROW(Cvt(std::vector<double>{0.5, 0.5, 0.5}, 2), std::invalid_argument);
}

// The brute-force nearest centroid, the lowest index among equally near ones.
std::size_t brute_nearest(const Cvt& cvt, std::span<const double> q) {
  std::size_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < cvt.cells(); ++c) {
    const double d = squared_distance(q, cvt.centroid(c));
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  return best;
}

TEST(Cvt, NearestCentroidIsTheBruteForceOne) {
  Rng init(3, {static_cast<std::uint64_t>(Stream::Init)});
  const Cvt cvt = Cvt::compute(3, 200, init, {.samples = 20'000, .iterations = 20});
  const Archive archive(DescriptorSpace({{0, 1}, {0, 1}, {0, 1}}), cvt, 0.0);
  Rng rng(4);
  for (int i = 0; i < 5000; ++i) {
    // A fifth of the queries lie outside the box: they count as the nearest bound.
    const std::vector<double> d{rng.uniform(-0.1, 1.1), rng.uniform(-0.1, 1.1), rng.uniform(-0.1, 1.1)};
    const std::vector<double> unit = archive.space().to_unit(d);
    ASSERT_EQ(archive.cell_of(d), brute_nearest(cvt, unit)) << "query " << i;
  }
}

TEST(Cvt, EquallyNearCentroidsGoToTheLowestIndex) {
  // (0.5, 0.5) is 0.25 from the first two centroids exactly; (0.5, 0.875) is 0.25 from
  // the last two (every number here is a binary fraction, so the distances tie exactly).
  const Cvt cvt({0.25, 0.5, 0.75, 0.5, 0.5, 0.125, 0.25, 0.875, 0.75, 0.875}, 2);
  EXPECT_EQ(cvt.cell_of(std::vector<double>{0.5, 0.5}), 0u);
  EXPECT_EQ(cvt.cell_of(std::vector<double>{0.5, 0.875}), 3u);
  const Cvt reversed({0.75, 0.875, 0.25, 0.875, 0.5, 0.125, 0.75, 0.5, 0.25, 0.5}, 2);
  EXPECT_EQ(reversed.cell_of(std::vector<double>{0.5, 0.5}), 3u);
  EXPECT_EQ(reversed.cell_of(std::vector<double>{0.5, 0.875}), 0u);
}

// ---- archive ----

TEST(Archive, InsertsImprovesRejectsAndKeepsTheIncumbentOnATie) {
  Archive a = small_grid();
  const std::vector<double> d{1.0, 0.5};  // cell 1
  EXPECT_EQ(a.insert({1.0}, 2.0, d), (InsertResult{Insertion::NewCell, 1}));
  EXPECT_EQ(a.insert({2.0}, 1.0, d), (InsertResult{Insertion::Rejected, 1}));
  EXPECT_EQ(a.insert({3.0}, 2.0, d), (InsertResult{Insertion::Rejected, 1}));  // a tie
  EXPECT_EQ(a.insert({4.0, 4.5}, 2.5, std::vector<double>{1.5, 0.9}), (InsertResult{Insertion::Improved, 1}));
  EXPECT_EQ(a.insert({5.0}, std::nan(""), std::vector<double>{7.0, 0.0}), (InsertResult{Insertion::Rejected, 7}));
  EXPECT_EQ(a.insert({5.0}, -std::numeric_limits<double>::infinity(), std::vector<double>{7.0, 0.0}).status, Insertion::Rejected);
  ASSERT_NE(a.elite(1), nullptr);
  EXPECT_EQ(*a.elite(1), (Elite{{4.0, 4.5}, 2.5, {1.5, 0.9}}));  // genomes of any length
  EXPECT_EQ(a.elite(7), nullptr);
  EXPECT_EQ(a.filled(), 1u);
  EXPECT_THROW(a.insert({}, 1.0, d), std::invalid_argument);
  EXPECT_THROW(a.insert({std::nan("")}, 1.0, d), std::invalid_argument);
  EXPECT_THROW(a.insert({1.0}, 1.0, std::vector<double>{1.0}), std::invalid_argument);
  EXPECT_THROW(a.insert({1.0}, 1.0, std::vector<double>{1.0, INFINITY}), std::invalid_argument);
}

TEST(Archive, QdScoreCoverageAndBestOnAHandExample) {
  Archive a = small_grid(-10.0);  // fitness bounded below by -10
  EXPECT_EQ(a.qd_score(), 0.0);
  EXPECT_EQ(a.coverage(), 0.0);
  EXPECT_FALSE(a.best().has_value());
  (void)a.insert({0.0}, -4.0, std::vector<double>{1.0, -1.0});  // cell 0: -4 - -10 = 6
  (void)a.insert({0.0}, 3.0, std::vector<double>{7.0, 1.0});   // cell 7: 13
  (void)a.insert({0.0}, -2.0, std::vector<double>{3.0, 0.5});  // cell 3: 8
  EXPECT_EQ(a.qd_score(), 27.0);
  EXPECT_EQ(a.coverage(), 3.0 / 8.0);
  EXPECT_EQ(a.best(), 3.0);
  (void)a.insert({0.0}, -1.0, std::vector<double>{1.5, -0.5});  // cell 0 improves to 9
  EXPECT_EQ(a.qd_score(), 30.0);
  // Below the declared bound the fitness counts 0, so the score never falls.
  (void)a.insert({0.0}, -15.0, std::vector<double>{5.0, 0.0});  // cell (2, 1) = 5
  EXPECT_EQ(a.qd_score(), 30.0);
  EXPECT_EQ(a.coverage(), 0.5);
  EXPECT_EQ(std::vector<std::size_t>(a.filled_cells().begin(), a.filled_cells().end()), (std::vector<std::size_t>{0, 3, 5, 7}));
}

// Fitnesses far above a bound far below: every contribution and the sum stay finite.
TEST(Archive, QdScoreSaturatesAtTheLargestDouble) {
  Archive a = small_grid(-1e308);
  (void)a.insert({0.0}, 1e300, std::vector<double>{1.0, -1.0});
  EXPECT_LT(a.qd_score(), std::numeric_limits<double>::max());   // 1e308 + 1e300
  (void)a.insert({0.0}, 1e300, std::vector<double>{7.0, 1.0});
  EXPECT_EQ(a.qd_score(), std::numeric_limits<double>::max());
  Archive b = small_grid(-1e307);
  for (const double x : {1.0, 3.0, 5.0, 7.0}) (void)b.insert({0.0}, 1e307, std::vector<double>{x, 1.0});
  EXPECT_DOUBLE_EQ(b.qd_score(), 8e307);   // within the doubles, the plain sum
}

TEST(Archive, ChangesAreTheLatestEliteOfEachChangedCellInCellOrder) {
  Archive a = small_grid();
  (void)a.insert({1.0}, 1.0, std::vector<double>{7.0, 1.0});   // cell 7
  (void)a.insert({2.0}, 1.0, std::vector<double>{1.0, -1.0});  // cell 0
  (void)a.insert({3.0}, 5.0, std::vector<double>{7.5, 1.0});   // cell 7 again, improved
  (void)a.insert({4.0}, 0.0, std::vector<double>{1.0, -1.0});  // rejected
  const std::vector<Change> first = a.take_changes();
  ASSERT_EQ(first.size(), 2u);
  EXPECT_EQ(first[0], (Change{0, Elite{{2.0}, 1.0, {1.0, -1.0}}}));
  EXPECT_EQ(first[1], (Change{7, Elite{{3.0}, 5.0, {7.5, 1.0}}}));
  EXPECT_TRUE(a.take_changes().empty());
  (void)a.insert({5.0}, 6.0, std::vector<double>{7.0, 0.9});
  EXPECT_EQ(a.take_changes(), (std::vector<Change>{{7, Elite{{5.0}, 6.0, {7.0, 0.9}}}}));
}

TEST(Archive, ReplayingEachGenerationsChangesRebuildsTheArchiveExactly) {
  for (const bool cvt : {false, true}) {
    const Archive empty = cvt ? Archive(unit_square(), small_cvt(5), -3.0) : Archive(unit_square(), Grid({8, 8}), -3.0);
    Archive live = empty;
    std::vector<std::vector<Change>> generations;
    std::vector<Archive> snapshots;
    Rng rng(6);
    for (int g = 0; g < 30; ++g) {
      for (int i = 0; i < 40; ++i) {
        const std::size_t length = 1 + rng.below(5);  // genomes of varying length
        Genome genome(length);
        for (double& v : genome) v = rng.normal();
        (void)live.insert(std::move(genome), rng.uniform(-3.0, 3.0), std::vector<double>{rng.uniform(), rng.uniform()});
      }
      generations.push_back(live.take_changes());
      snapshots.push_back(live);
    }
    Archive rebuilt = empty;
    for (std::size_t g = 0; g < generations.size(); ++g) {
      rebuilt = replay(std::move(rebuilt), generations[g]);
      EXPECT_EQ(rebuilt.take_changes(), generations[g]) << "generation " << g;
      for (std::size_t c = 0; c < rebuilt.cells(); ++c) {
        const Elite* want = snapshots[g].elite(c);
        const Elite* got = rebuilt.elite(c);
        ASSERT_EQ(want == nullptr, got == nullptr) << "generation " << g << " cell " << c;
        if (want) {
          EXPECT_EQ(*got, *want);
        }
      }
      EXPECT_EQ(rebuilt.save(), snapshots[g].save());
    }
    EXPECT_GT(live.filled(), live.cells() / 2);
    // A change whose descriptor lies in another cell is not a change this archive made.
    Change wrong = generations[0][0];
    wrong.cell = (wrong.cell + 1) % rebuilt.cells();
    EXPECT_THROW(rebuilt.apply(wrong), std::invalid_argument);
  }
}

// An archive with a few elites and a change not yet taken.
Archive filled_archive(Archive a) {
  Rng rng(8);
  for (int i = 0; i < 30; ++i)
    (void)a.insert({rng.normal(), rng.normal()}, rng.uniform(), std::vector<double>{rng.uniform(0.0, 8.0), rng.uniform(-1.0, 1.0)});
  (void)a.take_changes();
  (void)a.insert({9.0}, 99.0, std::vector<double>{0.0, 0.0});
  return a;
}

TEST(Archive, SaveLoadRoundTripsAndRefusesWhatItCouldNotHaveWritten) {
  const Archive a = filled_archive(small_grid());
  const StateBytes state = a.save();
  Archive b = small_grid();
  b.load(state);
  EXPECT_EQ(b.save(), state);
  EXPECT_EQ(b.qd_score(), a.qd_score());
  EXPECT_EQ(b.take_changes(), Archive(a).take_changes());

  const Archive untouched = small_grid();
  const auto refused = [&](const StateBytes& bytes, Archive into, const std::string& why) {
    const StateBytes before = into.save();
    const std::string m = message_of([&] { into.load(bytes); });
    EXPECT_NE(m.find(why), std::string::npos) << m;
    EXPECT_EQ(into.save(), before) << "a refused load changed the archive";
  };
  refused(StateBytes(state.begin(), state.end() - 1), untouched, "optimizer state");  // StateReader's refusal
  StateBytes longer = state;
  longer.push_back(0);
  refused(longer, untouched, "left after");
  refused(state, Archive(DescriptorSpace({{0.0, 8.0}, {-1.0, 1.0}}), Grid({4, 3}), 0.0), "bins");
  refused(state, Archive(DescriptorSpace({{0.0, 9.0}, {-1.0, 1.0}}), Grid({4, 2}), 0.0), "ranges");
  refused(state, small_grid(1.0), "fitness_offset");
  refused(state, Archive(DescriptorSpace({{0.0, 8.0}, {-1.0, 1.0}}), small_cvt(1, 8), 0.0), "kind");
  // The elite of fitness 99 with its fitness made NaN, then made to lie in another cell.
  StateBytes corrupt = state;
  const double f = 99.0, nan = std::nan("");
  const auto at = std::search(corrupt.begin(), corrupt.end(), reinterpret_cast<const std::uint8_t*>(&f),
                              reinterpret_cast<const std::uint8_t*>(&f) + sizeof f);
  ASSERT_NE(at, corrupt.end());
  std::memcpy(&*at, &nan, sizeof nan);
  refused(corrupt, untouched, "finite");
  // Two elites, cells 0 and 7; the first one's cell field says 3: in order, but its
  // descriptor lies in cell 0.
  Archive two = small_grid();
  (void)two.insert({1.0}, 99.0, std::vector<double>{0.0, 0.0});
  (void)two.insert({2.0}, 98.0, std::vector<double>{8.0, 1.0});
  StateBytes moved = two.save();
  const auto fitness_at = std::search(moved.begin(), moved.end(), reinterpret_cast<const std::uint8_t*>(&f),
                                      reinterpret_cast<const std::uint8_t*>(&f) + sizeof f);
  const std::uint64_t cell3 = 3;
  std::memcpy(&*(fitness_at - 8), &cell3, sizeof cell3);
  refused(moved, untouched, "does not lie in cell 3");
}

TEST(Archive, ACvtArchiveTakesItsCentroidsFromTheState) {
  const DescriptorSpace space({{0.0, 8.0}, {-1.0, 1.0}});
  const Archive a = filled_archive(Archive(space, small_cvt(1, 16), 0.0));
  Archive b(space, small_cvt(2, 16), 0.0);  // other centroids, same k
  ASSERT_NE(std::get<Cvt>(b.tessellation()).centroids(), std::get<Cvt>(a.tessellation()).centroids());
  b.load(a.save());
  EXPECT_EQ(std::get<Cvt>(b.tessellation()).centroids(), std::get<Cvt>(a.tessellation()).centroids());
  EXPECT_EQ(b.save(), a.save());
  Archive c(space, small_cvt(2, 17), 0.0);
  EXPECT_NE(message_of([&] { c.load(a.save()); }).find("number of cells"), std::string::npos);
}

TEST(Archive, MemoryEstimateBoundsAFullArchiveClosely) {
  const std::size_t genome = 100;
  for (const bool cvt : {false, true}) {
    Archive a = cvt ? Archive(unit_square(), small_cvt(1, 400), 0.0) : Archive(unit_square(), Grid({20, 20}), 0.0);
    Rng rng(2);
    while (a.filled() < a.cells()) (void)a.insert(Genome(genome, 0.5), 1.0, std::vector<double>{rng.uniform(), rng.uniform()});
    const double held = a.memory_bytes();
    const double estimate = archive_memory_bytes(a.cells(), genome, 2, static_cast<double>(a.cells()), cvt);
    EXPECT_GE(estimate, held) << (cvt ? "cvt" : "grid");
    EXPECT_LE(estimate, 1.15 * held) << (cvt ? "cvt" : "grid");
  }
}

// ---- selection and variation ----

TEST(Selection, DrawsEveryFilledCellUniformly) {
  Archive a = small_grid();
  for (const double x : {1.0, 3.0, 7.0}) (void)a.insert({x}, x, std::vector<double>{x, 0.5});  // cells 1, 3, 7
  Rng rng(11);
  std::vector<int> count(8);
  const int draws = 30'000;
  for (int i = 0; i < draws; ++i) ++count[a.cell_of(select_uniform(a, rng).descriptor)];
  for (const std::size_t cell : {1u, 3u, 7u}) EXPECT_NEAR(count[cell], draws / 3.0, 4.0 * std::sqrt(draws * 2.0 / 9.0));
  EXPECT_EQ(count[1] + count[3] + count[7], draws);
  Archive empty = small_grid();
  EXPECT_THROW((void)select_uniform(empty, rng), std::logic_error);
}

TEST(IsoLineDd, ChildrenSpreadAroundTheFirstParentAlongTheLineAsTheSigmasSay) {
  const std::vector<double> x{0.2, -0.3, 0.5, 0.1}, y{0.6, 0.1, -0.1, 0.3};
  const IsoLineDd op{.sigma_iso = 0.05, .sigma_line = 0.2, .lower = -10.0, .upper = 10.0};
  std::vector<double> u(4);
  double length = 0.0;
  for (std::size_t i = 0; i < 4; ++i) length += (y[i] - x[i]) * (y[i] - x[i]);
  length = std::sqrt(length);
  for (std::size_t i = 0; i < 4; ++i) u[i] = (y[i] - x[i]) / length;
  Rng rng(12);
  const int n = 40'000;
  std::vector<double> mean(4);
  double along2 = 0.0, across2 = 0.0;
  for (int k = 0; k < n; ++k) {
    const Genome c = iso_line_dd(x, y, op, rng);
    double along = 0.0;
    for (std::size_t i = 0; i < 4; ++i) {
      mean[i] += (c[i] - x[i]) / n;
      along += (c[i] - x[i]) * u[i];
    }
    along2 += along * along / n;
    for (std::size_t i = 0; i < 4; ++i) across2 += std::pow(c[i] - x[i] - along * u[i], 2) / n;
  }
  // Mean: the first parent (on the parents' line); along the line, variance
  // sigma_iso^2 + sigma_line^2 |y - x|^2; across it, sigma_iso^2 in each of 3 directions.
  const double var_along = 0.05 * 0.05 + 0.04 * length * length;
  for (const double m : mean) EXPECT_NEAR(m, 0.0, 5.0 * std::sqrt(var_along / n));
  EXPECT_NEAR(along2 / var_along, 1.0, 0.04);
  EXPECT_NEAR(across2 / (3 * 0.05 * 0.05), 1.0, 0.04);
}

TEST(IsoLineDd, WithoutTheIsotropicTermChildrenLieOnTheLineAndStayInTheBox) {
  const std::vector<double> x{0.0, 0.0, 0.0}, y{0.5, -0.25, 1.0};
  Rng rng(13);
  for (int k = 0; k < 1000; ++k) {
    const Genome c = iso_line_dd(x, y, {.sigma_iso = 0.0, .sigma_line = 0.5, .lower = -1.0, .upper = 1.0}, rng);
    if (std::abs(c[2]) < 1.0) {  // not clipped: a multiple of y - x
      EXPECT_DOUBLE_EQ(c[0], 0.5 * c[2]);
      EXPECT_DOUBLE_EQ(c[1], -0.25 * c[2]);
    }
    const Genome wide = iso_line_dd(y, x, {.sigma_iso = 5.0, .sigma_line = 5.0, .lower = -1.0, .upper = 1.0}, rng);
    for (const double v : wide) {
      ASSERT_GE(v, -1.0);
      ASSERT_LE(v, 1.0);
    }
  }
  EXPECT_THROW((void)iso_line_dd(x, std::vector<double>{1.0}, {}, rng), std::invalid_argument);
}

// ---- MAP-Elites ----

// The toy problem: genomes in [-1, 1]^6, the first two genes mapped onto [0, 1] as the
// descriptor, fitness -sphere (at least -6 in the box).
struct Toy {
  std::vector<double> fitness;
  std::vector<std::vector<double>> descriptors;
  explicit Toy(const std::vector<Genome>& genomes) {
    for (const Genome& g : genomes) {
      double s = 0.0;
      for (const double v : g) s += v * v;
      fitness.push_back(-s);
      descriptors.push_back({(g[0] + 1.0) / 2.0, (g[1] + 1.0) / 2.0});
    }
  }
};

// Empty toy archives, computed once: a grid of 10 x 10 and CVTs of 100 cells from two seeds.
const Archive& toy_archive(bool cvt, std::uint64_t centroid_seed = 1) {
  static const Archive grid(unit_square(), Grid({10, 10}), -6.0);
  static const Archive cvt1(unit_square(), small_cvt(1, 100), -6.0);
  static const Archive cvt2(unit_square(), small_cvt(2, 100), -6.0);
  return !cvt ? grid : centroid_seed == 1 ? cvt1 : cvt2;
}

MapElites toy_map_elites(bool cvt, std::uint64_t centroid_seed = 1) {
  return MapElites(MapElitesSettings{}, 6, toy_archive(cvt, centroid_seed));
}

TEST(MapElites, FirstGenerationIsUniformThenBatchesOfChildren) {
  MapElitesSettings s;
  s.initial = 37;
  s.batch = 12;
  s.lower = -2.0;
  s.upper = 3.0;
  MapElites me(s, 4, Archive(unit_square(), Grid({5, 5}), 0.0));
  Rng g0 = generation_rng(1, 0);
  const auto first = me.ask(g0);
  ASSERT_EQ(first.size(), 37u);
  double mean = 0.0;
  for (const Genome& g : first) {
    ASSERT_EQ(g.size(), 4u);
    for (const double v : g) {
      EXPECT_GE(v, -2.0);
      EXPECT_LT(v, 3.0);
      mean += v / (37.0 * 4.0);
    }
  }
  EXPECT_NEAR(mean, 0.5, 4.0 * 5.0 / std::sqrt(12.0 * 148.0));
  std::vector<double> fitness(37, 1.0);
  std::vector<std::vector<double>> d(37, std::vector<double>{0.5, 0.5});
  me.tell(fitness, d);
  Rng g1 = generation_rng(1, 1);
  EXPECT_EQ(me.ask(g1).size(), 12u);
  EXPECT_THROW(me.tell(std::vector<double>(11, 1.0), std::vector<std::vector<double>>(11, {0.5, 0.5})), std::invalid_argument);
  EXPECT_THROW(me.tell(std::vector<double>(12, 1.0), std::vector<std::vector<double>>(12, {0.5})), std::invalid_argument);
  EXPECT_EQ(me.archive().filled(), 1u);  // nothing of the refused tells went in
}

TEST(MapElites, FillsTheToyArchiveAndRaisesItsQdScore) {
  for (const bool cvt : {false, true}) {
    MapElites me = toy_map_elites(cvt);
    double last = 0.0, first = 0.0;
    for (std::uint64_t g = 0; g < 60; ++g) {
      Rng rng = generation_rng(21, g);
      const auto genomes = me.ask(rng);
      const Toy toy(genomes);
      me.tell(toy.fitness, toy.descriptors);
      EXPECT_GE(me.qd_score(), last) << "generation " << g;
      last = me.qd_score();
      if (g == 0) first = last;
    }
    EXPECT_GE(me.coverage(), 0.95) << (cvt ? "cvt" : "grid");
    EXPECT_GT(last, 1.3 * first) << (cvt ? "cvt" : "grid");
    // The genes that do not set the cell were optimised towards 0: uniform ones would give
    // 4 / 3 on average.
    double rest = 0.0;
    for (const std::size_t c : me.archive().filled_cells()) {
      const Genome& genome = me.archive().elite(c)->genome;
      for (std::size_t i = 2; i < 6; ++i) rest += genome[i] * genome[i] / static_cast<double>(me.archive().filled());
    }
    EXPECT_LT(rest, 0.2) << (cvt ? "cvt" : "grid");
    EXPECT_GT(*me.best(), -0.05);
  }
}

TEST(MapElites, SaveAfterEveryGenerationAndLoadContinuesBitIdentically) {
  for (const bool cvt : {false, true}) {
    MapElites straight = toy_map_elites(cvt);
    MapElites resumed = toy_map_elites(cvt);
    for (std::uint64_t g = 0; g < 25; ++g) {
      Rng a = generation_rng(31, g), b = generation_rng(31, g);
      const auto xs = straight.ask(a);
      const auto ys = resumed.ask(b);
      ASSERT_EQ(xs, ys) << "generation " << g;
      const Toy toy(xs);
      straight.tell(toy.fitness, toy.descriptors);
      resumed.tell(toy.fitness, toy.descriptors);
      // A fresh object, its CVT computed from another seed: the state brings the centroids.
      MapElites fresh = toy_map_elites(cvt, 2);
      fresh.load(resumed.save());
      resumed = std::move(fresh);
    }
    EXPECT_EQ(resumed.save(), straight.save());
    EXPECT_EQ(resumed.generation(), 25u);
  }
}

TEST(MapElites, GivenStartGenomeIsCandidateZeroOfTheNextAskAndSurvivesASave) {
  MapElites me = toy_map_elites(false);
  const std::vector<double> start{0.1, -0.2, 0.3, -0.4, 0.5, 1.0};
  me.start(start);
  MapElites loaded = toy_map_elites(false);
  loaded.load(me.save());  // a run killed before its first generation
  Rng a = generation_rng(1, 0), b = generation_rng(1, 0);
  const auto xs = me.ask(a);
  EXPECT_EQ(xs[0], start);
  EXPECT_NE(xs[1], start);
  EXPECT_EQ(loaded.ask(b), xs);
  EXPECT_THROW(me.start(std::vector<double>{0.0, 0.0, 0.0, 0.0, 0.0, 1.5}), std::invalid_argument);
  EXPECT_THROW(me.start(std::vector<double>{0.0}), std::invalid_argument);
}

TEST(MapElites, LoadRefusesOtherSettingsAndLeavesTheObjectAsItWas) {
  MapElites me = toy_map_elites(false);
  Rng rng = generation_rng(1, 0);
  const Toy toy(me.ask(rng));
  me.tell(toy.fitness, toy.descriptors);
  const StateBytes state = me.save();
  MapElitesSettings other;
  other.sigma_line = 0.3;
  MapElites different(other, 6, Archive(unit_square(), Grid({10, 10}), -6.0));
  const StateBytes before = different.save();
  EXPECT_NE(message_of([&] { different.load(state); }).find("sigma_line"), std::string::npos);
  EXPECT_EQ(different.save(), before);
  MapElites longer(MapElitesSettings{}, 7, Archive(unit_square(), Grid({10, 10}), -6.0));
  EXPECT_NE(message_of([&] { longer.load(state); }).find("genome of 6"), std::string::npos);
  MapElites finer(MapElitesSettings{}, 6, Archive(unit_square(), Grid({10, 11}), -6.0));
  EXPECT_NE(message_of([&] { finer.load(state); }).find("bins"), std::string::npos);
  MapElites same = toy_map_elites(false);
  EXPECT_THROW(same.load(StateBytes(state.begin(), state.end() - 8)), std::invalid_argument);
  StateBytes longer_state = state;
  longer_state.push_back(1);
  EXPECT_THROW(same.load(longer_state), std::invalid_argument);
  EXPECT_EQ(same.archive().filled(), 0u);
}

TEST(MapElites, RefusesImpossibleSettingsNamingThem) {
  const auto with = [](auto change) {
    MapElitesSettings s;
    change(s);
    return message_of([&] { MapElites(s, 4, Archive(unit_square(), Grid({2, 2}), 0.0)); });
  };
  EXPECT_NE(with([](MapElitesSettings& s) { s.batch = 0; }).find("batch"), std::string::npos);
  EXPECT_NE(with([](MapElitesSettings& s) { s.initial = 0; }).find("initial"), std::string::npos);
  EXPECT_NE(with([](MapElitesSettings& s) { s.sigma_iso = -0.1; }).find("sigma_iso"), std::string::npos);
  EXPECT_NE(with([](MapElitesSettings& s) { s.sigma_line = std::nan(""); }).find("sigma_line"), std::string::npos);
  EXPECT_NE(with([](MapElitesSettings& s) { s.upper = -2.0; }).find("upper"), std::string::npos);
  EXPECT_NE(with([](MapElitesSettings& s) { s.lower = -2e6; }).find("lower"), std::string::npos);
  EXPECT_NE(message_of([] { MapElites(MapElitesSettings{}, 0, Archive(unit_square(), Grid({2, 2}), 0.0)); }).find("genome size"),
            std::string::npos);
  Archive seeded(unit_square(), Grid({2, 2}), 0.0);
  (void)seeded.insert({0.0, 0.0, 0.0}, 1.0, std::vector<double>{0.5, 0.5});
  EXPECT_NE(message_of([&] { MapElites(MapElitesSettings{}, 2, seeded); }).find("another size"), std::string::npos);
  MapElites me(MapElitesSettings{}, 2, Archive(unit_square(), Grid({2, 2}), 0.0));
  EXPECT_THROW(me.tell(std::vector<double>{}, std::vector<std::vector<double>>{}), std::logic_error);
}

TEST(MapElites, MemoryEstimateAddsOneGenerationToTheArchive) {
  // 200 rows of 100 genes (asked and handed out) and 100 of 2 descriptors, as the heap holds them.
  EXPECT_EQ(map_elites_memory_bytes(MapElitesSettings{}, 100, 10'000, 2, 10'000, false),
            archive_memory_bytes(10'000, 100, 2, 10'000, false) + 200.0 * (24 + 816) + 100.0 * (24 + 32));
  // Only the cells a run can fill hold elites: the rest is the empty slots and centroids.
  EXPECT_LT(archive_memory_bytes(10'000, 100, 2, 500, false),
            0.25 * archive_memory_bytes(10'000, 100, 2, 10'000, false));
  EXPECT_EQ(archive_memory_bytes(10'000, 100, 2, 1e9, false), archive_memory_bytes(10'000, 100, 2, 10'000, false));
}

}  // namespace
}  // namespace esc::evo::qd
