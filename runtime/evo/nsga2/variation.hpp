#pragma once
// NSGA-II's variation of real genes in a box [lower, upper], as Deb's NSGA-II code (revision
// 1.1.6, KanGAL) and DEAP (cxSimulatedBinaryBounded, mutPolynomialBounded) apply it: binary
// crowded tournaments, simulated binary crossover (SBX; Deb & Agrawal, Complex Systems 9(2),
// 1995) with its bounded spread, and polynomial mutation (Deb & Goyal 1996) in its bounded
// form. Every number comes from the Rng given, in the order each function states.
#include <cstddef>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/evo/pareto/selection.hpp"

namespace esc::evo {

// Parents at a gap below this fraction of the box width are not crossed: SBX's spread is
// relative to the gap, and at 0 the bounded spread divides 0 by 0. Deb's code and DEAP use an
// absolute 1e-14, the same for their [0, 1] boxes.
inline constexpr double kSbxMinGap = 1e-14;

// As many winners as points ranked (an even number): the points in two random orders, one
// after the other (Fisher-Yates, n - 1 draws of rng.below each), then each consecutive
// pair's winner under crowded_tournament. Every point plays exactly two tournaments, as in
// Deb's code and DEAP's selTournamentDCD.
[[nodiscard]] std::vector<std::size_t> crowded_tournament_winners(const Ranking& r, Rng& rng);

// SBX of two parents into two children, in place: each gene crosses with probability 0.5
// (one uniform); a crossing gene whose parents differ by more than the minimum gap draws u
// for the spread, then one uniform that decides which child takes which value. With parents
// y1 < y2, beta = 1 + 2 (y1 - lower) / (y2 - y1) for the lower child (upper - y2 for the
// upper one), alpha = 2 - beta^-(eta + 1), and the spread beta_q = (u alpha)^(1/(eta + 1)) for
// u <= 1/alpha, else (1 / (2 - u alpha))^(1/(eta + 1)): the children y1 + y2 -+ beta_q
// (y2 - y1), halved, lie in the box (clamped against rounding). An eta of 20 keeps children
// near their parents.
void simulated_binary_crossover(std::span<double> a, std::span<double> b, double eta, double lower, double upper,
                                Rng& rng);

// Polynomial mutation in place: each gene mutates with `probability` (one uniform per gene),
// then draws u: with delta_1 = (x - lower) / (upper - lower), delta_2 = (upper - x) / (upper -
// lower) and e = eta + 1, the step is (2u + (1 - 2u) (1 - delta_1)^e)^(1/e) - 1 for u < 0.5,
// else 1 - (2 (1 - u) + 2 (u - 0.5) (1 - delta_2)^e)^(1/e), times upper - lower; the result is
// clamped to the box.
void polynomial_mutation(std::span<double> x, double eta, double probability, double lower, double upper, Rng& rng);

}  // namespace esc::evo
