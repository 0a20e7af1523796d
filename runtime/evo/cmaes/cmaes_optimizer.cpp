#include "runtime/evo/cmaes/cmaes_optimizer.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "runtime/evo/run_streams.hpp"

namespace esc::evo {

namespace {

class CmaesOptimizer final : public Optimizer {
 public:
  CmaesOptimizer(const CmaesSettings& settings, const Problem& problem)
      : cma_(settings, problem.genome_size), seed_(problem.seed) {
    start_core(cma_, problem);
  }

  std::vector<Genome> ask(int generation) override {
    Rng rng = breed_stream(seed_, generation);
    return cma_.ask(rng);
  }

  void tell(std::span<const Outcome> outcomes) override {
    std::vector<double> f(outcomes.size());
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = -outcomes[i].objectives.front();
    cma_.tell(f);
  }

  std::vector<Metric> metrics() const override {
    return {{"sigma", cma_.sigma()}, {"condition", cma_.condition()}, {"lambda", static_cast<double>(cma_.lambda())}};
  }

  std::string stopped() const override { return cma_.done() ? std::string(cma_.stop_reason()) : std::string(); }

  StateBytes save() const override { return cma_.save(); }
  void load(std::span<const std::uint8_t> state) override { cma_.load(state); }

 private:
  Cmaes cma_;
  std::uint64_t seed_;
};

}  // namespace

std::unique_ptr<Optimizer> make_cmaes(const CmaesSettings& settings, const Problem& problem) {
  if (problem.tree.primitives != nullptr) throw std::invalid_argument("CMA-ES evolves a network's weights, not trees");
  return std::make_unique<CmaesOptimizer>(settings, problem);
}

std::size_t cmaes_population(const CmaesSettings& settings, std::size_t n) {
  return settings.lambda > 0 ? static_cast<std::size_t>(settings.lambda) : cmaes_default_lambda(n);
}

MemoryPeak cmaes_memory_peak(const CmaesSettings& settings, std::size_t n) {
  const double d = static_cast<double>(n);
  const double lambda = std::ldexp(static_cast<double>(cmaes_population(settings, n)), settings.restarts);
  const double matrices = (settings.separable ? 2.0 * d : 4.0 * d * d) * sizeof(double);
  // z and y, the candidates handed out, their fitness and order.
  const double samples = (2.0 * d + 2.0) * lambda * sizeof(double) + rows_bytes(lambda, d);
  const double bytes = matrices + samples + 6.0 * d * sizeof(double);
  if (matrices > samples)
    return {bytes, lambda, fmt::format("CMA-ES's covariance of {} x {} weights", n, n), "cmaes.covariance"};
  if (settings.restarts > 0)
    return {bytes, lambda,
            fmt::format("CMA-ES's {:.0f} candidates of {} weights after {} IPOP restarts (lambda x 2^restarts)", lambda,
                        n, settings.restarts),
            "cmaes.restarts"};
  return {bytes, lambda, fmt::format("CMA-ES's {:.0f} candidates of {} weights", lambda, n), "cmaes.lambda"};
}

}  // namespace esc::evo
