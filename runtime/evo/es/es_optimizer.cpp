#include "runtime/evo/es/es_optimizer.hpp"

#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace esc::evo {

namespace {

class EsOptimizer final : public Optimizer {
 public:
  EsOptimizer(const EsSettings& settings, const Problem& problem)
      : es_(settings, problem.genome_size), seed_(problem.seed), start_(problem.start != nullptr) {
    if (start_) {
      parents_ = es_.seeded(*problem.start);
    } else {
      Rng init(seed_, {static_cast<std::uint64_t>(Stream::Init)});
      parents_ = es_.initial(init);
    }
  }

  std::vector<Genome> ask(int generation) override {
    Rng rng(seed_, {static_cast<std::uint64_t>(Stream::Breed), static_cast<std::uint64_t>(generation)});
    offspring_ = es_.breed(parents_, rng);
    if (start_ && generation == 0) offspring_.front() = parents_.front();
    std::vector<Genome> genomes;
    genomes.reserve(offspring_.size());
    for (const Individual& c : offspring_) genomes.push_back(c.genes);
    return genomes;
  }

  void tell(std::span<const Outcome> outcomes) override {
    if (outcomes.size() != offspring_.size())
      throw std::invalid_argument("evolution strategy: told " + std::to_string(outcomes.size()) + " outcomes for " +
                                  std::to_string(offspring_.size()) + " offspring");
    for (std::size_t i = 0; i < offspring_.size(); ++i) offspring_[i].fitness = outcomes[i].objectives.front();
    parents_ = es_.select(parents_, offspring_);
    offspring_.clear();
  }

  StateBytes save() const override { return es_state(parents_); }

  void load(std::span<const std::uint8_t> state) override {
    StateReader r(state);
    const std::size_t n = es_.genome_size();
    const std::size_t sigmas = es_.settings().step_sizes == StepSizes::One ? 1 : n;
    std::vector<Individual> parents(r.count(sizeof(double) * (1 + n + sigmas)));
    for (Individual& p : parents) {
      p.fitness = r.get<double>();
      p.genes = r.doubles();
      p.sigmas = r.doubles();
      if (p.genes.size() != n || p.sigmas.size() != sigmas)
        throw std::invalid_argument("evolution strategy: a stored parent has " + std::to_string(p.genes.size()) +
                                    " genes and " + std::to_string(p.sigmas.size()) + " step sizes, expected " +
                                    std::to_string(n) + " and " + std::to_string(sigmas));
    }
    r.finish();
    if (parents.size() != static_cast<std::size_t>(es_.settings().mu))
      throw std::invalid_argument("evolution strategy: the stored state holds " + std::to_string(parents.size()) +
                                  " parents, mu is " + std::to_string(es_.settings().mu));
    parents_ = std::move(parents);
  }

 private:
  EvolutionStrategy es_;
  std::uint64_t seed_;
  bool start_;
  std::vector<Individual> parents_;
  std::vector<Individual> offspring_;
};

}  // namespace

std::unique_ptr<Optimizer> make_es(const EsSettings& settings, const Problem& problem) {
  return std::make_unique<EsOptimizer>(settings, problem);
}

std::size_t es_population(const EsSettings& settings, std::size_t /*genome_size*/) {
  return static_cast<std::size_t>(settings.lambda);
}

MemoryPeak es_memory_peak(const EsSettings& settings, std::size_t genome_size) {
  const double genes = static_cast<double>(genome_size);
  const double sigmas = settings.step_sizes == StepSizes::PerGene ? genes : 1.0;
  const double mu = settings.mu, lambda = settings.lambda;
  const double individual = sizeof(Individual) + heap_bytes(genes * sizeof(double)) + heap_bytes(sigmas * sizeof(double));
  const double saved = 2.0 * mu * (3.0 + genes + sigmas) * sizeof(double);
  const double bytes = (2.0 * mu + lambda) * individual + rows_bytes(lambda, genes) + saved;
  if (2.0 * mu > lambda) return {bytes, lambda, fmt::format("the ES's {} parents of {} genes", settings.mu, genome_size), "mu"};
  return {bytes, lambda, fmt::format("the ES's {} offspring of {} genes", settings.lambda, genome_size), "lambda"};
}

StateBytes es_state(std::span<const Individual> parents) {
  StateWriter w;
  w.put(static_cast<std::uint64_t>(parents.size()));
  for (const Individual& p : parents) {
    w.put(p.fitness);
    w.put(std::span<const double>(p.genes));
    w.put(std::span<const double>(p.sigmas));
  }
  return std::move(w).take();
}

}  // namespace esc::evo
