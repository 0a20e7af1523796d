#include "runtime/genome/graph/graph_variation.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "runtime/genome/graph/codec.hpp"
#include "runtime/genome/graph/crossover.hpp"
#include "runtime/genome/graph/mutation.hpp"

namespace esc::genome::graph {

GraphVariation::GraphVariation(const GraphOperators& operators, const GraphSpace& space)
    : ops_(operators), space_(space) {
  if (!space.graphs() || space.inputs == 0) throw std::invalid_argument("graph variation: no network to evolve");
}

std::vector<Genome> GraphVariation::first(std::size_t count, Rng& rng) const {
  const Graph start = start_graph(ops_, space_.inputs, space_.outputs, space_.output_activation);
  std::vector<Genome> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    Graph g = start;
    replace_weights(g, kStartWeight, rng);
    out.push_back(encode(g));
  }
  return out;
}

std::string GraphVariation::misfit(std::span<const double> genome) const {
  Graph g;
  if (std::string why = decode(genome, g); !why.empty()) return why;
  const std::size_t inputs = count_nodes(g, NodeKind::Input), outputs = count_nodes(g, NodeKind::Output);
  if (inputs != space_.inputs || outputs != space_.outputs)
    return fmt::format("a network of {} inputs and {} outputs, not {} and {}", inputs, outputs, space_.inputs,
                       space_.outputs);
  return {};
}

Graph GraphVariation::decoded(std::span<const double> genome) const {
  Graph g;
  if (std::string why = misfit(genome); !why.empty()) throw std::invalid_argument("graph variation: " + why);
  (void)decode(genome, g);
  return g;
}

void GraphVariation::begin(std::span<const Genome> bred_from) {
  Id innovation = 1, node = 1;
  for (const Genome& genome : bred_from) {
    const Graph g = decoded(genome);
    innovation = std::max(innovation, next_innovation(g));
    node = std::max(node, next_node_id(g));
  }
  record_.emplace(innovation, node);
}

Graph GraphVariation::child_of(const Graph& own, const Graph& other, Rng& rng) {
  if (!record_) throw std::logic_error("graph variation: a child bred before begin()");
  if (rng.uniform() < ops_.mutate_only_prob) {
    Graph child = own;
    mutate(child, ops_, *record_, rng);
    return child;
  }
  const Mating how = rng.uniform() < ops_.mate_multipoint_prob ? Mating::Multipoint : Mating::MultipointAverage;
  Graph child = mate(own, other, 1.0, 0.0, how, rng);
  if (rng.uniform() >= ops_.mate_only_prob) mutate(child, ops_, *record_, rng);
  return child;
}

void GraphVariation::cross_and_mutate(Genome& a, Genome& b, Rng& rng) {
  const Graph ga = decoded(a), gb = decoded(b);
  a = encode(child_of(ga, gb, rng));
  b = encode(child_of(gb, ga, rng));
}

Genome GraphVariation::mutate_one(std::span<const double> parent, Rng& rng) {
  if (!record_) throw std::logic_error("graph variation: a child bred before begin()");
  Graph child = decoded(parent);
  mutate(child, ops_, *record_, rng);
  return encode(child);
}

std::size_t typical_encoded_size(const GraphSpace& space) {
  const std::size_t links = 2 * (space.inputs + 1) * space.outputs;
  const std::size_t nodes = space.inputs + 1 + 2 * space.outputs;
  return encoded_size(nodes, links);
}

}  // namespace esc::genome::graph
