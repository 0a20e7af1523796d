#include "runtime/evo/cmaes/cmaes.hpp"
#include "runtime/evo/cmaes/cmaes_optimizer.hpp"

#include <cmath>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/evo/test_functions.hpp"

namespace esc::evo {
namespace {

// The box and step size of scripts/validate-cmaes.py, so the thresholds below come from its
// table (docs/optimizers.md): 1.5 times DEAP's median at n = 10, 1,446 evaluations on the
// sphere and 5,813 on the rotated ellipsoid.
CmaesSettings literature() {
  CmaesSettings s;
  s.lower = -5.0;
  s.upper = 5.0;
  s.sigma = 0.2;
  return s;
}

Rng generation_rng(std::uint64_t seed, std::uint64_t g) {
  return Rng(seed, {static_cast<std::uint64_t>(Stream::Breed), g});
}

std::vector<double> values_of(const std::vector<std::vector<double>>& xs, const Objective& f) {
  std::vector<double> v;
  for (const auto& x : xs) v.push_back(f(x));
  return v;
}

TEST(Cmaes, DefaultLambdaIsFourPlusThreeLnN) {
  for (const auto& [n, lambda] : std::vector<std::pair<std::size_t, std::size_t>>{{1, 4}, {2, 6}, {10, 10}, {40, 15}, {100, 17}}) {
    const Cmaes cma(CmaesSettings{}, n);
    EXPECT_EQ(cma.lambda(), lambda) << "n = " << n;
    EXPECT_EQ(cma.mu(), lambda / 2) << "n = " << n;
  }
}

TEST(Cmaes, SphereReachesTargetWithinTheValidatedBudget) {
  for (const std::uint64_t seed : {1, 2, 3}) {
    const MinimiseResult r = minimise(literature(), 10, sphere, seed, 1e-8, 100000);
    ASSERT_TRUE(r.evaluations_to_target.has_value()) << "seed " << seed << ": best " << r.best_f;
    EXPECT_LE(*r.evaluations_to_target, 2170u) << "seed " << seed;
  }
}

TEST(Cmaes, RotatedEllipsoidReachesTargetWithinTheValidatedBudget) {
  for (const std::uint64_t seed : {1, 2, 3}) {
    const MinimiseResult r = minimise(literature(), 10, test_function("ellipsoid", 10, seed), seed, 1e-8, 100000);
    ASSERT_TRUE(r.evaluations_to_target.has_value()) << "seed " << seed << ": best " << r.best_f;
    EXPECT_LE(*r.evaluations_to_target, 8720u) << "seed " << seed;
  }
}

TEST(Cmaes, SeparableConvergesOnTheAxisParallelEllipsoid) {
  const auto ellipsoid = [](std::span<const double> x) {
    double s = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) s += std::pow(10.0, 6.0 * static_cast<double>(i) / 9.0) * x[i] * x[i];
    return s;
  };
  CmaesSettings s = literature();
  s.separable = true;
  const MinimiseResult sep = minimise(s, 10, ellipsoid, 7, 1e-8, 100000);
  ASSERT_TRUE(sep.evaluations_to_target.has_value()) << "best " << sep.best_f;
  // Learning n variances instead of n (n + 1) / 2 covariances is what sep-CMA-ES is for.
  s.separable = false;
  const MinimiseResult full = minimise(s, 10, ellipsoid, 7, 1e-8, 100000);
  ASSERT_TRUE(full.evaluations_to_target.has_value());
  EXPECT_LT(*sep.evaluations_to_target, *full.evaluations_to_target);
}

TEST(Cmaes, CandidatesStayInBoundsAndReachTheCornerNearestAnOptimumOutside) {
  const auto shifted = [](std::span<const double> x) {
    double s = 0.0;
    for (const double v : x) s += (v - 2.0) * (v - 2.0);
    return s;
  };
  CmaesSettings s;  // [-1, 1], the optimum at (2, ..., 2)
  s.sigma = 0.5;
  Cmaes cma(s, 5);
  Rng init(3);
  cma.start(init);
  for (std::uint64_t g = 0; g < 400 && !cma.done(); ++g) {
    Rng rng = generation_rng(3, g);
    const auto xs = cma.ask(rng);
    for (const auto& x : xs)
      for (const double v : x) {
        ASSERT_GE(v, -1.0);
        ASSERT_LE(v, 1.0);
      }
    cma.tell(values_of(xs, shifted));
  }
  for (const double m : cma.mean()) EXPECT_NEAR(m, 1.0, 1e-6);
}

TEST(Cmaes, HugeStepsStillLandInBounds) {
  CmaesSettings s;
  s.lower = 0.0;
  s.upper = 0.001;
  s.sigma = 1000.0;
  Cmaes cma(s, 3);
  Rng init(1);
  cma.start(init);
  for (std::uint64_t g = 0; g < 20; ++g) {
    Rng rng = generation_rng(1, g);
    const auto xs = cma.ask(rng);
    for (const auto& x : xs)
      for (const double v : x) {
        ASSERT_GE(v, 0.0);
        ASSERT_LE(v, 0.001);
      }
    cma.tell(values_of(xs, rastrigin));
  }
}

TEST(Cmaes, GivenStartPointIsTheFirstCandidateUnchanged) {
  Cmaes cma(CmaesSettings{}, 4);
  const std::vector<double> start{-1.0, 0.999, 0.25, 1.0};
  cma.start(start);
  Cmaes resumed(CmaesSettings{}, 4);
  resumed.load(cma.save());  // a run killed before its first generation
  Rng rng = generation_rng(1, 0), same = generation_rng(1, 0);
  const auto xs = cma.ask(rng);
  EXPECT_EQ(xs[0], start);
  EXPECT_NE(xs[1], start);
  EXPECT_EQ(resumed.ask(same), xs);
  EXPECT_THROW(cma.start(std::vector<double>{0.0, 0.0, 0.0, 1.5}), std::invalid_argument);
  EXPECT_THROW(cma.start(std::vector<double>{0.0}), std::invalid_argument);
}

// A run that saves its state after every tell and continues in a fresh object asks for
// exactly the candidates of one that never stops; returns the one that never stopped.
Cmaes expect_resume_identical(const CmaesSettings& s, std::size_t n, const Objective& f, std::uint64_t generations) {
  Cmaes straight(s, n);
  Cmaes resumed(s, n);
  Rng a(5), b(5);
  straight.start(a);
  resumed.start(b);
  for (std::uint64_t g = 0; g < generations && !straight.done(); ++g) {
    Rng ra = generation_rng(5, g), rb = generation_rng(5, g);
    const auto xs = straight.ask(ra);
    const auto ys = resumed.ask(rb);
    EXPECT_EQ(xs, ys) << "generation " << g;  // bit for bit
    if (xs != ys) break;
    straight.tell(values_of(xs, f));
    resumed.tell(values_of(ys, f));
    Cmaes fresh(s, n);
    fresh.load(resumed.save());
    resumed = fresh;
  }
  EXPECT_EQ(resumed.done(), straight.done());
  EXPECT_EQ(resumed.restarts(), straight.restarts());
  EXPECT_EQ(resumed.save(), straight.save());
  return straight;
}

TEST(Cmaes, SaveLoadContinuesBitIdentically) {
  CmaesSettings s;
  s.restarts = 2;
  s.stop_sigma = 1e-3;  // both restarts and the end within the 2000 generations
  for (const bool separable : {false, true}) {
    s.separable = separable;
    const Cmaes straight = expect_resume_identical(s, 6, rastrigin, 2000);
    EXPECT_TRUE(straight.done());
    EXPECT_EQ(straight.restarts(), 2);
  }
  // At n = 200 the eigendecomposition lags C by two generations: the state holds when.
  const Cmaes lazy = expect_resume_identical(CmaesSettings{}, 200, rastrigin, 12);
  EXPECT_EQ(lazy.generation(), 12u);
}

TEST(Cmaes, LoadRefusesAnotherDimensionOrGarbage) {
  Cmaes five(CmaesSettings{}, 5);
  Rng rng(1);
  five.start(rng);
  const StateBytes state = five.save();
  Cmaes six(CmaesSettings{}, 6);
  try {
    six.load(state);
    FAIL() << "loaded a state of n = 5 into n = 6";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("n = 5"), std::string::npos) << e.what();
  }
  CmaesSettings sep;
  sep.separable = true;
  Cmaes other(sep, 5);
  EXPECT_THROW(other.load(state), std::invalid_argument);
  EXPECT_THROW(five.load(StateBytes(state.begin(), state.end() - 3)), std::invalid_argument);
  StateBytes longer = state;
  longer.push_back(0);
  EXPECT_THROW(five.load(longer), std::invalid_argument);
  StateBytes garbage(200);
  for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<std::uint8_t>(i * 37 + 11);
  EXPECT_THROW(five.load(garbage), std::invalid_argument);
  EXPECT_THROW(five.load(StateBytes{}), std::invalid_argument);
  // A refused blob leaves the optimizer as it was.
  EXPECT_EQ(five.save(), state);
}

void run_until_done(Cmaes& cma, const Objective& f, std::uint64_t max_generations) {
  Rng init(9);
  cma.start(init);
  for (std::uint64_t g = 0; g < max_generations && !cma.done(); ++g) {
    Rng rng = generation_rng(9, g);
    cma.tell(values_of(cma.ask(rng), f));
  }
}

TEST(Cmaes, SigmaStopEndsTheSearch) {
  CmaesSettings s;
  s.stop_sigma = 1e-6;
  Cmaes cma(s, 5);
  run_until_done(cma, sphere, 2000);
  ASSERT_TRUE(cma.done());
  EXPECT_EQ(cma.stop_reason(), "stop_sigma");
  Rng rng(1);
  EXPECT_THROW((void)cma.ask(rng), std::logic_error);
}

TEST(Cmaes, ConditionStopEndsTheSearch) {
  CmaesSettings s = literature();
  s.stop_condition = 1e3;
  Cmaes cma(s, 10);
  run_until_done(cma, test_function("ellipsoid", 10, 1), 5000);
  ASSERT_TRUE(cma.done());
  EXPECT_EQ(cma.stop_reason(), "stop_condition");
  EXPECT_GT(cma.condition(), 1e3);
}

TEST(Cmaes, FlatFitnessStopEndsTheSearch) {
  CmaesSettings s;
  s.stop_flat = 4;
  Cmaes cma(s, 3);
  run_until_done(cma, [](std::span<const double>) { return 1.0; }, 100);
  ASSERT_TRUE(cma.done());
  EXPECT_EQ(cma.stop_reason(), "stop_flat");
  EXPECT_EQ(cma.generation(), 4u);
}

TEST(Cmaes, IpopDoublesThePopulationOnEachRestart) {
  CmaesSettings s;
  s.restarts = 2;
  s.stop_flat = 1;
  Cmaes cma(s, 10);
  Rng init(2);
  cma.start(init);
  const auto flat = [](std::span<const double>) { return 0.0; };
  for (const std::size_t lambda : {10u, 20u, 40u}) {
    ASSERT_FALSE(cma.done());
    EXPECT_EQ(cma.lambda(), lambda);
    EXPECT_EQ(cma.mu(), lambda / 2);
    Rng rng = generation_rng(2, cma.generation());
    const auto xs = cma.ask(rng);
    ASSERT_EQ(xs.size(), lambda);
    cma.tell(values_of(xs, flat));
  }
  EXPECT_TRUE(cma.done());
  EXPECT_EQ(cma.restarts(), 2);
  EXPECT_EQ(cma.evaluations(), 70u);
}

TEST(Cmaes, IpopSolvesRastriginWherePlainRunsStop) {
  CmaesSettings s = literature();
  const MinimiseResult plain = minimise(s, 5, rastrigin, 4, 1e-8, 200000);
  s.restarts = 9;
  const MinimiseResult ipop = minimise(s, 5, rastrigin, 4, 1e-8, 200000);
  EXPECT_FALSE(plain.evaluations_to_target.has_value());
  EXPECT_FALSE(plain.stopped.empty());
  ASSERT_TRUE(ipop.evaluations_to_target.has_value()) << "best " << ipop.best_f;
  EXPECT_GT(ipop.restarts, 0);
}

TEST(Cmaes, SameSeedSameRunOtherSeedOtherRun) {
  const Objective f = test_function("rosenbrock", 8, 0);
  const MinimiseResult a = minimise(literature(), 8, f, 11, 1e-8, 20000);
  const MinimiseResult b = minimise(literature(), 8, f, 11, 1e-8, 20000);
  const MinimiseResult c = minimise(literature(), 8, f, 12, 1e-8, 20000);
  EXPECT_EQ(a.evaluations, b.evaluations);
  EXPECT_EQ(a.best_f, b.best_f);
  EXPECT_NE(a.best_f, c.best_f);
}

TEST(Cmaes, TellNeedsOneValuePerCandidateOfAPendingAsk) {
  Cmaes cma(CmaesSettings{}, 3);
  Rng rng(1);
  EXPECT_THROW((void)cma.ask(rng), std::logic_error);  // not started
  cma.start(rng);
  EXPECT_THROW(cma.tell(std::vector<double>(cma.lambda())), std::logic_error);
  const auto xs = cma.ask(rng);
  EXPECT_THROW(cma.tell(std::vector<double>(xs.size() - 1)), std::invalid_argument);
}

TEST(Cmaes, InvalidSettingsThrowNamingTheSetting) {
  const std::vector<std::pair<std::function<void(CmaesSettings&)>, std::string>> cases{
      {[](CmaesSettings& s) { s.lambda = 1; }, "lambda"},
      {[](CmaesSettings& s) { s.lambda = -3; }, "lambda"},
      {[](CmaesSettings& s) { s.mu = 6; }, "mu"},  // lambda is 10 for n = 10
      {[](CmaesSettings& s) { s.mu = -1; }, "mu"},
      {[](CmaesSettings& s) { s.sigma = 0.0; }, "sigma"},
      {[](CmaesSettings& s) { s.sigma = std::nan(""); }, "sigma"},
      {[](CmaesSettings& s) { s.lower = 1.0; }, "lower"},
      {[](CmaesSettings& s) { s.upper = 2e6; }, "upper"},
      {[](CmaesSettings& s) { s.restarts = -1; }, "restarts"},
      {[](CmaesSettings& s) { s.restarts = 21; }, "restarts"},
      {[](CmaesSettings& s) { s.stop_sigma = 1.0; }, "stop_sigma"},
      {[](CmaesSettings& s) { s.stop_condition = 1.0; }, "stop_condition"},
      {[](CmaesSettings& s) { s.stop_condition = 1e17; }, "stop_condition"},
      {[](CmaesSettings& s) { s.stop_flat = -1; }, "stop_flat"},
  };
  for (const auto& [change, name] : cases) {
    CmaesSettings s;
    change(s);
    try {
      const Cmaes cma(s, 10);
      ADD_FAILURE() << name << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(Cmaes(CmaesSettings{}, 0), std::invalid_argument);
}

TEST(Cmaes, MemoryPeakCountsIpopsLargestPopulation) {
  CmaesSettings s;
  s.lambda = 1000;
  const MemoryPeak none = cmaes_memory_peak(s, 18);
  EXPECT_EQ(none.candidates, 1000);
  EXPECT_EQ(none.setting, "cmaes.lambda");
  s.restarts = 9;
  const MemoryPeak ipop = cmaes_memory_peak(s, 18);
  EXPECT_EQ(ipop.candidates, 1000.0 * 512);
  EXPECT_GT(ipop.bytes, 500 * none.bytes) << "lambda x 2^restarts candidates, each of 18 weights";
  EXPECT_EQ(ipop.setting, "cmaes.restarts");
  EXPECT_NE(ipop.what.find("512000 candidates of 18 weights after 9 IPOP restarts"), std::string::npos) << ipop.what;
  // 2,000 weights: the covariance and its eigenvectors outweigh a small population.
  s = CmaesSettings{};
  EXPECT_EQ(cmaes_memory_peak(s, 2000).setting, "cmaes.covariance");
}

}  // namespace
}  // namespace esc::evo
