#include "runtime/evo/neat/neat_optimizer.hpp"

#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "runtime/evo/neat/neat.hpp"
#include "runtime/evo/neat/neat_options.hpp"
#include "runtime/evo/run_streams.hpp"
#include "runtime/genome/graph/codec.hpp"

namespace esc::evo {

namespace gg = genome::graph;

namespace {

class NeatOptimizer final : public Optimizer {
 public:
  NeatOptimizer(const NeatSettings& settings, const NeatProblem& problem)
      : neat_(settings, problem.inputs, problem.outputs, problem.output_activation), seed_(problem.seed) {
    gg::Graph start;
    if (problem.start != nullptr) {
      if (const std::string why = gg::decode(*problem.start, start); !why.empty())
        throw std::invalid_argument("NEAT: the start genome is not a graph genome: " + why);
      if (gg::count_nodes(start, gg::NodeKind::Input) != problem.inputs ||
          gg::count_nodes(start, gg::NodeKind::Output) != problem.outputs)
        throw std::invalid_argument(
            fmt::format("NEAT: the start genome has {} inputs and {} outputs, the problem {} and {}",
                        gg::count_nodes(start, gg::NodeKind::Input), gg::count_nodes(start, gg::NodeKind::Output),
                        problem.inputs, problem.outputs));
    }
    Rng init = init_stream(seed_);
    neat_.start(problem.start != nullptr ? &start : nullptr, init);
  }

  std::vector<Genome> ask(int generation) override {
    if (generation != neat_.breedings()) {
      if (generation != neat_.breedings() + 1 || !neat_.told())
        throw std::logic_error(
            fmt::format("NEAT: generation {} asked after {} breedings", generation, neat_.breedings()));
      Rng rng = breed_stream(seed_, generation);
      neat_.breed(rng);
    }
    std::vector<Genome> out;
    out.reserve(neat_.population().size());
    for (const gg::Graph& g : neat_.population()) out.push_back(gg::encode(g));
    return out;
  }

  void tell(std::span<const Outcome> outcomes) override {
    std::vector<double> f(outcomes.size());
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = outcomes[i].objectives.front();
    neat_.tell(f);
  }

  std::vector<Metric> metrics() const override {
    double hidden = 0.0, links = 0.0;
    for (const gg::Graph& g : neat_.population()) {
      hidden += static_cast<double>(gg::count_nodes(g, gg::NodeKind::Hidden));
      links += static_cast<double>(gg::enabled_links(g));
    }
    const auto n = static_cast<double>(neat_.population().size());
    return {{"species", static_cast<double>(neat_.species().size())},
            {"hidden_nodes", hidden / n},
            {"enabled_links", links / n},
            {"threshold", neat_.threshold()}};
  }

  StateBytes save() const override { return neat_.save(); }
  void load(std::span<const std::uint8_t> state) override { neat_.load(state); }

 private:
  Neat neat_;
  std::uint64_t seed_;
};

}  // namespace

std::unique_ptr<Optimizer> make_neat(const NeatSettings& settings, const NeatProblem& problem) {
  return std::make_unique<NeatOptimizer>(settings, problem);
}

std::size_t neat_population(const NeatSettings& settings) { return static_cast<std::size_t>(settings.population); }

MemoryPeak neat_memory_peak(const NeatSettings& settings, std::size_t inputs, std::size_t outputs) {
  const double pop = static_cast<double>(settings.population);
  const double links = 2.0 * static_cast<double>((inputs + 1) * outputs);
  const double nodes = static_cast<double>(inputs + 1 + 2 * outputs);
  const double graph =
      sizeof(gg::Graph) + heap_bytes(nodes * sizeof(gg::NodeGene)) + heap_bytes(links * sizeof(gg::LinkGene));
  const double flat =
      static_cast<double>(gg::encoded_size(static_cast<std::size_t>(nodes), static_cast<std::size_t>(links)));
  // The saved state: each genome's flat form with its length, its fitness and species index.
  const double state = pop * (flat + 3.0) * sizeof(double);
  const double bytes = 2.0 * pop * graph + rows_bytes(pop, flat) + pop * 3.0 * sizeof(double) + writer_bytes(state);
  return {bytes, pop,
          fmt::format("NEAT's {} networks of about {:.0f} links, parents and children", settings.population, links),
          "neat.population"};
}

namespace {

NeatProblem neat_problem_of(const Problem& p) {
  return {p.graph.inputs, p.graph.outputs, p.seed, p.start, p.graph.output_activation};
}

}  // namespace

std::unique_ptr<Optimizer> make_neat_run(const NeatSettings& settings, const Problem& problem) {
  if (!problem.graph.graphs()) throw std::invalid_argument("NEAT evolves graph genomes (a `neat(...)` controller)");
  return make_neat(settings, neat_problem_of(problem));
}

std::size_t neat_run_population(const NeatSettings& settings, const Problem& /*problem*/) {
  return neat_population(settings);
}

MemoryPeak neat_run_memory_peak(const NeatSettings& settings, const Problem& problem) {
  return neat_memory_peak(settings, problem.graph.inputs, problem.graph.outputs);
}

std::string neat_run_problem(const NeatSettings& settings, const Problem& problem) {
  if (!problem.graph.graphs()) return "NEAT evolves graph genomes: a `neat(...)` controller";
  return neat_problem(settings, problem.graph.inputs, problem.graph.outputs);
}

}  // namespace esc::evo
