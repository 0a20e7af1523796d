#pragma once
// The kinds of genome an algorithm can evolve (docs/optimizers.md): every kind has a folder
// of its own under runtime/genome/ (its representation, variation, encoding into an
// evo::Genome, printing), and every algorithm declares the kinds it takes, so that the
// compiler can name the algorithms that evolve a controller and refuse the others.
#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace esc::genome {

enum class GenomeKind : std::uint8_t {
  Vector,   // a network's weights: runtime/genome/vector
  Tree,     // a tree over a primitive set: runtime/genome/tree
  Graph,    // a network's topology and weights (NEAT's): runtime/genome/graph
};

[[nodiscard]] constexpr std::string_view name_of(GenomeKind k) noexcept {
  switch (k) {
    case GenomeKind::Vector: return "vector";
    case GenomeKind::Tree: return "tree";
    case GenomeKind::Graph: return "graph";
  }
  return "?";
}

// A set of kinds, as an algorithm declares them.
class GenomeKinds {
 public:
  constexpr GenomeKinds() noexcept = default;
  constexpr GenomeKinds(std::initializer_list<GenomeKind> kinds) noexcept {
    for (const GenomeKind k : kinds) bits_ |= bit(k);
  }
  [[nodiscard]] constexpr bool has(GenomeKind k) const noexcept { return (bits_ & bit(k)) != 0; }
  friend constexpr bool operator==(GenomeKinds, GenomeKinds) = default;

 private:
  static constexpr std::uint8_t bit(GenomeKind k) noexcept { return static_cast<std::uint8_t>(1U << static_cast<unsigned>(k)); }
  std::uint8_t bits_ = 0;
};

}  // namespace esc::genome
