#include "runtime/evo/neat/neat.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "runtime/evo/neat/neat_options.hpp"
#include "runtime/genome/graph/crossover.hpp"
#include "runtime/genome/graph/mutation.hpp"

namespace esc::evo {

namespace gg = genome::graph;

namespace {

std::size_t pick(Rng& rng, std::size_t n) { return static_cast<std::size_t>(rng.below(n)); }

}  // namespace

Neat::Neat(const NeatSettings& settings, std::size_t inputs, std::size_t outputs,
           std::optional<gg::Activation> output_activation)
    : s_(settings),
      inputs_(inputs),
      outputs_(outputs),
      output_activation_(output_activation.value_or(settings.activation)),
      ops_(graph_operators(settings)),
      threshold_(settings.threshold) {
  if (const std::string why = neat_problem(settings, inputs, outputs); !why.empty())
    throw std::invalid_argument("NEAT: " + why);
}

gg::Coefficients Neat::coefficients() const { return {s_.excess_coeff, s_.disjoint_coeff, s_.weight_coeff}; }

void Neat::start(const gg::Graph* start, Rng& init) {
  const gg::Graph first = start != nullptr ? *start : gg::start_graph(ops_, inputs_, outputs_, output_activation_);
  population_.assign(static_cast<std::size_t>(s_.population), first);
  for (std::size_t i = 0; i < population_.size(); ++i) {
    if (start == nullptr) {
      gg::replace_weights(population_[i], gg::kStartWeight, init);
    } else if (i > 0) {
      gg::mutate_weights(population_[i], s_.weight_mut_power, init);
    }
  }
  next_innovation_ = gg::next_innovation(first);
  next_node_ = gg::next_node_id(first);
  speciate_start();
}

void Neat::speciate_start() {
  species_.clear();
  std::vector<const gg::Graph*> reps;
  for (std::size_t i = 0; i < population_.size(); ++i) {
    const std::size_t k = find_species(population_[i], reps, coefficients(), threshold_);
    if (k == reps.size()) {
      species_.push_back({next_species_++, 1, 0, kNoRecord, false, {}});
      reps.push_back(&population_[i]);
    }
    species_[k].members.push_back(i);
  }
}

void Neat::tell(std::span<const double> fitness) {
  if (fitness.size() != population_.size())
    throw std::invalid_argument("NEAT: told " + std::to_string(fitness.size()) + " fitness values for " +
                                std::to_string(population_.size()) + " members");
  double low = std::numeric_limits<double>::infinity();
  for (const double f : fitness)
    if (std::isfinite(f)) low = std::min(low, f);
  if (!std::isfinite(low)) low = 0.0;
  fitness_.resize(fitness.size());
  for (std::size_t i = 0; i < fitness.size(); ++i) fitness_[i] = std::isfinite(fitness[i]) ? fitness[i] : low;
}

void Neat::breed(Rng& rng) {
  if (!told()) throw std::logic_error("NEAT: breeding a generation whose fitness is not known");
  const std::size_t n = population_.size();
  const auto pop = static_cast<std::size_t>(s_.population);

  if (s_.target_species > 0 && breedings_ >= 1) {
    const auto count = static_cast<int>(species_.size());
    if (count < s_.target_species) threshold_ -= s_.threshold_step;
    if (count > s_.target_species) threshold_ += s_.threshold_step;
    threshold_ = std::max(threshold_, s_.threshold_step);
  }

  const Shares shares = share_fitness(species_, fitness_, s_);
  std::vector<int> offspring = allocate_offspring(species_, shares.shared, n);

  // Species by their champion's fitness, best first (ties in species order).
  std::vector<std::size_t> ranked(species_.size());
  for (std::size_t k = 0; k < ranked.size(); ++k) ranked[k] = k;
  std::stable_sort(ranked.begin(), ranked.end(), [&](std::size_t a, std::size_t b) {
    return fitness_[species_[a].members.front()] > fitness_[species_[b].members.front()];
  });

  // A population that has not improved for dropoff_age + 5 generations breeds from its two
  // best species' champions only, half the offspring each (the lone species all of them:
  // NEAT C++ gives it half and the population shrinks).
  std::vector<std::size_t> super(species_.size(), 0);
  if (const double best = fitness_[species_[ranked.front()].members.front()]; best > highest_) {
    highest_ = best;
    highest_last_changed_ = 0;
  } else {
    ++highest_last_changed_;
  }
  if (highest_last_changed_ >= s_.dropoff_age + kPopulationDropoffExtra) {
    highest_last_changed_ = 0;
    std::fill(offspring.begin(), offspring.end(), 0);
    const std::size_t half = pop / 2;
    const std::size_t first = ranked.front();
    const bool two = ranked.size() > 1;
    super[first] = two ? half : pop;
    for (std::size_t r = 0; r < (two ? 2U : 1U); ++r) {
      Species& sp = species_[ranked[r]];
      super[ranked[r]] = r == 0 ? super[first] : pop - half;
      offspring[ranked[r]] = static_cast<int>(super[ranked[r]]);
      sp.last_improved = sp.age;
    }
  }

  // Representatives for placing the children: each old species' champion; a new species'
  // first child.
  gg::InnovationRecord record(next_innovation_, next_node_);
  std::vector<gg::Graph> next;
  next.reserve(pop);
  std::vector<Species> grown = species_;
  for (Species& sp : grown) sp.members.clear();
  struct Rep {
    bool child;
    std::size_t index;
  };
  std::vector<Rep> reps;
  for (const Species& sp : species_) reps.push_back({false, sp.members.front()});
  std::vector<const gg::Graph*> rep_graphs;
  const gg::Coefficients c = coefficients();

  const std::size_t old_species = species_.size();
  for (std::size_t k = 0; k < old_species; ++k) {
    const Species& sp = species_[k];
    const std::size_t parents = shares.parents[k];
    const std::size_t champ = sp.members.front();
    bool champ_done = false;
    for (int child = 0; child < offspring[k]; ++child) {
      gg::Graph baby;
      if (super[k] > 0) {
        baby = population_[champ];
        if (super[k] > 1) {
          if (rng.uniform() < kSuperChampWeights || s_.add_link_prob == 0.0) {
            gg::mutate_weights(baby, s_.weight_mut_power, rng);
          } else {
            (void)gg::add_link(baby, record, s_.recur_only_prob, s_.newlink_tries, s_.new_link_weight, rng);
          }
        }
        --super[k];
      } else if (!champ_done && offspring[k] > s_.elitism) {
        baby = population_[champ];
        champ_done = true;
      } else if (rng.uniform() < s_.mutate_only_prob || parents == 1) {
        baby = population_[sp.members[pick(rng, parents)]];
        gg::mutate(baby, ops_, record, rng);
      } else {
        const std::size_t mom = sp.members[pick(rng, parents)];
        std::size_t dad = 0;
        if (rng.uniform() > s_.interspecies_mate_rate) {
          dad = sp.members[pick(rng, parents)];
        } else {
          // Another species, favouring the best: |N(0, 1)| / 4 of the way down the ranking
          // (NEAT C++: gaussrand() / 4, at most 1, a negative draw the best), 5 tries.
          std::size_t other = k;
          for (int tries = 0; other == k && tries < 5; ++tries) {
            const double r = std::min(rng.normal() / 4.0, 1.0);
            const double at = std::floor(r * (static_cast<double>(ranked.size()) - 1.0) + 0.5);
            other = ranked[at > 0.0 ? static_cast<std::size_t>(at) : 0];
          }
          dad = species_[other].members.front();
        }
        const gg::Mating how =
            rng.uniform() < s_.mate_multipoint_prob ? gg::Mating::Multipoint : gg::Mating::MultipointAverage;
        baby = gg::mate(population_[mom], population_[dad], fitness_[mom], fitness_[dad], how, rng);
        if (rng.uniform() > s_.mate_only_prob || mom == dad ||
            gg::compatibility(population_[mom], population_[dad], c) == 0.0)
          gg::mutate(baby, ops_, record, rng);
      }

      next.push_back(std::move(baby));
      rep_graphs.clear();
      for (const Rep& r : reps) rep_graphs.push_back(r.child ? &next[r.index] : &population_[r.index]);
      const std::size_t to = find_species(next.back(), rep_graphs, c, threshold_);
      if (to == reps.size()) {
        grown.push_back({next_species_++, 1, 0, kNoRecord, true, {}});
        reps.push_back({true, next.size() - 1});
      }
      grown[to].members.push_back(next.size() - 1);
    }
  }

  // The new population species by species, in the species' order; empty species die.
  population_.clear();
  species_.clear();
  for (Species& sp : grown) {
    if (sp.members.empty()) continue;
    if (sp.novel) {
      sp.novel = false;
    } else {
      ++sp.age;
    }
    for (std::size_t& m : sp.members) {
      population_.push_back(std::move(next[m]));
      m = population_.size() - 1;
    }
    species_.push_back(std::move(sp));
  }
  next_innovation_ = record.next_innovation();
  next_node_ = record.next_node();
  fitness_.clear();
  ++breedings_;
}

}  // namespace esc::evo
