#include "runtime/sim/robot_params.hpp"

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

}  // namespace esc::sim
