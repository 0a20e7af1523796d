#include "runtime/genome/genome_size.hpp"

#include "runtime/genome/graph/graph_variation.hpp"
#include "runtime/genome/tree/codec.hpp"
#include "runtime/genome/tree/tree_operators.hpp"

namespace esc::genome {

std::size_t genes_at_most(const evo::Problem& problem) {
  if (problem.graph.graphs()) return graph::typical_encoded_size(problem.graph);
  if (problem.tree.primitives == nullptr || problem.tree.operators == nullptr) return problem.genome_size;
  return tree::kCodedNodeWidth * static_cast<std::size_t>(problem.tree.operators->max_size);
}

}  // namespace esc::genome
