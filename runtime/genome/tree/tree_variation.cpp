#include "runtime/genome/tree/tree_variation.hpp"


#include "runtime/genome/tree/codec.hpp"
#include "runtime/genome/tree/init.hpp"

namespace esc::genome::tree {

TreeVariation::TreeVariation(const TreeOperators& operators, PrimitiveSet set) : ops_(operators), set_(std::move(set)) {
  check_operators(ops_, set_);
}

std::vector<Genome> TreeVariation::first(std::size_t count, Rng& rng) const {
  const TreeOperators& s = ops_;
  std::vector<Genome> out;
  out.reserve(count);
  for (const Tree& t : ramped_half_and_half(set_, count, s.init_min_depth, s.init_max_depth, s.max_size, rng))
    out.push_back(encode(t));
  return out;
}

std::string TreeVariation::misfit(std::span<const double> genome) const {
  Tree t;
  try {
    t = decode(genome, set_);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  const Limits limits = ops_.limits();
  if (static_cast<int>(t.size()) > limits.max_size)
    return "a tree of " + std::to_string(t.size()) + " nodes, above max_size " + std::to_string(limits.max_size);
  if (depth(t) > limits.max_depth)
    return "a tree of depth " + std::to_string(depth(t)) + ", above max_depth " + std::to_string(limits.max_depth);
  return {};
}

void TreeVariation::cross_and_mutate(Genome& a, Genome& b, Rng& rng) const {
  Tree x = decode(a, set_);
  Tree y = decode(b, set_);
  if (rng.uniform() < ops_.crossover) {
    Tree xy = crossover(x, y, set_, ops_.limits(), ops_.internal_bias, rng);
    y = crossover(y, x, set_, ops_.limits(), ops_.internal_bias, rng);
    x = std::move(xy);
  }
  for (auto [tree, genome] : {std::pair{&x, &a}, std::pair{&y, &b}}) {
    const double u = rng.uniform();
    *genome = encode(mutate(*tree, ops_, set_, u, 0.0, rng));
  }
}

Genome TreeVariation::mutate_one(std::span<const double> parent, Rng& rng) const {
  const double u = rng.uniform() * mutation_sum();
  return encode(mutate(decode(parent, set_), ops_, set_, u, 0.0, rng));
}

double TreeVariation::mutation_sum() const noexcept {
  return ops_.subtree_mutation + ops_.point_mutation + ops_.hoist_mutation;
}

double encoded_tree_bytes(const TreeOperators& operators) noexcept {
  return static_cast<double>(kCodedNodeWidth) * static_cast<double>(operators.max_size) * sizeof(double);
}

std::string tree_problem(const evo::Problem& problem, std::string_view algorithm) {
  if (problem.tree.primitives == nullptr || problem.tree.operators != nullptr) return {};
  return std::string(algorithm) + " varies trees with the GP's operators, whose settings come from `evolve gp(...)`: "
                                  "the experiment gives none";
}

}  // namespace esc::genome::tree
