#include "runtime/evo/test_functions.hpp"

#include <Eigen/QR>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace esc::evo {

double sphere(std::span<const double> x) {
  double s = 0.0;
  for (const double v : x) s += v * v;
  return s;
}

double rosenbrock(std::span<const double> x) {
  double s = 0.0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double a = x[i] * x[i] - x[i + 1];
    const double b = x[i] - 1.0;
    s += 100.0 * a * a + b * b;
  }
  return s;
}

double rastrigin(std::span<const double> x) {
  double s = 10.0 * static_cast<double>(x.size());
  for (const double v : x) s += v * v - 10.0 * std::cos(2.0 * std::numbers::pi * v);
  return s;
}

RotatedEllipsoid::RotatedEllipsoid(std::size_t n, Rng& rng) : n_(n), rotation_(n * n), scale_(n, 1.0) {
  const auto size = static_cast<Eigen::Index>(n);
  Eigen::MatrixXd g(size, size);
  for (Eigen::Index j = 0; j < size; ++j)
    for (Eigen::Index i = 0; i < size; ++i) g(i, j) = rng.normal();
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(g);
  Eigen::MatrixXd q = qr.householderQ();
  // Householder QR leaves the signs of R's diagonal arbitrary; fixing them makes Q Haar.
  const Eigen::MatrixXd r = qr.matrixQR().triangularView<Eigen::Upper>();
  for (Eigen::Index j = 0; j < size; ++j)
    if (r(j, j) < 0.0) q.col(j) *= -1.0;
  for (Eigen::Index i = 0; i < size; ++i)
    for (Eigen::Index j = 0; j < size; ++j) rotation_[static_cast<std::size_t>(i * size + j)] = q(i, j);
  for (std::size_t i = 0; n > 1 && i < n; ++i)
    scale_[i] = std::pow(10.0, 6.0 * static_cast<double>(i) / static_cast<double>(n - 1));
}

double RotatedEllipsoid::operator()(std::span<const double> x) const {
  double s = 0.0;
  for (std::size_t i = 0; i < n_; ++i) {
    double y = 0.0;
    for (std::size_t j = 0; j < n_; ++j) y += rotation_[i * n_ + j] * x[j];
    s += scale_[i] * y * y;
  }
  return s;
}

const std::vector<std::string>& test_function_names() {
  static const std::vector<std::string> names{"sphere", "ellipsoid", "rosenbrock", "rastrigin"};
  return names;
}

Objective test_function(std::string_view name, std::size_t n, std::uint64_t seed) {
  if (name == "sphere") return sphere;
  if (name == "rosenbrock") return rosenbrock;
  if (name == "rastrigin") return rastrigin;
  if (name == "ellipsoid") {
    Rng rng(seed, {kTestProblemStream});
    return RotatedEllipsoid(n, rng);
  }
  std::string known;
  for (const std::string& k : test_function_names()) known += (known.empty() ? "" : ", ") + k;
  throw std::invalid_argument("unknown test function '" + std::string(name) + "' (known: " + known + ")");
}

MinimiseResult minimise(const CmaesSettings& settings, std::size_t n, const Objective& f, std::uint64_t seed,
                        double target, std::uint64_t max_evals) {
  Cmaes cma(settings, n);
  Rng init(seed, {static_cast<std::uint64_t>(Stream::Init)});
  cma.start(init);
  MinimiseResult result;
  result.best_f = std::numeric_limits<double>::infinity();
  const auto finish = [&]() {
    result.restarts = cma.restarts();
    result.lambda = cma.lambda();
    return result;
  };
  while (!cma.done()) {
    Rng rng(seed, {static_cast<std::uint64_t>(Stream::Breed), cma.generation()});
    const std::vector<std::vector<double>> candidates = cma.ask(rng);
    std::vector<double> values(candidates.size());
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      if (result.evaluations == max_evals) return finish();
      values[k] = f(candidates[k]);
      ++result.evaluations;
      result.best_f = std::min(result.best_f, values[k]);
      if (values[k] < target) {
        result.evaluations_to_target = result.evaluations;
        return finish();
      }
    }
    cma.tell(values);
  }
  result.stopped = cma.stop_reason();
  return finish();
}

namespace {

// ZDT's f1 and g.
std::array<double, 2> zdt_parts(std::span<const double> x) {
  if (x.size() < 2)
    throw std::invalid_argument("the ZDT functions need at least 2 variables, got " + std::to_string(x.size()));
  double sum = 0.0;
  for (std::size_t i = 1; i < x.size(); ++i) sum += x[i];
  return {x[0], 1.0 + 9.0 * sum / static_cast<double>(x.size() - 1)};
}

}  // namespace

std::array<double, 2> zdt1(std::span<const double> x) {
  const auto [f1, g] = zdt_parts(x);
  return {f1, g * (1.0 - std::sqrt(f1 / g))};
}

std::array<double, 2> zdt2(std::span<const double> x) {
  const auto [f1, g] = zdt_parts(x);
  return {f1, g * (1.0 - (f1 / g) * (f1 / g))};
}

std::array<double, 2> zdt3(std::span<const double> x) {
  const auto [f1, g] = zdt_parts(x);
  return {f1, g * (1.0 - std::sqrt(f1 / g) - f1 / g * std::sin(10.0 * std::numbers::pi * f1))};
}

const std::vector<std::string>& multi_objective_function_names() {
  static const std::vector<std::string> names{"zdt1", "zdt2", "zdt3"};
  return names;
}

MultiObjective multi_objective_function(std::string_view name) {
  const auto wrap = [](std::array<double, 2> (*f)(std::span<const double>)) -> MultiObjective {
    return [f](std::span<const double> x) {
      const auto v = f(x);
      return std::vector<double>(v.begin(), v.end());
    };
  };
  if (name == "zdt1") return wrap(zdt1);
  if (name == "zdt2") return wrap(zdt2);
  if (name == "zdt3") return wrap(zdt3);
  std::string known;
  for (const std::string& k : multi_objective_function_names()) known += (known.empty() ? "" : ", ") + k;
  throw std::invalid_argument("unknown multi-objective function '" + std::string(name) + "' (known: " + known + ")");
}

Nsga2 nsga2_run(const Nsga2Settings& settings, std::size_t n, const MultiObjective& f, std::uint64_t seed,
                std::uint64_t generations) {
  Nsga2 nsga(settings, n);
  Rng init(seed, {static_cast<std::uint64_t>(Stream::Init)});
  nsga.start(init);
  for (std::uint64_t g = 0; g < generations; ++g) {
    Rng rng(seed, {static_cast<std::uint64_t>(Stream::Breed), g});
    const std::vector<std::vector<double>> candidates = nsga.ask(rng);
    std::vector<std::vector<double>> values;
    values.reserve(candidates.size());
    for (const auto& x : candidates) values.push_back(f(x));
    nsga.tell(values);
  }
  return nsga;
}

}  // namespace esc::evo
