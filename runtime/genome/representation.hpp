#pragma once
// What a search over genomes leaves to what its genomes are: NSGA-II and MAP-Elites rank,
// select and keep genomes the same way whether they are a network's weights in a box
// (vector/box.hpp) or trees encoded as doubles (tree/tree_variation.hpp); only the first
// candidates, the check of a genome read back from a state, and the settings a stored state
// must match differ. The variation itself belongs to each algorithm (pairs of winners for
// NSGA-II, one elite for MAP-Elites), so it is not part of this interface.
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/evo/state_bytes.hpp"

namespace esc::genome {

// A genome of every kind travels as an evo::Genome (its kind encodes it).
using evo::Genome;

// A setting a stored state was written with and must be read back with.
struct FixedSetting {
  std::string_view name;
  double value = 0.0;
};

class Representation {
 public:
  virtual ~Representation() = default;
  // In messages: "a network's weights", "trees".
  [[nodiscard]] virtual std::string_view what() const = 0;
  // Appended to an algorithm's state format ("esc-nsga2" + "-trees"), so that a state of
  // one representation is never read as the other's.
  [[nodiscard]] virtual std::string_view tag() const = 0;
  // Values per genome; 0 when genomes differ in length (trees).
  [[nodiscard]] virtual std::size_t genes() const = 0;
  // `count` genomes to start from, drawn from `rng` one after the other.
  [[nodiscard]] virtual std::vector<Genome> first(std::size_t count, Rng& rng) const = 0;
  // Why `genome` cannot be one of this representation ("" when it can): what a start
  // genome and every genome of a loaded state are checked by.
  [[nodiscard]] virtual std::string misfit(std::span<const double> genome) const = 0;
  // The settings a state records and a load checks, in their order (a box's bounds).
  [[nodiscard]] virtual std::vector<FixedSetting> fixed() const = 0;
};

inline void put_fixed(evo::StateWriter& w, const Representation& rep) {
  for (const FixedSetting& s : rep.fixed()) w.put(s.value);
}

// Why the settings read from `r` differ from rep's, or "".
[[nodiscard]] inline std::string fixed_differs(evo::StateReader& r, const Representation& rep) {
  for (const FixedSetting& s : rep.fixed())
    if (r.get<double>() != s.value) return std::string(s.name) + " differs from the saved one";
  return {};
}

// Why a state whose format reads `read` is not one of `base` + rep.tag(), or "": a state
// of the other representation is named as such rather than as garbage.
[[nodiscard]] inline std::string format_mismatch(std::string_view read, std::string_view base, std::string_view algorithm,
                                                 const Representation& rep) {
  const std::string own = std::string(base) + std::string(rep.tag());
  if (read == own) return {};
  const std::string mine = " (this one evolves " + std::string(rep.what()) + ")";
  if (read == base) return "a state of " + std::string(algorithm) + " over a network's weights" + mine;
  if (read == std::string(base) + "-trees") return "a state of " + std::string(algorithm) + " over trees" + mine;
  return "not " + std::string(algorithm) + " state";
}

}  // namespace esc::genome
