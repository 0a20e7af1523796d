#pragma once
// Checks an arena and a robot before a World is built; throws std::invalid_argument with a
// message naming the offending field and its value.
#include "runtime/sim/arena.hpp"
#include "runtime/sim/khepera_params.hpp"

namespace esc::sim {

// Largest distance a point of the body may travel in one physics substep: Bullet creates
// contact points (which the solver uses to stop the body at a surface) only within this
// look-ahead, Bullet's gContactBreakingThreshold (0.02 m), of which we allow half.
inline constexpr double kMaxTravelPerSubstep_m = 0.01;

// The area-sweeping grid holds at most this many cells (one bit each).
inline constexpr double kMaxSweepCells = 1e8;

// discharge_steps and recharge_steps are at most this: the accumulator counts in integer
// units, discharge_steps * recharge_steps * physics_substeps of them, in 64 bits.
inline constexpr int kMaxEnergySteps = 10'000'000;

void validate_arena(const ArenaSpec& arena);
void validate_robot(const KheperaParams& robot);

}  // namespace esc::sim
