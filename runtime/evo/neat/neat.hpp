#pragma once
// NEAT's population (Stanley & Miikkulainen 2002), generation by generation as NEAT C++'s
// Population::epoch and Species::reproduce make it: species ranked and their fitness
// shared, offspring allotted, the worst of each species dropped, then each species breeds
// its offspring (its champion copied when it has more than `elitism`, the rest by mutation
// alone or crossover, now and then with another species' champion), and every child joins
// the first species whose representative (the previous generation's champion, or a new
// species' first member) lies within the threshold. A state saved after a generation's
// fitness is known and loaded into a fresh Neat breeds the same next generation.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/evo/neat/neat_settings.hpp"
#include "runtime/evo/neat/speciation.hpp"
#include "runtime/evo/state_bytes.hpp"
#include "runtime/genome/graph/graph.hpp"
#include "runtime/genome/graph/innovation.hpp"

namespace esc::evo {

class Neat {
 public:
  // Throws std::invalid_argument on settings the option table would refuse, or no inputs
  // or outputs. The minimal start's output nodes take `output_activation` (a controller's
  // head's), or the settings' activation as the hidden nodes do when none is given.
  Neat(const NeatSettings& settings, std::size_t inputs, std::size_t outputs,
       std::optional<genome::graph::Activation> output_activation = std::nullopt);

  // The first population: copies of `start` (or NEAT's minimal start, with the settings'
  // start_hidden hidden nodes) with every weight drawn from `init` in [-1, 1]; a given
  // start stays unchanged as member 0 and its other copies have their weights mutated
  // instead. Then speciated in order.
  void start(const genome::graph::Graph* start, Rng& init);

  // The fitness of every member, in population order (maximised, of any sign: see
  // share_fitness; a value that is not finite counts as the generation's lowest finite one).
  void tell(std::span<const double> fitness);

  // The next generation from the told one; draws from `rng` only.
  void breed(Rng& rng);

  [[nodiscard]] const std::vector<genome::graph::Graph>& population() const noexcept { return population_; }
  [[nodiscard]] const std::vector<Species>& species() const noexcept { return species_; }
  [[nodiscard]] bool told() const noexcept { return !fitness_.empty(); }
  [[nodiscard]] double threshold() const noexcept { return threshold_; }
  [[nodiscard]] std::int64_t breedings() const noexcept { return breedings_; }

  [[nodiscard]] StateBytes save() const;
  // Throws std::invalid_argument on bytes this Neat could not have written: another format,
  // a checksum that does not match, other inputs, outputs or population, a genome that
  // misfits, species that do not partition the population.
  void load(std::span<const std::uint8_t> state);

 private:
  void speciate_start();
  [[nodiscard]] genome::graph::Coefficients coefficients() const;

  NeatSettings s_;
  std::size_t inputs_;
  std::size_t outputs_;
  genome::graph::Activation output_activation_;
  genome::graph::GraphOperators ops_;
  std::vector<genome::graph::Graph> population_;
  std::vector<double> fitness_;        // as measured, finite; empty until told
  std::vector<Species> species_;
  genome::graph::Id next_innovation_ = 1;
  genome::graph::Id next_node_ = 1;
  std::int64_t next_species_ = 1;
  double threshold_;
  double highest_ = kNoRecord;         // the best fitness ever (highest_fitness)
  int highest_last_changed_ = 0;       // generations since it rose
  std::int64_t breedings_ = 0;
};

}  // namespace esc::evo
