#include "runtime/genome/vector/box.hpp"

#include <algorithm>

namespace esc::genome {

std::vector<Genome> Box::first(std::size_t count, Rng& rng) const {
  std::vector<Genome> out(count, Genome(n_));
  for (Genome& x : out)
    for (double& v : x) v = rng.uniform(lower_, upper_);
  return out;
}

std::string Box::misfit(std::span<const double> genome) const {
  if (genome.size() != n_)
    return "a genome of another size (" + std::to_string(genome.size()) + " values, not " + std::to_string(n_) + ")";
  // false for NaN too
  if (!std::all_of(genome.begin(), genome.end(), [&](double v) { return v >= lower_ && v <= upper_; }))
    return "a genome outside [lower, upper] = [" + std::to_string(lower_) + ", " + std::to_string(upper_) + "]";
  return {};
}

}  // namespace esc::genome
