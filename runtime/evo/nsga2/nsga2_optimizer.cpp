#include "runtime/evo/nsga2/nsga2_optimizer.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "runtime/genome/genome_size.hpp"
#include "runtime/genome/graph/graph_variation.hpp"
#include "runtime/genome/tree/tree_variation.hpp"
#include "runtime/evo/measured_state.hpp"
#include "runtime/evo/pareto/hypervolume.hpp"
#include "runtime/evo/run_streams.hpp"

namespace esc::evo {

namespace {

// The run-level state's tag (measured_state.hpp): the core's state and the parents' origins.
constexpr std::string_view kRunTag = "esc-nsga2-run";

class Nsga2Optimizer final : public Optimizer {
 public:
  Nsga2Optimizer(const Nsga2Settings& settings, const Problem& problem)
      : core_(nsga2_core(settings, problem)),
        seed_(problem.seed),
        objectives_(problem.objectives.size()),
        reference_(hypervolume_reference(problem)) {
    start_core(core_, problem);
  }

  std::vector<Genome> ask(int generation) override {
    generation_ = generation;
    Rng rng = breed_stream(seed_, generation);
    return core_.ask(rng);
  }

  void tell(std::span<const Outcome> outcomes) override {
    std::vector<std::vector<double>> f(outcomes.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (outcomes[i].objectives.size() != objectives_)
        throw std::invalid_argument("NSGA-II: told " + std::to_string(outcomes[i].objectives.size()) +
                                    " objectives for a problem of " + std::to_string(objectives_));
      for (const double v : outcomes[i].objectives) f[i].push_back(-v);
    }
    measured_ = survivors_measured(measured_, generation_, core_.tell(f));
  }

  std::vector<Metric> metrics() const override {
    const std::vector<std::size_t> front = core_.first_front();
    std::vector<Metric> m{{"front", static_cast<double>(front.size())}};
    if (!reference_.empty()) {
      ObjectiveRows points;
      for (const std::size_t i : front) points.push_back(core_.objectives()[i]);
      m.push_back({"hypervolume", hypervolume(points, reference_)});
    }
    return m;
  }

  // The first front of the parents: its objectives, back in their maximised terms.
  std::optional<Members> members(bool changes) const override {
    Members m{MemberKind::Front, objectives_, 0, {}, {}, {}, {}};
    const std::vector<std::size_t> front = core_.first_front();
    for (std::size_t i = 0; i < front.size(); ++i) {
      Member& x = m.members.emplace_back();
      x.cell = static_cast<std::int64_t>(i);
      for (const double v : core_.objectives()[front[i]]) x.objectives.push_back(-v);
      if (!changes) x.genome = core_.population()[front[i]];
      x.measured = measured_[front[i]];
    }
    return m;
  }

  StateBytes save() const override { return save_with_measured(kRunTag, core_.save(), measured_); }
  void load(std::span<const std::uint8_t> state) override {
    auto [core, measured] = read_with_measured(kRunTag, state);
    Nsga2 c = core_;
    c.load(core);
    measured_ = measured_for(std::move(measured), c.population().size(), "NSGA-II", "parents");
    core_ = std::move(c);
  }

 private:
  Nsga2 core_;
  std::uint64_t seed_;
  std::size_t objectives_;
  std::vector<double> reference_;
  int generation_ = 0;                 // of the last ask
  std::vector<Measured> measured_;     // aligned with core_.population()
};

}  // namespace

std::vector<Measured> survivors_measured(const std::vector<Measured>& parents, int generation,
                                         std::span<const std::size_t> kept) {
  std::vector<Measured> out;
  out.reserve(kept.size());
  for (const std::size_t i : kept)
    out.push_back(i < parents.size() ? parents[i]
                                     : Measured{generation, static_cast<std::uint64_t>(i - parents.size())});
  return out;
}


std::vector<double> hypervolume_reference(const Problem& problem) {
  const std::size_t n = problem.objectives.size();
  if (n < 2 || n > 3) return {};
  std::vector<double> r;
  for (const Bounds& b : problem.objectives) {
    if (!std::isfinite(b.lower)) return {};
    r.push_back(-b.lower);
  }
  return r;
}

Nsga2 nsga2_core(const Nsga2Settings& settings, const Problem& problem) {
  if (problem.graph.graphs()) {
    auto graphs = std::make_shared<genome::graph::GraphVariation>(problem.graph.operators, problem.graph);
    return {settings,
            Nsga2Genomes{graphs, [graphs](Genome& a, Genome& b, Rng& rng) { graphs->cross_and_mutate(a, b, rng); },
                         [graphs](std::span<const Genome> parents) { graphs->begin(parents); }}};
  }
  if (problem.tree.primitives == nullptr) return {settings, problem.genome_size};
  if (const std::string why = genome::tree::tree_problem(problem, "NSGA-II"); !why.empty()) throw std::invalid_argument(why);
  auto trees = std::make_shared<const genome::tree::TreeVariation>(*problem.tree.operators, *problem.tree.primitives);
  return {settings, Nsga2Genomes{trees, [trees](Genome& a, Genome& b, Rng& rng) { trees->cross_and_mutate(a, b, rng); }}};
}

std::unique_ptr<Optimizer> make_nsga2(const Nsga2Settings& settings, const Problem& problem) {
  return std::make_unique<Nsga2Optimizer>(settings, problem);
}

std::size_t nsga2_population(const Nsga2Settings& settings, const Problem& /*problem*/) {
  return static_cast<std::size_t>(settings.population);
}

MemoryPeak nsga2_memory_peak(const Nsga2Settings& settings, const Problem& problem) {
  const double big_n = static_cast<double>(settings.population);
  const std::size_t genes = genome::genes_at_most(problem);
  return {nsga2_memory_bytes(settings, genes, problem.objectives.size()) + 2.0 * big_n * sizeof(Measured), big_n,
          fmt::format("NSGA-II's {} parents and {} children of {} genes, ranked together", settings.population,
                      settings.population, genes),
          "nsga2.population"};
}

}  // namespace esc::evo
