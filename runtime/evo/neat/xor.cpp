#include "runtime/evo/neat/xor.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "runtime/evo/neat/neat_optimizer.hpp"
#include "runtime/genome/graph/codec.hpp"
#include "runtime/genome/graph/network.hpp"

namespace esc::evo {

namespace gg = genome::graph;

namespace {

constexpr std::array<std::array<double, 2>, 4> kPatterns = {{{0, 0}, {0, 1}, {1, 0}, {1, 1}}};
constexpr std::array<double, 4> kTargets = {0, 1, 1, 0};
constexpr double kFlawedFitness = 0.001;   // xor_evaluate's score for a net that never answers

}  // namespace

XorScore score_xor(const gg::Graph& g) {
  gg::Network net(g);
  double error = 0.0;
  bool solved = true;
  for (std::size_t p = 0; p < kPatterns.size(); ++p) {
    net.reset();
    if (!net.relax(kPatterns[p])) return {kFlawedFitness, false};
    const double out = net.output()[0];
    error += std::abs(kTargets[p] - out);
    solved = solved && (out >= 0.5) == (kTargets[p] == 1.0);
  }
  return {(4.0 - error) * (4.0 - error), solved};
}

XorRun solve_xor(const NeatSettings& settings, std::uint64_t seed, int max_generations) {
  XorRun run;
  run.seed = seed;
  const auto optimizer = make_neat(settings, {2, 1, seed, nullptr});
  for (int g = 0; g < max_generations; ++g) {
    const std::vector<Genome> candidates = optimizer->ask(g);
    std::vector<Outcome> outcomes(candidates.size());
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      gg::Graph net;
      if (const std::string why = gg::decode(candidates[i], net); !why.empty())
        throw std::logic_error("NEAT bred " + why);
      const XorScore s = score_xor(net);
      outcomes[i].objectives = {s.fitness};
      if (s.solved && !run.solved) {
        run.solved = true;
        run.evaluations = static_cast<std::uint64_t>(g) * candidates.size() + i + 1;
        run.hidden_nodes = gg::count_nodes(net, gg::NodeKind::Hidden);
        run.enabled_links = gg::enabled_links(net);
      }
    }
    run.generations = g + 1;
    if (run.solved) return run;
    optimizer->tell(outcomes);
  }
  run.evaluations = static_cast<std::uint64_t>(max_generations) * static_cast<std::uint64_t>(settings.population);
  return run;
}

}  // namespace esc::evo
