#pragma once
// NEAT's settings, with the defaults of the paper's XOR experiment (Stanley & Miikkulainen
// 2002, section 4.1 and the appendix) and, where the paper is silent, of NEAT C++'s
// parameter file for it, test.ne (pop_size 150 ...). docs/neat.md lists each default's
// source. The names follow NEAT C++'s parameter files.
#include <cstdint>

#include "runtime/evo/novelty/novelty_archive.hpp"
#include "runtime/genome/graph/graph.hpp"
#include "runtime/genome/graph/graph_operators.hpp"

namespace esc::evo {

// What NEAT's reproduction ranks networks by: the fitness (the paper), or their novelty,
// as Lehman & Stanley (2011) ran NEAT: the mean distance from a network's descriptors to
// its k nearest among its generation and an archive of past novel ones
// (novelty/novelty_archive.hpp, the archive by the authors' adapted threshold).
enum class NeatScore : std::uint8_t { Fitness, Novelty };

struct NeatSettings {
  int population = 150;                 // paper; test.ne pop_size
  // Compatibility distance c1 E + c2 D + c3 W and the threshold delta_t.
  double excess_coeff = 1.0;            // paper c1; test.ne
  double disjoint_coeff = 1.0;          // paper c2; test.ne
  double weight_coeff = 0.4;            // paper c3; test.ne mutdiff_coeff
  double threshold = 3.0;               // paper delta_t; test.ne compat_thresh
  // Steering the threshold towards a number of species (0: off, the paper's XOR): at every
  // breeding but the first it moves by threshold_step towards the target, never below
  // threshold_step (Lehman's fork of NEAT C++: num_species_target 10, compat_mod 0.3).
  int target_species = 0;
  double threshold_step = 0.3;
  int dropoff_age = 15;                 // paper, test.ne: a species not improving for this long x 0.01
  double survival_thresh = 0.2;         // test.ne: the best fraction of a species that breeds
  int elitism = 5;                      // paper: a species with more offspring than this keeps its champion
  double mutate_only_prob = 0.25;       // paper, test.ne: offspring by mutation alone
  double mate_only_prob = 0.2;          // test.ne: offspring of crossover not mutated
  double interspecies_mate_rate = 0.001;   // paper, test.ne
  double mate_multipoint_prob = 0.6;    // test.ne; the rest are averaged (mate_multipoint_avg_prob 0.4)
  double weight_mut_prob = 0.8;         // paper (test.ne: 0.9)
  double weight_mut_power = 2.5;        // test.ne weigh_mut_power
  double toggle_enable_prob = 0.0;      // test.ne
  double reenable_prob = 0.0;           // test.ne mutate_gene_reenable_prob
  double add_node_prob = 0.03;          // paper, test.ne
  double add_link_prob = 0.05;          // paper, test.ne
  double recur_only_prob = 0.0;         // test.ne: 0, no recurrent links; p2nv.ne 0.2
  int newlink_tries = 20;               // test.ne
  double new_link_weight = 10.0;        // NEAT C++ genome.cpp: a new link's weight in [-10, 10]
  genome::graph::Activation activation = genome::graph::Activation::NeatSigmoid;   // network.cpp
  // Hidden nodes of the start genome, each fed by every sensor and feeding every output
  // (no sensor-to-output links then); 0: the paper's minimal start. The authors' maze runs
  // start from one (novelty-search-cpp's mazestartgenes).
  int start_hidden = 0;
  NeatScore score = NeatScore::Fitness;
  int novelty_k = static_cast<int>(qd::NoveltySettings{}.k);
  double novelty_threshold = qd::NoveltySettings{}.threshold;   // descriptors scaled to [0, 1]
};

// A whole population's standstill that halves it between its two best species (NEAT C++
// Population::epoch: highest_last_changed >= dropoff_age + 5).
inline constexpr int kPopulationDropoffExtra = 5;
// A stagnant species' fitness factor (Species::adjust_fitness).
inline constexpr double kStagnantFactor = 0.01;
// A champion's clone mutated when cloned for a population standstill: weights with this
// probability, else a new link (Species::reproduce).
inline constexpr double kSuperChampWeights = 0.8;

// The settings of NEAT's variation, as every algorithm that varies graphs takes them.
[[nodiscard]] inline genome::graph::GraphOperators graph_operators(const NeatSettings& s) {
  return {s.mutate_only_prob, s.mate_only_prob,     s.mate_multipoint_prob, s.weight_mut_prob,
          s.weight_mut_power, s.toggle_enable_prob, s.reenable_prob,        s.add_node_prob,
          s.add_link_prob,    s.recur_only_prob,    s.newlink_tries,        s.new_link_weight,
          s.activation,       s.start_hidden};
}

}  // namespace esc::evo
