#include "runtime/sim/robot_params.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>

namespace esc::sim {

std::vector<IrMount> khepera_ir_mounts() {
  constexpr double kRadPerDeg = std::numbers::pi / 180.0;
  std::vector<IrMount> mounts(kKheperaIrMountDeg.size());
  for (std::size_t s = 0; s < mounts.size(); ++s)
    mounts[s] = {kKheperaIrMountDeg[s] * kRadPerDeg, kKheperaIrFacingDeg[s] * kRadPerDeg, std::nullopt};
  return mounts;
}

bool BumperSector::holds(double b) const noexcept {
  constexpr double kTurn = 2 * std::numbers::pi;
  const double from_b = b - from_rad - kTurn * std::floor((b - from_rad) / kTurn);   // in [0, 2 pi)
  return from_b <= width_rad();
}

}  // namespace esc::sim
