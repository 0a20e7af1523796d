#include "runtime/evo/cmaes/cmaes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "runtime/evo/limits.hpp"

namespace esc::evo {

namespace {

constexpr std::string_view kFormat = "esc-cmaes";
constexpr std::uint32_t kVersion = 1;

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("CMA-ES: " + message);
}

std::string text(double v) { return std::to_string(v); }
std::string text(std::size_t v) { return std::to_string(v); }
std::string text(int v) { return std::to_string(v); }

// The box map (pycma's BoundTransform). With margin a, L = lower - a and U = upper + a, a
// genotype is first folded into [L, U] (the map has period 2 (U - L)), then sent to the box
// by a parabola on [L, lower + a] and on [upper - a, U] and the identity between: continuous
// with a continuous slope, so the search sees a smooth function, and flat at L and U, which
// map to the bounds, so an optimum on a bound is approached as an interior one. pycma's
// margin is 0.05 max(|bound|, 1); ours, 2.5 % of the width, is the same for esc's [-1, 1]
// and does not depend on where the box lies.
struct BoxMap {
  double lo, hi, a;
  BoxMap(double lower, double upper) : lo(lower), hi(upper), a(0.025 * (upper - lower)) {}
  [[nodiscard]] double left() const { return lo - a; }
  [[nodiscard]] double right() const { return hi + a; }
  [[nodiscard]] double period() const { return 2.0 * (right() - left()); }

  [[nodiscard]] double to_box(double x) const {
    if (!std::isfinite(x)) return lo + 0.5 * (hi - lo);  // unreachable with capped sigma
    const double w = right() - left();
    double t = x;
    if (t < left() || t > right()) {
      double m = std::fmod(t - left(), 2.0 * w);
      if (m < 0.0) m += 2.0 * w;
      if (m > w) m = 2.0 * w - m;
      t = left() + m;
    }
    double y = t;
    if (t < lo + a) y = lo + (t - left()) * (t - left()) / (4.0 * a);
    else if (t > hi - a) y = hi - (right() - t) * (right() - t) / (4.0 * a);
    return std::clamp(y, lo, hi);  // the clamp only absorbs rounding
  }
  // The genotype in [L, U] whose image is p (p within the box).
  [[nodiscard]] double from_box(double p) const {
    if (p < lo + a) return left() + 2.0 * std::sqrt(a * (p - lo));
    if (p > hi - a) return right() - 2.0 * std::sqrt(a * (hi - p));
    return p;
  }
  // The same image, from the period centred on the box: moving a coordinate of the mean by
  // whole periods moves every sample by them and changes no candidate, and keeps the mean
  // from drifting on a flat fitness until rounding eats its samples.
  [[nodiscard]] double recentre(double x) const {
    const double start = left() - 0.25 * period();
    const double k = std::floor((x - start) / period());
    return k == 0.0 ? x : x - k * period();
  }
};

// Expected length of an n-dimensional standard normal vector (tutorial, p. 28).
double chi_n(std::size_t n) {
  const double d = static_cast<double>(n);
  return std::sqrt(d) * (1.0 - 1.0 / (4.0 * d) + 1.0 / (21.0 * d * d));
}

double norm(const std::vector<double>& v) {
  double s = 0.0;
  for (const double x : v) s += x * x;
  return std::sqrt(s);
}

bool all_finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

}  // namespace

std::size_t cmaes_default_lambda(std::size_t n) {
  return 4 + static_cast<std::size_t>(std::floor(3.0 * std::log(static_cast<double>(n))));  // (48)
}

Cmaes::Cmaes(const CmaesSettings& settings, std::size_t n) : s_(settings), n_(n) {
  require(n_ >= 1, "the dimension n must be at least 1, got 0");
  require(s_.lambda == 0 || (s_.lambda >= 2 && s_.lambda <= kCmaesMaxLambda),
          "lambda must be 0 (4 + floor(3 ln n)) or in [2, " + text(kCmaesMaxLambda) + "], got " + text(s_.lambda));
  const std::size_t lambda = s_.lambda == 0 ? cmaes_default_lambda(n_) : static_cast<std::size_t>(s_.lambda);
  require(s_.mu == 0 || (s_.mu >= 1 && static_cast<std::size_t>(s_.mu) <= lambda / 2),
          "mu must be 0 (lambda / 2) or in [1, lambda / 2 = " + text(lambda / 2) + "], got " + text(s_.mu));
  require(std::abs(s_.lower) <= kMaxGeneBound && std::abs(s_.upper) <= kMaxGeneBound && s_.lower < s_.upper,
          "lower (" + text(s_.lower) + ") must be below upper (" + text(s_.upper) + "), both within +-1e6");
  require(s_.sigma > 0.0 && s_.sigma <= kMaxStepSize, "sigma must be in (0, 1000], got " + text(s_.sigma));
  require(s_.restarts >= 0 && s_.restarts <= kCmaesMaxRestarts,
          "restarts must be in [0, " + text(kCmaesMaxRestarts) + "], got " + text(s_.restarts));
  require(s_.stop_sigma >= 0.0 && s_.stop_sigma < 1.0, "stop_sigma must be in [0, 1), got " + text(s_.stop_sigma));
  require(s_.stop_condition > 1.0 && s_.stop_condition <= kCmaesMaxCondition,
          "stop_condition must be in (1, 1e16], got " + text(s_.stop_condition));
  require(s_.stop_flat >= 0, "stop_flat must be at least 0, got " + text(s_.stop_flat));

  set_population(lambda, s_.mu == 0 ? lambda / 2 : static_cast<std::size_t>(s_.mu));
  mean_.assign(n_, 0.0);
  reset_distribution();
}

// Weights (49), (53) restricted to the mu positive ones, and the constants (55)-(58).
void Cmaes::set_population(std::size_t lambda, std::size_t mu) {
  lambda_ = lambda;
  weights_.resize(mu);
  const double half = std::log((static_cast<double>(lambda) + 1.0) / 2.0);
  for (std::size_t i = 0; i < mu; ++i) weights_[i] = half - std::log(static_cast<double>(i + 1));
  const double sum = std::accumulate(weights_.begin(), weights_.end(), 0.0);
  double squares = 0.0;
  for (double& w : weights_) {
    w /= sum;
    squares += w * w;
  }
  mu_eff_ = 1.0 / squares;

  const double n = static_cast<double>(n_);
  c_sigma_ = (mu_eff_ + 2.0) / (n + mu_eff_ + 5.0);
  d_sigma_ = 1.0 + 2.0 * std::max(0.0, std::sqrt((mu_eff_ - 1.0) / (n + 1.0)) - 1.0) + c_sigma_;
  c_c_ = (4.0 + mu_eff_ / n) / (n + 4.0 + 2.0 * mu_eff_ / n);
  constexpr double alpha_cov = 2.0;
  c_1_ = alpha_cov / ((n + 1.3) * (n + 1.3) + mu_eff_);
  c_mu_ = std::min(1.0 - c_1_,
                   alpha_cov * (mu_eff_ - 2.0 + 1.0 / mu_eff_) / ((n + 2.0) * (n + 2.0) + alpha_cov * mu_eff_ / 2.0));
  if (s_.separable) {
    // A diagonal has n, not n^2 / 2, degrees of freedom to learn (Ros & Hansen 2008).
    c_1_ *= (n + 2.0) / 3.0;
    c_mu_ = std::min(1.0 - c_1_, c_mu_ * (n + 2.0) / 3.0);
  }
  // The tutorial's lazy update (Appendix B): C moves little in 1 / (10 n (c_1 + c_mu))
  // generations, so B and D can lag that long at O(n^3) each time.
  eigen_gap_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::floor(1.0 / (10.0 * n * (c_1_ + c_mu_)))));
}

void Cmaes::reset_distribution() {
  sigma_ = s_.sigma * (s_.upper - s_.lower);
  p_sigma_.assign(n_, 0.0);
  p_c_.assign(n_, 0.0);
  d_.assign(n_, 1.0);
  if (s_.separable) {
    c_.assign(n_, 1.0);
    b_.clear();
  } else {
    c_.assign(n_ * n_, 0.0);
    for (std::size_t i = 0; i < n_; ++i) c_[i * n_ + i] = 1.0;
    b_ = c_;
  }
  updates_ = 0;
  decomposed_at_ = 0;
  flat_ = 0;
}

void Cmaes::place_mean(std::span<const double> point) {
  const BoxMap box(s_.lower, s_.upper);
  for (std::size_t i = 0; i < n_; ++i) mean_[i] = box.from_box(point[i]);
}

void Cmaes::start(Rng& rng) {
  std::vector<double> point(n_);
  for (double& x : point) x = rng.uniform(s_.lower, s_.upper);
  start(point);
  first_.clear();
}

void Cmaes::start(std::span<const double> mean) {
  require(mean.size() == n_, "the start point must have " + text(n_) + " coordinates, got " + text(mean.size()));
  for (const double x : mean)
    require(x >= s_.lower && x <= s_.upper,
            "the start point must lie within [lower, upper] = [" + text(s_.lower) + ", " + text(s_.upper) +
                "], found " + text(x));
  const std::size_t lambda = s_.lambda == 0 ? cmaes_default_lambda(n_) : static_cast<std::size_t>(s_.lambda);
  set_population(lambda, s_.mu == 0 ? lambda / 2 : static_cast<std::size_t>(s_.mu));
  place_mean(mean);
  reset_distribution();
  first_.assign(mean.begin(), mean.end());
  started_ = true;
  restart_due_ = false;
  done_ = false;
  stop_.clear();
  restarts_ = 0;
  generation_ = 0;
  evaluations_ = 0;
  asked_ = false;
}

std::vector<std::vector<double>> Cmaes::ask(Rng& rng) {
  if (!started_) throw std::logic_error("CMA-ES: ask before start");
  if (done_) throw std::logic_error("CMA-ES: ask after the search stopped (" + stop_ + ")");
  if (restart_due_) {
    std::vector<double> point(n_);
    for (double& x : point) x = rng.uniform(s_.lower, s_.upper);
    place_mean(point);
    restart_due_ = false;
  }
  z_.resize(n_ * lambda_);
  for (double& z : z_) z = rng.normal();  // (38)
  if (!first_.empty()) std::fill_n(z_.begin(), n_, 0.0);  // candidate 0 is the mean itself

  // y = B D z (39), column by column in a fixed order, so the sums do not depend on how a
  // build vectorises them.
  y_.assign(n_ * lambda_, 0.0);
  for (std::size_t k = 0; k < lambda_; ++k) {
    const double* z = &z_[k * n_];
    double* y = &y_[k * n_];
    if (s_.separable) {
      for (std::size_t i = 0; i < n_; ++i) y[i] = d_[i] * z[i];
      continue;
    }
    for (std::size_t j = 0; j < n_; ++j) {
      const double s = d_[j] * z[j];
      const double* b = &b_[j * n_];
      for (std::size_t i = 0; i < n_; ++i) y[i] += s * b[i];
    }
  }

  const BoxMap box(s_.lower, s_.upper);
  std::vector<std::vector<double>> candidates(lambda_, std::vector<double>(n_));
  for (std::size_t k = 0; k < lambda_; ++k)
    for (std::size_t i = 0; i < n_; ++i)
      candidates[k][i] = box.to_box(mean_[i] + sigma_ * y_[k * n_ + i]);  // (40)
  // A given start point is handed out unchanged, not through its genotype and back.
  if (!first_.empty()) candidates[0] = first_;
  asked_ = true;
  return candidates;
}

void Cmaes::tell(std::span<const double> f) {
  if (!asked_) throw std::logic_error("CMA-ES: tell without a pending ask");
  require(f.size() == lambda_, "tell needs " + text(lambda_) + " values (lambda), got " + text(f.size()));
  asked_ = false;
  first_.clear();

  // Rank by f, NaN last; ties keep the candidates' order, so ranking is deterministic.
  const auto key = [](double v) { return std::isnan(v) ? std::numeric_limits<double>::infinity() : v; };
  std::vector<std::size_t> order(lambda_);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(f[a]) < key(f[b]); });

  // <y>_w (41) and <z>_w, for which C^(-1/2) <y>_w = B <z>_w with the B and D that sampled.
  const std::size_t mu = weights_.size();
  std::vector<double> y_w(n_, 0.0), z_w(n_, 0.0);
  for (std::size_t r = 0; r < mu; ++r) {
    const std::size_t k = order[r];
    for (std::size_t i = 0; i < n_; ++i) {
      y_w[i] += weights_[r] * y_[k * n_ + i];
      z_w[i] += weights_[r] * z_[k * n_ + i];
    }
  }
  for (std::size_t i = 0; i < n_; ++i) mean_[i] += sigma_ * y_w[i];  // (42), c_m = 1

  // Step-size path (43).
  std::vector<double> c_half_y(n_, 0.0);
  if (s_.separable) {
    c_half_y = z_w;
  } else {
    for (std::size_t j = 0; j < n_; ++j)
      for (std::size_t i = 0; i < n_; ++i) c_half_y[i] += b_[j * n_ + i] * z_w[j];
  }
  const double path_gain = std::sqrt(c_sigma_ * (2.0 - c_sigma_) * mu_eff_);
  for (std::size_t i = 0; i < n_; ++i) p_sigma_[i] = (1.0 - c_sigma_) * p_sigma_[i] + path_gain * c_half_y[i];
  ++updates_;

  // h_sigma stalls the rank-one path while p_sigma is long (p. 28).
  const double ps_norm = norm(p_sigma_);
  const double chi = chi_n(n_);
  const double warmup = std::sqrt(1.0 - std::pow(1.0 - c_sigma_, 2.0 * static_cast<double>(updates_)));
  const bool h_sigma = ps_norm / warmup < (1.4 + 2.0 / (static_cast<double>(n_) + 1.0)) * chi;
  const double c_gain = h_sigma ? std::sqrt(c_c_ * (2.0 - c_c_) * mu_eff_) : 0.0;
  for (std::size_t i = 0; i < n_; ++i) p_c_[i] = (1.0 - c_c_) * p_c_[i] + c_gain * y_w[i];  // (45)

  update_covariance(order, h_sigma);
  sigma_ *= std::exp(c_sigma_ / d_sigma_ * (ps_norm / chi - 1.0));  // (44)
  sigma_ = std::min(sigma_, kMaxStepSize * (s_.upper - s_.lower));

  ++generation_;
  evaluations_ += lambda_;
  if (s_.separable) {
    for (std::size_t i = 0; i < n_; ++i) d_[i] = std::sqrt(c_[i]);
  } else if (updates_ - decomposed_at_ >= eigen_gap_) {
    decompose();
  }
  const BoxMap box(s_.lower, s_.upper);
  for (double& m : mean_) m = box.recentre(m);

  // Flat fitness: the best value equals the one floor(0.1 + lambda / 4) ranks behind (pycma's test).
  const std::size_t kth = std::min(lambda_ - 1, static_cast<std::size_t>(0.1 + static_cast<double>(lambda_) / 4.0));
  const bool flat = f[order[0]] == f[order[kth]];
  flat_ = flat ? flat_ + 1 : 0;
  end_generation();
}

// Rank-one and rank-mu updates (47); the weights sum to 1 and are all positive (46).
void Cmaes::update_covariance(std::span<const std::size_t> order, bool h_sigma) {
  const std::size_t mu = weights_.size();
  const double delta = h_sigma ? 0.0 : c_c_ * (2.0 - c_c_);
  const double keep = 1.0 + c_1_ * delta - c_1_ - c_mu_;
  if (s_.separable) {
    for (std::size_t i = 0; i < n_; ++i) {
      double c = keep * c_[i] + c_1_ * p_c_[i] * p_c_[i];
      for (std::size_t r = 0; r < mu; ++r) {
        const double y = y_[order[r] * n_ + i];
        c += c_mu_ * weights_[r] * y * y;
      }
      c_[i] = c;
    }
  } else {
    // The lower triangle, column by column, then mirrored: C stays exactly symmetric.
    for (std::size_t j = 0; j < n_; ++j) {
      for (std::size_t i = j; i < n_; ++i) c_[j * n_ + i] = keep * c_[j * n_ + i] + c_1_ * p_c_[i] * p_c_[j];
      for (std::size_t r = 0; r < mu; ++r) {
        const double* y = &y_[order[r] * n_];
        const double s = c_mu_ * weights_[r] * y[j];
        for (std::size_t i = j; i < n_; ++i) c_[j * n_ + i] += s * y[i];
      }
    }
    for (std::size_t j = 0; j < n_; ++j)
      for (std::size_t i = j + 1; i < n_; ++i) c_[i * n_ + j] = c_[j * n_ + i];
  }
}

// A stop that fires restarts the search (IPOP) while restarts are left, else ends it.
void Cmaes::end_generation() {
  const char* reason = stop_fired();
  if (reason == nullptr) return;
  stop_ = reason;
  if (restarts_ >= s_.restarts) {
    done_ = true;
    return;
  }
  // IPOP: a fresh distribution, twice the population, a new mean drawn at the next ask.
  ++restarts_;
  set_population(2 * lambda_, 2 * weights_.size());
  reset_distribution();
  restart_due_ = true;
}

void Cmaes::decompose() {
  Eigen::Map<const Eigen::MatrixXd> c(c_.data(), static_cast<Eigen::Index>(n_), static_cast<Eigen::Index>(n_));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(c);
  // A non-positive eigenvalue (rounding, far beyond any useful condition) becomes D = 0,
  // an infinite condition number, which stops the search.
  for (std::size_t i = 0; i < n_; ++i) d_[i] = std::sqrt(std::max(eig.eigenvalues()(static_cast<Eigen::Index>(i)), 0.0));
  Eigen::Map<Eigen::MatrixXd>(b_.data(), static_cast<Eigen::Index>(n_), static_cast<Eigen::Index>(n_)) =
      eig.eigenvectors();
  decomposed_at_ = updates_;
}

const char* Cmaes::stop_fired() const {
  // tolX: every coordinate's sd, and the rank-one path, below the tolerance.
  const double tol = s_.stop_sigma * (s_.upper - s_.lower);
  bool small = true;
  for (std::size_t i = 0; i < n_ && small; ++i) {
    const double c_ii = s_.separable ? c_[i] : c_[i * n_ + i];
    small = sigma_ * std::max(std::sqrt(c_ii), std::abs(p_c_[i])) < tol;
  }
  if (small) return "stop_sigma";
  if (!(condition() <= s_.stop_condition)) return "stop_condition";
  if (s_.stop_flat > 0 && flat_ >= s_.stop_flat) return "stop_flat";
  return nullptr;
}

double Cmaes::condition() const noexcept {
  const auto [lo, hi] = std::minmax_element(d_.begin(), d_.end());
  if (*lo <= 0.0) return std::numeric_limits<double>::infinity();
  const double r = *hi / *lo;
  return r * r;
}

std::vector<double> Cmaes::mean() const {
  const BoxMap box(s_.lower, s_.upper);
  std::vector<double> point(n_);
  for (std::size_t i = 0; i < n_; ++i) point[i] = box.to_box(mean_[i]);
  return point;
}

StateBytes Cmaes::save() const {
  StateWriter w;
  w.put(std::string(kFormat));
  w.put(kVersion);
  w.put(static_cast<std::uint64_t>(n_));
  w.put(static_cast<std::uint8_t>(s_.separable));
  w.put(s_.lower);
  w.put(s_.upper);
  w.put(static_cast<std::int32_t>(s_.lambda));
  w.put(static_cast<std::int32_t>(s_.mu));
  w.put(static_cast<std::uint8_t>(started_));
  w.put(static_cast<std::uint8_t>(restart_due_));
  w.put(static_cast<std::uint8_t>(done_));
  w.put(stop_);
  w.put(static_cast<std::int32_t>(restarts_));
  w.put(static_cast<std::int32_t>(flat_));
  w.put(generation_);
  w.put(updates_);
  w.put(decomposed_at_);
  w.put(evaluations_);
  w.put(sigma_);
  for (const auto* v : {&mean_, &p_sigma_, &p_c_, &c_, &b_, &d_, &first_}) w.put(std::span<const double>(*v));
  return std::move(w).take();
}

void Cmaes::load(std::span<const std::uint8_t> bytes) {
  StateReader r(bytes);
  const auto fail = [](const std::string& why) { throw std::invalid_argument("CMA-ES state: " + why); };
  if (r.text() != kFormat) fail("not a CMA-ES state");
  if (const auto v = r.get<std::uint32_t>(); v != kVersion) fail("format version " + std::to_string(v) + ", expected 1");
  if (const auto n = r.get<std::uint64_t>(); n != n_)
    fail("saved for n = " + std::to_string(n) + ", this optimizer has n = " + text(n_));
  if (r.get<std::uint8_t>() != static_cast<std::uint8_t>(s_.separable)) fail("separable differs from the saved one");
  if (r.get<double>() != s_.lower) fail("lower differs from the saved one");
  if (r.get<double>() != s_.upper) fail("upper differs from the saved one");
  if (r.get<std::int32_t>() != s_.lambda) fail("lambda differs from the saved one");
  if (r.get<std::int32_t>() != s_.mu) fail("mu differs from the saved one");

  Cmaes next = *this;
  const auto flag = [&]() {
    const auto b = r.get<std::uint8_t>();
    if (b > 1) fail("a flag is neither 0 nor 1");
    return b == 1;
  };
  next.started_ = flag();
  next.restart_due_ = flag();
  next.done_ = flag();
  next.stop_ = r.text();
  next.restarts_ = r.get<std::int32_t>();
  next.flat_ = r.get<std::int32_t>();
  next.generation_ = r.get<std::uint64_t>();
  next.updates_ = r.get<std::uint64_t>();
  next.decomposed_at_ = r.get<std::uint64_t>();
  next.evaluations_ = r.get<std::uint64_t>();
  next.sigma_ = r.get<double>();
  for (auto* v : {&next.mean_, &next.p_sigma_, &next.p_c_, &next.c_, &next.b_, &next.d_, &next.first_}) *v = r.doubles();
  r.finish();

  if (next.stop_ != "" && next.stop_ != "stop_sigma" && next.stop_ != "stop_condition" && next.stop_ != "stop_flat")
    fail("unknown stop '" + next.stop_ + "'");
  if (next.restarts_ < 0 || next.restarts_ > kCmaesMaxRestarts) fail("restarts out of range");
  if (next.flat_ < 0 || next.decomposed_at_ > next.updates_) fail("counters out of range");
  if (!(next.sigma_ >= 0.0) || !std::isfinite(next.sigma_)) fail("sigma is not a finite non-negative number");
  const std::size_t matrix = s_.separable ? n_ : n_ * n_;
  if (next.mean_.size() != n_ || next.p_sigma_.size() != n_ || next.p_c_.size() != n_ || next.c_.size() != matrix ||
      next.b_.size() != (s_.separable ? 0 : matrix) || next.d_.size() != n_ ||
      (!next.first_.empty() && next.first_.size() != n_))
    fail("vector sizes do not match n = " + text(n_));
  for (const auto* v : {&next.mean_, &next.p_sigma_, &next.p_c_, &next.c_, &next.b_, &next.d_, &next.first_})
    if (!all_finite(*v)) fail("a non-finite number");
  for (const double x : next.first_)
    if (x < s_.lower || x > s_.upper) fail("the start point lies outside [lower, upper]");

  // The population follows from the restarts: IPOP doubled it once per restart.
  const std::size_t lambda0 = s_.lambda == 0 ? cmaes_default_lambda(n_) : static_cast<std::size_t>(s_.lambda);
  const std::size_t mu0 = s_.mu == 0 ? lambda0 / 2 : static_cast<std::size_t>(s_.mu);
  next.set_population(lambda0 << next.restarts_, mu0 << next.restarts_);
  next.asked_ = false;
  next.z_.clear();
  next.y_.clear();
  *this = std::move(next);
}

}  // namespace esc::evo
