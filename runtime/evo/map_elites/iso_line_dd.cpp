#include "runtime/evo/map_elites/iso_line_dd.hpp"

#include <algorithm>
#include <stdexcept>

namespace esc::evo::qd {

Genome iso_line_dd(std::span<const double> x, std::span<const double> y, const IsoLineDd& op, Rng& rng) {
  if (x.size() != y.size()) throw std::invalid_argument("iso+line-dd: parents of different sizes");
  Genome child(x.begin(), x.end());
  for (double& c : child) c += op.sigma_iso * rng.normal();
  const double line = op.sigma_line * rng.normal();
  for (std::size_t i = 0; i < child.size(); ++i) child[i] = std::clamp(child[i] + line * (y[i] - x[i]), op.lower, op.upper);
  return child;
}

}  // namespace esc::evo::qd
