#pragma once
// Test functions of the CMA-ES literature, minimised, and a driver that runs esc's CMA-ES on
// one: what esc-testfn, tests/evo/cmaes_test.cpp and scripts/validate-cmaes.py measure. The
// ZDT functions, two objectives, and a driver that runs NSGA-II on one, do the same for
// tests/evo/nsga2_test.cpp and scripts/validate-nsga2.py.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/cmaes/cmaes.hpp"
#include "runtime/evo/nsga2/nsga2.hpp"

namespace esc::evo {

using Objective = std::function<double(std::span<const double>)>;

double sphere(std::span<const double> x);
// 100 (x_i^2 - x_{i+1})^2 + (x_i - 1)^2 summed; minimum 0 at (1, ..., 1).
double rosenbrock(std::span<const double> x);
// 10 n + sum x_i^2 - 10 cos(2 pi x_i); minimum 0 at 0, a local one near every integer point.
double rastrigin(std::span<const double> x);

// sum 10^(6 (i-1)/(n-1)) y_i^2 with y = R x, R a random rotation: condition 1e6, no axis
// aligned with the coordinates. R is Q of the QR factorisation of a matrix of standard
// normals from `rng` (columns signed so that R is uniformly distributed).
class RotatedEllipsoid {
 public:
  RotatedEllipsoid(std::size_t n, Rng& rng);
  double operator()(std::span<const double> x) const;

 private:
  std::size_t n_;
  std::vector<double> rotation_;  // row-major n x n
  std::vector<double> scale_;
};

// The functions by name ("sphere", "ellipsoid", "rosenbrock", "rastrigin"); the ellipsoid's
// rotation is drawn from Rng(seed, {kTestProblemStream}). Throws std::invalid_argument
// listing the names.
inline constexpr std::uint64_t kTestProblemStream = 1000;  // apart from rng.hpp's Streams
Objective test_function(std::string_view name, std::size_t n, std::uint64_t seed);
const std::vector<std::string>& test_function_names();

struct MinimiseResult {
  std::optional<std::uint64_t> evaluations_to_target;  // counting the one that got below
  double best_f = 0.0;
  std::uint64_t evaluations = 0;
  int restarts = 0;
  std::size_t lambda = 0;   // the last population size
  std::string stopped;      // the stop that ended the search, empty for target or budget
};

// Ask-tell loop from `seed` as esc runs it: the start from Rng(seed, {Stream::Init}),
// generation g's candidates from Rng(seed, {Stream::Breed, g}). Evaluates candidates in
// order and ends at the first below `target`, after `max_evals`, or when the search stops.
MinimiseResult minimise(const CmaesSettings& settings, std::size_t n, const Objective& f, std::uint64_t seed,
                        double target, std::uint64_t max_evals);

// ZDT1-3 (Zitzler, Deb & Thiele, Evolutionary Computation 8(2), 2000), both objectives
// minimised, x in [0, 1]^n, n >= 2 (std::invalid_argument otherwise): f1 = x_1,
// g = 1 + 9 (x_2 + ... + x_n) / (n - 1) and f2 = g h(f1, g). The optimal fronts have g = 1
// (x_2 = ... = x_n = 0).
// ZDT1: h = 1 - sqrt(f1 / g), a convex front.
std::array<double, 2> zdt1(std::span<const double> x);
// ZDT2: h = 1 - (f1 / g)^2, a concave front.
std::array<double, 2> zdt2(std::span<const double> x);
// ZDT3: h = 1 - sqrt(f1 / g) - (f1 / g) sin(10 pi f1), a front in five disconnected pieces.
std::array<double, 2> zdt3(std::span<const double> x);

using MultiObjective = std::function<std::vector<double>(std::span<const double>)>;

// The multi-objective functions by name ("zdt1", "zdt2", "zdt3"); std::invalid_argument
// listing the names for another.
MultiObjective multi_objective_function(std::string_view name);
const std::vector<std::string>& multi_objective_function_names();

// NSGA-II on f from `seed` as esc runs an optimizer: the first population from
// Rng(seed, {Stream::Init}), generation g's children from Rng(seed, {Stream::Breed, g}).
// `generations` tells, the first of the initial population, so generations x N evaluations
// (DEAP's NGEN counts alike). Returns the optimizer after the last tell.
Nsga2 nsga2_run(const Nsga2Settings& settings, std::size_t n, const MultiObjective& f, std::uint64_t seed,
                std::uint64_t generations);

}  // namespace esc::evo
