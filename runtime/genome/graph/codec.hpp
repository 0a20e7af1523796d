#pragma once
// A graph genome as the flat vector of doubles a run hands out, stores and resumes from
// (evo::Genome): a version, the node and link counts, then per node its id, kind and
// activation, then per link its in and out nodes, weight, enabled flag and innovation.
// Ids and counts below 2^53 are exact in a double, so the round trip is lossless.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "runtime/genome/graph/graph.hpp"

namespace esc::genome::graph {

inline constexpr double kCodecVersion = 1.0;
inline constexpr std::size_t kCodedNodeWidth = 3;   // doubles per node
inline constexpr std::size_t kCodedLinkWidth = 5;   // doubles per link

[[nodiscard]] std::vector<double> encode(const Graph& g);
// Doubles encode(g) takes: what a population of graphs costs.
[[nodiscard]] std::size_t encoded_size(std::size_t nodes, std::size_t links);

// Reads `genes` into `out`; returns why it is not a graph genome ("" when it is): another
// version, a length that does not match its counts, a number that is not a whole id or a
// known kind, or what misfit() finds.
[[nodiscard]] std::string decode(std::span<const double> genes, Graph& out);

}  // namespace esc::genome::graph
