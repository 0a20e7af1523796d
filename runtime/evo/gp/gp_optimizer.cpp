#include "runtime/evo/gp/gp_optimizer.hpp"

#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "runtime/genome/tree/codec.hpp"

namespace esc::evo::gp {

using namespace genome::tree;

namespace {

class GpOptimizer final : public Optimizer {
 public:
  GpOptimizer(const GpSettings& settings, const Problem& problem)
      : gp_(settings, *problem.tree.primitives), seed_(problem.seed) {
    if (problem.start != nullptr) start_ = Individual{decode(*problem.start, gp_.primitives()), 0.0};
  }

  std::vector<Genome> ask(int generation) override {
    if (generation > 0) {
      Rng rng(seed_, {static_cast<std::uint64_t>(Stream::Breed), static_cast<std::uint64_t>(generation)});
      bred_ = gp_.breed(population_, rng);
    } else {
      Rng init(seed_, {static_cast<std::uint64_t>(Stream::Init)});
      if (start_) {
        const std::vector<Individual> copies(static_cast<std::size_t>(gp_.settings().population), *start_);
        bred_ = gp_.breed(copies, init);
        bred_.front() = *start_;
      } else {
        bred_ = gp_.initial(init);
      }
    }
    std::vector<Genome> genomes;
    genomes.reserve(bred_.size());
    for (const Individual& ind : bred_) genomes.push_back(encode(ind.tree));
    return genomes;
  }

  void tell(std::span<const Outcome> outcomes) override {
    if (outcomes.size() != bred_.size())
      throw std::invalid_argument("genetic programming: told " + std::to_string(outcomes.size()) +
                                  " outcomes for " + std::to_string(bred_.size()) + " trees");
    for (std::size_t i = 0; i < bred_.size(); ++i) bred_[i].fitness = outcomes[i].objectives.front();
    population_ = std::move(bred_);
    bred_.clear();
  }

  StateBytes save() const override { return gp_state(population_); }

  // A stored population must be one this script could have bred (the store keeps trees
  // without their primitive set): its size, and every tree decodes in the set.
  void load(std::span<const std::uint8_t> state) override {
    StateReader r(state);
    std::vector<Individual> population(r.count(2 * sizeof(double)));
    for (Individual& ind : population) {
      ind.fitness = r.get<double>();
      ind.tree = decode(r.doubles(), gp_.primitives());
    }
    r.finish();
    if (population.size() != static_cast<std::size_t>(gp_.settings().population))
      throw std::invalid_argument("genetic programming: the state to resume from holds " +
                                  std::to_string(population.size()) + " trees, the population is " +
                                  std::to_string(gp_.settings().population));
    population_ = std::move(population);
  }

 private:
  GeneticProgramming gp_;
  std::uint64_t seed_;
  std::optional<Individual> start_;
  std::vector<Individual> population_;   // the last generation evaluated
  std::vector<Individual> bred_;
};

}  // namespace

std::unique_ptr<Optimizer> make_gp(const GpSettings& settings, const Problem& problem) {
  if (problem.tree.primitives == nullptr) throw std::invalid_argument("genetic programming evolves trees, not networks");
  return std::make_unique<GpOptimizer>(settings, problem);
}

std::size_t gp_population(const GpSettings& settings, std::size_t /*genome_size*/) {
  return static_cast<std::size_t>(settings.population);
}

MemoryPeak gp_memory_peak(const GpSettings& settings, std::size_t /*genome_size*/) {
  const double nodes = settings.max_size, population = settings.population;
  const double tree = sizeof(Individual) + heap_bytes(nodes * sizeof(Node));
  const double coded = static_cast<double>(kCodedNodeWidth) * nodes;
  const double saved = 2.0 * population * (coded + 2.0) * sizeof(double);
  return {2.0 * population * tree + rows_bytes(population, coded) + saved, population,
          fmt::format("GP's {} trees of up to {} nodes, two generations", settings.population, settings.max_size),
          "gp.population"};
}

StateBytes gp_state(std::span<const Individual> population) {
  StateWriter w;
  w.put(static_cast<std::uint64_t>(population.size()));
  for (const Individual& ind : population) {
    w.put(ind.fitness);
    w.put(std::span<const double>(encode(ind.tree)));
  }
  return std::move(w).take();
}

}  // namespace esc::evo::gp
