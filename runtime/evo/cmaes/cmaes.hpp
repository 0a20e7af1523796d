#pragma once
// CMA-ES after Hansen, "The CMA Evolution Strategy: A Tutorial" (arXiv:1604.00772, 2016),
// with positive recombination weights only; equation numbers below are the tutorial's.
// Options: sep-CMA-ES (diagonal covariance, Ros & Hansen 2008) and IPOP restarts with a
// doubled population (Auger & Hansen 2005). docs/optimizers.md has the details and the
// validation against DEAP.
//
// The core minimises, as the literature does: tell() takes values to minimise, so a caller
// that maximises a fitness passes its negation. NaN ranks last.
//
// Candidates stay within [lower, upper] through a piecewise linear-quadratic periodic map
// (pycma's BoundTransform): the algorithm runs unchanged on unbounded "genotypes" and hands
// out their images in the box. The map is the identity over the inner 95 % of the box, and
// ranking never looks at fitness magnitudes, so the bounds work alike for fitnesses near 0
// or in the thousands.
//
// The optimizer is a value type. Every random draw comes from the Rng passed to start() or
// ask(), in a fixed order: start(Rng&) draws n uniforms for the mean (coordinate order);
// ask() first draws n uniforms for a restart's new mean when one is due, then lambda x n
// standard normals, candidate by candidate, coordinate by coordinate. Give ask() the
// generation's own stream (derived from the seed and generation()), so a run resumed from
// save() draws what it would have drawn: no Rng state is stored.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/evo/state_bytes.hpp"

namespace esc::evo {

struct CmaesSettings {
  int lambda = 0;                // population size; 0: 4 + floor(3 ln n) (48)
  int mu = 0;                    // parents; 0: lambda / 2; at most lambda / 2 (positive weights)
  double sigma = 0.2;           // initial step size as a fraction of (upper - lower)
  double lower = -1.0;           // every candidate lies in [lower, upper], in each coordinate
  double upper = 1.0;
  bool separable = false;        // sep-CMA-ES: diagonal covariance, O(n) per candidate
  int restarts = 0;          // IPOP: restarts with lambda (and mu) doubled; 0: none
  // Stops; when one fires with no restart left, done() is true.
  double stop_sigma = 1e-12;     // every coordinate's sd below this fraction of (upper - lower)
  double stop_condition = 1e14;  // condition number of C above this
  int stop_flat = 10;            // this many generations in a row with a flat fitness; 0: never
};

// Limits of the settings: beyond about 1e16 the eigenvalues of C are rounding noise, so the
// condition stop cannot be put off further; a population 2^20 times the first is far beyond
// any budget.
inline constexpr double kCmaesMaxCondition = 1e16;
inline constexpr int kCmaesMaxLambda = 1'000'000;
inline constexpr int kCmaesMaxRestarts = 20;

// The default population for n coordinates, 4 + floor(3 ln n) (48).
[[nodiscard]] std::size_t cmaes_default_lambda(std::size_t n);

class Cmaes {
 public:
  // Throws std::invalid_argument naming the setting that is out of range.
  Cmaes(const CmaesSettings& settings, std::size_t n);

  // Starts (again) from a mean drawn uniformly in the bounds, or from a given point in them;
  // a given point is also candidate 0 of the first ask, unchanged (z = 0 for it), so that
  // generation measures it.
  void start(Rng& rng);
  void start(std::span<const double> mean);

  // lambda() candidates, each of n coordinates within [lower, upper]. std::logic_error
  // before start() or once done().
  [[nodiscard]] std::vector<std::vector<double>> ask(Rng& rng);
  // Values to minimise of the last ask's candidates, in their order (std::logic_error
  // without a pending ask, std::invalid_argument for another count). One generation: the
  // mean, step size and covariance move; a stop may fire and restart or end the search.
  void tell(std::span<const double> f);

  [[nodiscard]] bool done() const noexcept { return done_; }
  // The setting whose stop fired last ("stop_sigma", "stop_condition", "stop_flat"), even
  // when a restart followed; empty before any.
  [[nodiscard]] std::string_view stop_reason() const noexcept { return stop_; }
  [[nodiscard]] double sigma() const noexcept { return sigma_; }
  [[nodiscard]] double condition() const noexcept;
  [[nodiscard]] int restarts() const noexcept { return restarts_; }
  [[nodiscard]] std::size_t lambda() const noexcept { return lambda_; }
  [[nodiscard]] std::size_t mu() const noexcept { return weights_.size(); }
  [[nodiscard]] std::uint64_t generation() const noexcept { return generation_; }
  [[nodiscard]] std::uint64_t evaluations() const noexcept { return evaluations_; }
  // The distribution's mean as a point in the bounds (its image, like a candidate).
  [[nodiscard]] std::vector<double> mean() const;
  [[nodiscard]] std::size_t dimension() const noexcept { return n_; }
  [[nodiscard]] const CmaesSettings& settings() const noexcept { return s_; }

  // The whole state between generations (after tell or start; a pending ask is not part of
  // it). load() takes a state saved by an optimizer of the same n, bounds, population
  // settings and variant, and continues bit for bit; anything else throws
  // std::invalid_argument. The stop and restart settings are this object's, not the blob's.
  [[nodiscard]] StateBytes save() const;
  void load(std::span<const std::uint8_t> bytes);

 private:
  void set_population(std::size_t lambda, std::size_t mu);
  void reset_distribution();
  void place_mean(std::span<const double> point);
  void update_covariance(std::span<const std::size_t> order, bool h_sigma);
  void end_generation();
  void decompose();
  [[nodiscard]] const char* stop_fired() const;

  CmaesSettings s_;
  std::size_t n_;

  // Constants of the current population size (48)-(58); recomputed on a restart.
  std::size_t lambda_ = 0;
  std::vector<double> weights_;
  double mu_eff_ = 0.0, c_sigma_ = 0.0, d_sigma_ = 0.0, c_c_ = 0.0, c_1_ = 0.0, c_mu_ = 0.0;
  std::uint64_t eigen_gap_ = 1;   // generations between eigendecompositions

  // The distribution, in genotype space: C column-major n x n (its diagonal when separable),
  // B its eigenvectors as columns (none when separable), D the square roots of its
  // eigenvalues, as of the last decomposition.
  std::vector<double> mean_, p_sigma_, p_c_, c_, b_, d_;
  double sigma_ = 0.0;
  bool started_ = false;
  bool restart_due_ = false;      // the next ask draws a new mean
  bool done_ = false;
  std::string stop_;
  int restarts_ = 0;
  int flat_ = 0;                  // consecutive flat generations
  std::uint64_t generation_ = 0;  // tells, over all restarts
  std::uint64_t updates_ = 0;     // tells since the last (re)start, for h_sigma
  std::uint64_t decomposed_at_ = 0;
  std::uint64_t evaluations_ = 0;

  // The last ask: z ~ N(0, I) and y = B D z, n x lambda column-major.
  std::vector<double> z_, y_;
  bool asked_ = false;
  std::vector<double> first_;     // a given start point, until the first tell
};

}  // namespace esc::evo
