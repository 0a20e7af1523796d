// Novelty search's archive: k-nearest-neighbour novelty against a brute-force reference,
// hand examples, the threshold's adaptation, random additions, determinism and state.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/evo/map_elites/point_tree.hpp"
#include "runtime/evo/novelty/novelty_optimizer.hpp"
#include "runtime/evo/nsga2/nsga2_optimizer.hpp"
#include "runtime/evo/novelty/novelty_archive.hpp"

namespace esc::evo::qd {
namespace {

using Points = std::vector<std::vector<double>>;

template <class F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

NoveltySettings with_k(std::size_t k) {
  NoveltySettings s;
  s.k = k;
  return s;
}

// An archive holding exactly `points`: random mode with probability 1 adds everyone (the
// mode plays no part in scores()).
NoveltyArchive holding(NoveltySettings s, const DescriptorSpace& space, const Points& points) {
  s.mode = NoveltyMode::Random;
  s.random_probability = 1.0;
  NoveltyArchive a(s, space);
  Rng rng(1);
  (void)a.update(points, std::vector<double>(points.size(), 0.0), rng);
  return a;
}

// The reference: for each individual, every distance to the other individuals and to the
// archive, sorted, the k smallest summed in increasing order, divided by how many there are.
std::vector<double> brute_force(const DescriptorSpace& space, const Points& population, const Points& archive, std::size_t k) {
  std::vector<std::vector<double>> unit;
  for (const auto& p : population) unit.push_back(space.to_unit(p));
  for (const auto& p : archive) unit.push_back(space.to_unit(p));
  std::vector<double> novelty;
  for (std::size_t i = 0; i < population.size(); ++i) {
    std::vector<double> d;
    for (std::size_t j = 0; j < unit.size(); ++j)
      if (j != i) d.push_back(std::sqrt(squared_distance(unit[i], unit[j])));
    std::sort(d.begin(), d.end());
    const std::size_t m = std::min(k, d.size());
    double sum = 0.0;
    for (std::size_t j = 0; j < m; ++j) sum += d[j];
    novelty.push_back(m == 0 ? 0.0 : sum / static_cast<double>(m));
  }
  return novelty;
}

Points random_points(Rng& rng, std::size_t n, std::size_t dims, double lo, double hi) {
  Points p(n, std::vector<double>(dims));
  for (auto& v : p)
    for (double& x : v) x = rng.uniform(lo, hi);
  return p;
}

TEST(Novelty, HandExampleOnALine) {
  const DescriptorSpace space({{0.0, 10.0}});
  const Points population{{0.0}, {1.0}, {3.0}};  // 0, 0.1, 0.3 in unit coordinates
  const auto k1 = NoveltyArchive(with_k(1), space).scores(population);
  EXPECT_NEAR(k1[0], 0.1, 1e-15);
  EXPECT_NEAR(k1[1], 0.1, 1e-15);
  EXPECT_NEAR(k1[2], 0.2, 1e-15);
  const auto k2 = NoveltyArchive(with_k(2), space).scores(population);
  EXPECT_NEAR(k2[0], (0.1 + 0.3) / 2, 1e-15);
  EXPECT_NEAR(k2[1], (0.1 + 0.2) / 2, 1e-15);
  EXPECT_NEAR(k2[2], (0.2 + 0.3) / 2, 1e-15);
  // With the archive point 3.5 (0.35) the third individual's two nearest are 0.05 and 0.2
  // away; 15 neighbours asked, 3 there: the mean over those.
  const auto archived = holding(with_k(2), space, {{3.5}}).scores(population);
  EXPECT_NEAR(archived[2], (0.05 + 0.2) / 2, 1e-15);
  const auto all = holding(with_k(15), space, {{3.5}}).scores(population);
  EXPECT_NEAR(all[0], (0.1 + 0.3 + 0.35) / 3, 1e-15);
  // Alone, nothing to differ from; outside its range, a behavior counts as the bound.
  EXPECT_EQ(NoveltyArchive(with_k(15), space).scores(Points{{5.0}}), std::vector<double>{0.0});
  EXPECT_EQ(NoveltyArchive(with_k(1), space).scores(Points{{-4.0}, {20.0}}), (std::vector<double>{1.0, 1.0}));
  EXPECT_TRUE(NoveltyArchive(with_k(1), space).scores(Points{}).empty());
}

TEST(Novelty, KNearestDistancesEqualABruteForceSearchExactly) {
  Rng rng(7);
  for (const std::size_t dims : {1u, 2u, 5u}) {
    std::vector<Range> ranges;
    for (std::size_t d = 0; d < dims; ++d) ranges.push_back({-1.0 - static_cast<double>(d), 2.0 + static_cast<double>(d)});
    const DescriptorSpace space(ranges);
    for (const std::size_t k : {1u, 3u, 15u, 60u}) {
      for (const auto& [n, m] : std::vector<std::pair<std::size_t, std::size_t>>{{2, 0}, {10, 5}, {150, 0}, {150, 700}}) {
        Points population = random_points(rng, n, dims, -3.0, 5.0);  // some outside the ranges
        Points archive = random_points(rng, m, dims, -3.0, 5.0);
        population.push_back(population[0]);  // twins: equal distances and a zero
        if (m > 0) archive.push_back(population[1]);
        const auto got = holding(with_k(k), space, archive).scores(population);
        ASSERT_EQ(got, brute_force(space, population, archive, k)) << "dims " << dims << " k " << k << " n " << n << " m " << m;
      }
    }
  }
}

TEST(Novelty, OneCommonRangeOnlyScalesThePapersRawDistances) {
  // Maze end points in the paper's units (a 200-unit arena): normalising both coordinates by
  // one width divides every distance by it, so the ranking is the raw one.
  Rng rng(8);
  const Points population = random_points(rng, 100, 2, 0.0, 200.0);
  const auto unit = NoveltyArchive(with_k(15), DescriptorSpace({{0.0, 200.0}, {0.0, 200.0}})).scores(population);
  const auto raw = brute_force(DescriptorSpace({{0.0, 1.0}, {0.0, 1.0}}), [&] {
    Points p = population;
    for (auto& v : p)
      for (double& x : v) x /= 200.0;
    return p;
  }(), {}, 15);
  for (std::size_t i = 0; i < population.size(); ++i) EXPECT_NEAR(unit[i], raw[i], 1e-12);
}

TEST(Novelty, ThresholdAddsAboveItAndAdaptsAsTheAuthorsCodeDoes) {
  NoveltySettings s;
  s.threshold = 1.0;
  s.threshold_floor = 0.9;
  NoveltyArchive a(s, DescriptorSpace({{0.0, 1.0}}));
  Rng rng(1);
  const Points five(5, std::vector<double>{0.5});
  const auto update = [&](std::vector<double> novelty) {
    return a.update(Points(novelty.size(), std::vector<double>{0.5}), novelty, rng);
  };
  // Five above 1.0 (equal is not above): all added, more than four, so x 1.2.
  EXPECT_EQ(update({1.5, 2.0, 1.01, 3.0, 1.1, 1.0, 0.2}), 5u);
  EXPECT_EQ(a.size(), 5u);
  EXPECT_DOUBLE_EQ(a.threshold(), 1.2);
  // Exactly four: no change.
  EXPECT_EQ(update({1.3, 1.3, 1.3, 1.3}), 4u);
  EXPECT_DOUBLE_EQ(a.threshold(), 1.2);
  // Nine generations adding nothing, then one adding one: the stall count restarts.
  for (int g = 0; g < 9; ++g) EXPECT_EQ(update({0.1, 1.2}), 0u);
  EXPECT_EQ(update({1.25}), 1u);
  EXPECT_DOUBLE_EQ(a.threshold(), 1.2);
  // Ten in a row adding nothing: x 0.95 at the tenth, not before.
  for (int g = 0; g < 9; ++g) (void)update({0.0});
  EXPECT_DOUBLE_EQ(a.threshold(), 1.2);
  (void)update({0.0});
  EXPECT_DOUBLE_EQ(a.threshold(), 1.14);
  // Ten more each time: 1.083, 1.02885, 0.9774075, 0.928537125, then 0.88211... is below
  // the floor, 0.9, where it stays.
  for (const double expected : {1.083, 1.02885, 0.9774075, 0.928537125, 0.9, 0.9}) {
    for (int g = 0; g < 10; ++g) (void)update({});
    EXPECT_DOUBLE_EQ(a.threshold(), expected);
  }
  EXPECT_EQ(a.size(), 10u);
  EXPECT_THROW((void)a.update(five, std::vector<double>{2.0}, rng), std::invalid_argument);  // a score each
}

TEST(Novelty, RandomModeAddsEachIndividualWithTheGivenProbability) {
  NoveltySettings s;
  s.mode = NoveltyMode::Random;
  s.random_probability = 0.05;
  NoveltyArchive a(s, DescriptorSpace({{0.0, 1.0}, {0.0, 1.0}}));
  Rng rng(3);
  const Points population = random_points(rng, 1000, 2, 0.0, 1.0);
  const std::vector<double> huge(1000, 1e9);  // novelty plays no part
  for (int g = 0; g < 100; ++g) {
    Rng breed(3, {2, static_cast<std::uint64_t>(g)});
    (void)a.update(population, huge, breed);
  }
  // 100,000 draws at 0.05: 5,000 expected, sd sqrt(100000 * 0.05 * 0.95) = 68.9.
  EXPECT_NEAR(static_cast<double>(a.size()), 5000.0, 4 * 68.9);
  EXPECT_EQ(a.threshold(), s.threshold);
  s.random_probability = 0.0;
  NoveltyArchive none(s, DescriptorSpace({{0.0, 1.0}, {0.0, 1.0}}));
  EXPECT_EQ(none.update(population, huge, rng), 0u);
}

TEST(Novelty, SameSeedSameArchiveAndStateRoundTrips) {
  const DescriptorSpace space({{0.0, 1.0}, {-5.0, 5.0}, {0.0, 3.0}});
  const auto run = [&](NoveltyMode mode, std::uint64_t seed, int generations) {
    NoveltySettings s;
    s.mode = mode;
    s.random_probability = 0.1;
    s.threshold = 0.2;
    NoveltyArchive a(s, space);
    for (int g = 0; g < generations; ++g) {
      Rng rng(seed, {2, static_cast<std::uint64_t>(g)});
      const Points population = random_points(rng, 50, 3, -1.0, 4.0);
      (void)a.update(population, a.scores(population), rng);
    }
    return a;
  };
  for (const NoveltyMode mode : {NoveltyMode::Threshold, NoveltyMode::Random}) {
    const NoveltyArchive a = run(mode, 5, 30);
    EXPECT_GT(a.size(), 10u);
    EXPECT_EQ(a.save(), run(mode, 5, 30).save());
    EXPECT_NE(a.save(), run(mode, 6, 30).save());
    NoveltySettings s = a.settings();
    NoveltyArchive b(s, space);
    b.load(a.save());
    EXPECT_EQ(b.save(), a.save());
    EXPECT_EQ(b.points(), a.points());
    EXPECT_EQ(b.threshold(), a.threshold());
  }
}

TEST(Novelty, LoadContinuesBitIdenticallyAndRefusesOtherStates) {
  const DescriptorSpace space({{0.0, 1.0}, {0.0, 1.0}});
  NoveltySettings s;
  s.threshold = 0.1;
  NoveltyArchive straight(s, space), resumed(s, space);
  for (std::uint64_t g = 0; g < 40; ++g) {
    Rng a(9, {2, g}), b(9, {2, g});
    const Points pa = random_points(a, 30, 2, 0.0, 1.0);
    const Points pb = random_points(b, 30, 2, 0.0, 1.0);
    ASSERT_EQ(straight.scores(pa), resumed.scores(pb));
    (void)straight.update(pa, straight.scores(pa), a);
    (void)resumed.update(pb, resumed.scores(pb), b);
    NoveltyArchive fresh(s, space);
    fresh.load(resumed.save());
    resumed = fresh;
  }
  EXPECT_EQ(resumed.save(), straight.save());

  const StateBytes state = straight.save();
  const auto refused = [&](NoveltyArchive into, const StateBytes& bytes, const std::string& why) {
    const StateBytes before = into.save();
    const std::string m = message_of([&] { into.load(bytes); });
    EXPECT_NE(m.find(why), std::string::npos) << m;
    EXPECT_EQ(into.save(), before);
  };
  refused(NoveltyArchive(s, DescriptorSpace({{0.0, 1.0}, {0.0, 2.0}})), state, "ranges");
  refused(NoveltyArchive(s, DescriptorSpace({{0.0, 1.0}})), state, "descriptors");
  refused(NoveltyArchive(with_k(5), space), state, "k");
  NoveltySettings random = s;
  random.mode = NoveltyMode::Random;
  refused(NoveltyArchive(random, space), state, "mode");
  refused(NoveltyArchive(s, space), StateBytes(state.begin(), state.end() - 3), "optimizer state");
  StateBytes longer = state;
  longer.push_back(0);
  refused(NoveltyArchive(s, space), longer, "left after");
  StateBytes nan = state;
  const double not_a_number = std::nan("");
  std::memcpy(nan.data() + nan.size() - 8, &not_a_number, 8);  // the last point's last value
  refused(NoveltyArchive(s, space), nan, "finite");
}

TEST(Novelty, RefusesImpossibleSettingsAndDescriptorsNamingThem) {
  const DescriptorSpace space({{0.0, 1.0}});
  const auto with = [&](auto change) {
    NoveltySettings s;
    change(s);
    return message_of([&] { NoveltyArchive(s, space); });
  };
  EXPECT_NE(with([](NoveltySettings& s) { s.k = 0; }).find("k "), std::string::npos);
  EXPECT_NE(with([](NoveltySettings& s) { s.threshold = 0.0; }).find("threshold"), std::string::npos);
  EXPECT_NE(with([](NoveltySettings& s) { s.threshold_floor = 1.0; }).find("threshold_floor"), std::string::npos);
  EXPECT_NE(with([](NoveltySettings& s) { s.raise_factor = 0.5; }).find("raise_factor"), std::string::npos);
  EXPECT_NE(with([](NoveltySettings& s) { s.lower_factor = 1.5; }).find("lower_factor"), std::string::npos);
  EXPECT_NE(with([](NoveltySettings& s) { s.stall_generations = 0; }).find("stall_generations"), std::string::npos);
  EXPECT_NE(with([](NoveltySettings& s) { s.random_probability = 2.0; }).find("random_probability"), std::string::npos);
  const NoveltyArchive a(NoveltySettings{}, space);
  EXPECT_THROW((void)a.scores(Points{{0.5, 0.5}}), std::invalid_argument);
  EXPECT_THROW((void)a.scores(Points{{std::nan("")}}), std::invalid_argument);
}

// Novelty search as an optimizer on a toy behavior space: the descriptor is the first two
// genes mapped to [0, 1], the fitness rewards one corner only. Searching for novelty fills
// the space and its archive grows; searching for the fitness alone (NSGA-II on one
// objective) crowds into the corner.
TEST(NoveltySearch, SpreadsOverTheBehaviorSpaceWhereTheFitnessCrowdsIntoACorner) {
  const auto cells_reached = [](const std::string& algorithm) {
    NoveltyRunSettings s;
    s.population = 20;
    Problem p;
    p.genome_size = 4;
    p.seed = 3;
    p.objectives = {{-2, 0}};
    p.descriptors = {{0, 1}, {0, 1}};
    std::unique_ptr<Optimizer> o;
    if (algorithm == "novelty") {
      o = make_novelty(s, p);
    } else {
      Nsga2Settings n;
      n.population = 20;
      o = make_nsga2(n, p);
    }
    std::vector<bool> seen(100, false);
    for (int g = 0; g < 30; ++g) {
      const std::vector<Genome> asked = o->ask(g);
      std::vector<Outcome> outcomes;
      for (const Genome& x : asked) {
        const double a = (x[0] + 1) / 2, b = (x[1] + 1) / 2;
        outcomes.push_back({{-std::hypot(a, b)}, {a, b}});
        seen[static_cast<std::size_t>(std::min(9.0, a * 10) * 10 + std::min(9.0, b * 10))] = true;
      }
      o->tell(outcomes);
    }
    if (algorithm == "novelty") {
      EXPECT_GT(o->metrics().front().value, 0.0) << "the archive grew";
    }
    return std::count(seen.begin(), seen.end(), true);
  };
  const auto novelty = cells_reached("novelty"), fitness = cells_reached("fitness");
  EXPECT_GT(novelty, 60) << "of 100 cells";
  EXPECT_GT(novelty, fitness + 10) << "fitness alone reached " << fitness;
}

}  // namespace
}  // namespace esc::evo::qd
