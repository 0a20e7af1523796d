#pragma once
// Limits shared by every algorithm that evolves a network's weights (the ES, CMA-ES).
namespace esc::evo {

// Genes within +-kMaxGeneBound, so HI - LO <= 2e6, intermediate recombination, reflection (fmod over 2 (HI - LO)) and the
// networks' weighted sums stay far from overflow; step sizes at most kMaxStepSize (HI - LO)
// (a step of a few times HI - LO already folds back to about uniform, so more means
// nothing), so a mutation moves a gene by at most about 1e11, the geometric mean of two
// step sizes cannot overflow, and every CMA-ES sample stays finite.
inline constexpr double kMaxGeneBound = 1e6;
inline constexpr double kMaxStepSize = 1e3;

}  // namespace esc::evo
