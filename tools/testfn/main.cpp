// esc-testfn: esc's CMA-ES on one test function of the literature, one JSON line per run,
// for scripts/validate-cmaes.py. The box is [-5, 5] unless told (the usual domain of these
// functions), sigma a fraction of its width as in CmaesSettings.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <exception>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "runtime/evo/test_functions.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Runs esc's CMA-ES on a test function; prints one JSON line"};
  std::string function;
  std::size_t n = 10;
  std::uint64_t seed = 1;
  double target = 1e-8;
  double max_evals = 1e6;
  esc::evo::CmaesSettings s;
  s.lower = -5.0;
  s.upper = 5.0;
  app.add_option("--function", function, "sphere, ellipsoid, rosenbrock or rastrigin")->required();
  app.add_option("--n", n, "dimension")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "seed of the start, the samples and the ellipsoid's rotation");
  app.add_option("--target", target, "stop at the first evaluation below this value");
  app.add_option("--max-evals", max_evals, "evaluation budget")->check(CLI::PositiveNumber);
  app.add_option("--lambda", s.lambda, "population size (0: 4 + floor(3 ln n))");
  app.add_option("--sigma", s.sigma, "initial step size, a fraction of upper - lower");
  app.add_option("--lower", s.lower, "lower bound of every coordinate");
  app.add_option("--upper", s.upper, "upper bound of every coordinate");
  app.add_option("--ipop", s.restarts, "IPOP restarts at most (population doubled each)");
  app.add_flag("--separable", s.separable, "sep-CMA-ES: diagonal covariance");
  CLI11_PARSE(app, argc, argv);

  try {
    const esc::evo::Objective f = esc::evo::test_function(function, n, seed);
    const auto r = esc::evo::minimise(s, n, f, seed, target, static_cast<std::uint64_t>(max_evals));
    nlohmann::json line{{"function", function},
                        {"n", n},
                        {"seed", seed},
                        {"separable", s.separable},
                        {"ipop", s.restarts},
                        {"evaluations_to_target", nullptr},
                        {"final_f", r.best_f},
                        {"evaluations", r.evaluations},
                        {"restarts", r.restarts},
                        {"lambda", r.lambda},
                        {"stopped", r.stopped}};
    if (r.evaluations_to_target) line["evaluations_to_target"] = *r.evaluations_to_target;
    std::cout << line.dump() << '\n';
  } catch (const std::exception& e) {
    std::cerr << "esc-testfn: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
