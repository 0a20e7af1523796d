// esc-testfn: esc's optimizers on test functions of the literature, for the validation
// scripts. Three modes:
//   esc-testfn --function NAME ...        CMA-ES on a single-objective function, one JSON line
//                                          per run (scripts/validate-cmaes.py); the box is
//                                          [-5, 5] unless told, sigma a fraction of its width.
//   esc-testfn nsga2 --function zdtK ...  NSGA-II on a ZDT function in [0, 1]^n: the final
//                                          population's objectives, one line per point, then
//                                          "hypervolume V" for the reference (11, 11)
//                                          (scripts/validate-nsga2.py).
//   esc-testfn hypervolume --reference R... the hypervolume of the points read from standard
//                                          input (one per line), for the script's cross-check
//                                          against DEAP's.
//   esc-testfn neat-xor --runs N ...       NEAT on the paper's XOR (docs/neat-xor.md): one
//                                          JSON line per run (seeds first-seed, +1, ...),
//                                          then one with the summary.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <algorithm>
#include <any>
#include <cmath>
#include <exception>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "runtime/evo/neat/neat_options.hpp"
#include "runtime/evo/neat/xor.hpp"
#include "runtime/evo/pareto/hypervolume.hpp"
#include "runtime/evo/test_functions.hpp"

namespace {

// The reference point of DEAP's examples/ga/nsga2.py for ZDT1-3.
constexpr double kZdtReference = 11.0;

int run_cmaes(const std::string& function, std::size_t n, std::uint64_t seed, double target, double max_evals,
              const esc::evo::CmaesSettings& s) {
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
  return 0;
}

int run_nsga2(const std::string& function, std::size_t n, std::uint64_t seed, std::uint64_t generations,
              const esc::evo::Nsga2Settings& s) {
  const esc::evo::Nsga2 nsga = esc::evo::nsga2_run(s, n, esc::evo::multi_objective_function(function), seed, generations);
  for (const auto& f : nsga.objectives()) {
    for (std::size_t k = 0; k < f.size(); ++k) std::printf(k == 0 ? "%.17g" : " %.17g", f[k]);
    std::printf("\n");
  }
  const std::vector<double> reference(2, kZdtReference);
  std::printf("hypervolume %.17g\n", esc::evo::hypervolume(nsga.objectives(), reference));
  return 0;
}

int run_hypervolume(const std::vector<double>& reference) {
  esc::evo::ObjectiveRows points;
  std::string line;
  while (std::getline(std::cin, line)) {
    std::istringstream in(line);
    std::vector<double> p;
    for (double v = 0.0; in >> v;) p.push_back(v);
    if (!in.eof()) throw std::invalid_argument("not a number in the line '" + line + "'");
    if (!p.empty()) points.push_back(std::move(p));
  }
  std::printf("%.17g\n", esc::evo::hypervolume(points, reference));
  return 0;
}

// Mean and sample standard deviation.
std::pair<double, double> mean_sd(const std::vector<double>& v) {
  if (v.empty()) return {0.0, 0.0};
  double sum = 0.0;
  for (const double x : v) sum += x;
  const double mean = sum / static_cast<double>(v.size());
  double sq = 0.0;
  for (const double x : v) sq += (x - mean) * (x - mean);
  return {mean, v.size() > 1 ? std::sqrt(sq / static_cast<double>(v.size() - 1)) : 0.0};
}

// NEAT's settings from `KEY=VALUE` texts, through the option table: the keys, ranges and
// words a script will use.
esc::evo::NeatSettings neat_settings(const std::vector<std::string>& sets) {
  std::any settings = esc::evo::NeatSettings{};
  for (const std::string& set : sets) {
    const auto eq = set.find('=');
    const std::string key = set.substr(0, eq);
    const auto& rows = esc::evo::neat_options();
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& o) { return o.key == key; });
    if (eq == std::string::npos || row == rows.end())
      throw std::invalid_argument("--set '" + set + "': not KEY=VALUE with a NEAT option's key");
    const std::string value = set.substr(eq + 1);
    esc::evo::OptionValue v;
    if (row->form == esc::evo::OptionForm::Word) {
      const auto w = std::find(row->words.begin(), row->words.end(), value);
      if (w == row->words.end())
        throw std::invalid_argument("--set " + key + ": '" + value + "' is not one of its words");
      v.word = static_cast<std::size_t>(w - row->words.begin());
    } else {
      std::size_t used = 0;
      try {
        v.number = std::stod(value, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != value.size())
        throw std::invalid_argument("--set " + key + ": '" + value + "' is not a number");
    }
    if (const esc::evo::OptionRefusal why = row->set(settings, v); !why.empty())
      throw std::invalid_argument("--set " + key + " " + why.message);
  }
  return std::any_cast<esc::evo::NeatSettings>(settings);
}

int run_neat_xor(int runs, std::uint64_t first_seed, int generations, const esc::evo::NeatSettings& s) {
  std::vector<double> evaluations, generations_used, hidden, links;
  double worst = 0.0;
  for (int r = 0; r < runs; ++r) {
    const auto run = esc::evo::solve_xor(s, first_seed + static_cast<std::uint64_t>(r), generations);
    nlohmann::json line{{"seed", run.seed},       {"solved", run.solved},
                        {"generations", run.generations}, {"evaluations", run.evaluations},
                        {"hidden_nodes", nullptr}, {"enabled_links", nullptr}};
    if (run.solved) {
      line["hidden_nodes"] = run.hidden_nodes;
      line["enabled_links"] = run.enabled_links;
      evaluations.push_back(static_cast<double>(run.evaluations));
      generations_used.push_back(run.generations);
      hidden.push_back(static_cast<double>(run.hidden_nodes));
      links.push_back(static_cast<double>(run.enabled_links));
      worst = std::max(worst, static_cast<double>(run.evaluations));
    }
    std::cout << line.dump() << std::endl;
  }
  const auto [e_mean, e_sd] = mean_sd(evaluations);
  const auto [g_mean, g_sd] = mean_sd(generations_used);
  const auto [h_mean, h_sd] = mean_sd(hidden);
  const auto [l_mean, l_sd] = mean_sd(links);
  nlohmann::json summary{{"runs", runs},           {"solved", evaluations.size()}, {"evaluations_mean", e_mean},
                         {"evaluations_sd", e_sd}, {"evaluations_worst", worst},  {"generations_mean", g_mean},
                         {"generations_sd", g_sd}, {"hidden_nodes_mean", h_mean}, {"hidden_nodes_sd", h_sd},
                         {"enabled_links_mean", l_mean}, {"enabled_links_sd", l_sd}};
  std::cout << summary.dump() << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Runs esc's optimizers on test functions (CMA-ES, or the subcommands nsga2 and hypervolume)"};
  std::string function;
  std::size_t n = 10;
  std::uint64_t seed = 1;
  double target = 1e-8;
  double max_evals = 1e6;
  esc::evo::CmaesSettings s;
  s.lower = -5.0;
  s.upper = 5.0;
  app.add_option("--function", function, "sphere, ellipsoid, rosenbrock or rastrigin");
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

  CLI::App* nsga2 = app.add_subcommand("nsga2", "NSGA-II on a ZDT function; prints the final population's objectives "
                                                "and its hypervolume for the reference (11, 11)");
  std::string zdt;
  std::size_t zdt_n = 30;
  std::uint64_t zdt_seed = 1;
  std::uint64_t generations = 250;
  esc::evo::Nsga2Settings ns;
  ns.lower = 0.0;
  ns.upper = 1.0;
  nsga2->add_option("--function", zdt, "zdt1, zdt2 or zdt3")->required();
  nsga2->add_option("--n", zdt_n, "number of variables, in [0, 1] each")->check(CLI::Range(2, 1'000'000));
  nsga2->add_option("--seed", zdt_seed, "seed of the first population and of every generation");
  nsga2->add_option("--population", ns.population, "N, even");
  nsga2->add_option("--generations", generations,
                    "generations evaluated, the first population included (N each; DEAP's NGEN)");
  nsga2->add_option("--crossover", ns.crossover, "probability that a pair of parents is crossed");
  nsga2->add_option("--eta-crossover", ns.eta_crossover, "SBX's distribution index");
  nsga2->add_option("--eta-mutation", ns.eta_mutation, "polynomial mutation's distribution index");
  nsga2->add_option("--mutation", ns.mutation, "probability that a gene mutates (0: 1 / n)");

  CLI::App* hv = app.add_subcommand("hypervolume", "the hypervolume (minimised objectives) of the points on standard "
                                                   "input, one per line");
  std::vector<double> reference;
  hv->add_option("--reference", reference, "the reference point, 2 or 3 numbers")->required();

  CLI::App* xor_cmd = app.add_subcommand("neat-xor", "NEAT on XOR with the paper's setup; one JSON line per run, then "
                                                    "the summary (solved runs, evaluations, hidden nodes, links)");
  int xor_runs = 100;
  std::uint64_t xor_seed = 1;
  int xor_generations = 100;
  xor_cmd->add_option("--runs", xor_runs, "independent runs")->check(CLI::Range(1, 1'000'000));
  xor_cmd->add_option("--first-seed", xor_seed, "seed of the first run; each next run the next seed");
  xor_cmd->add_option("--generations", xor_generations, "generations before a run counts as failed (NEAT C++: 100)")
      ->check(CLI::Range(1, 1'000'000));
  std::vector<std::string> xor_sets;
  xor_cmd->add_option("--set", xor_sets, "KEY=VALUE: a NEAT option as docs/neat.md lists them (population=300, "
                                          "activation=tanh, ...); repeatable");

  try {
    app.parse(argc, argv);
    if (app.get_subcommands().empty() && function.empty()) throw CLI::RequiredError("--function");
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  try {
    if (nsga2->parsed()) return run_nsga2(zdt, zdt_n, zdt_seed, generations, ns);
    if (hv->parsed()) return run_hypervolume(reference);
    if (xor_cmd->parsed()) return run_neat_xor(xor_runs, xor_seed, xor_generations, neat_settings(xor_sets));
    return run_cmaes(function, n, seed, target, max_evals, s);
  } catch (const std::exception& e) {
    std::cerr << "esc-testfn: " << e.what() << '\n';
    return 2;
  }
}
