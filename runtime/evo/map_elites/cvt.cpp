#include "runtime/evo/map_elites/cvt.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace esc::evo::qd {

namespace {

// scikit-learn's relative tolerance: Lloyd stops once the centroids' squared shifts sum to
// at most this times the mean per-coordinate variance of the samples.
constexpr double kRelativeTolerance = 1e-4;

double mean_variance(const std::vector<double>& samples, std::size_t dims) {
  const std::size_t n = samples.size() / dims;
  double total = 0.0;
  for (std::size_t d = 0; d < dims; ++d) {
    double mean = 0.0;
    for (std::size_t s = 0; s < n; ++s) mean += samples[s * dims + d];
    mean /= static_cast<double>(n);
    double sq = 0.0;
    for (std::size_t s = 0; s < n; ++s) sq += (samples[s * dims + d] - mean) * (samples[s * dims + d] - mean);
    total += sq / static_cast<double>(n);
  }
  return total / static_cast<double>(dims);
}

}  // namespace

Cvt Cvt::compute(std::size_t dims, std::size_t k, Rng& rng, const CvtSettings& settings) {
  if (dims == 0 || dims > 1024) throw std::invalid_argument("descriptors: a CVT needs 1 to 1024");
  if (settings.samples > kMaxCvtSamples) throw std::invalid_argument("samples: at most 10^7");
  if (k == 0 || k > settings.samples)
    throw std::invalid_argument("cells: a CVT needs 1 to samples (" + std::to_string(settings.samples) + ") cells");
  if (settings.iterations == 0) throw std::invalid_argument("iterations: at least 1");

  std::vector<double> samples(settings.samples * dims);
  for (double& v : samples) v = rng.uniform();
  std::vector<double> centroids(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(k * dims));
  const double tolerance = kRelativeTolerance * mean_variance(samples, dims);

  std::vector<std::size_t> cell_of_sample(settings.samples, std::numeric_limits<std::size_t>::max());
  std::vector<double> sums(k * dims);
  std::vector<std::size_t> counts(k);
  for (std::size_t iteration = 0; iteration < settings.iterations; ++iteration) {
    const PointTree tree(centroids, dims);
    bool moved = false;
    for (std::size_t s = 0; s < settings.samples; ++s) {
      const std::size_t c = tree.nearest_one(std::span<const double>(samples).subspan(s * dims, dims));
      moved = moved || c != cell_of_sample[s];
      cell_of_sample[s] = c;
    }
    if (!moved) break;
    std::fill(sums.begin(), sums.end(), 0.0);
    std::fill(counts.begin(), counts.end(), 0);
    for (std::size_t s = 0; s < settings.samples; ++s) {
      const std::size_t c = cell_of_sample[s];
      ++counts[c];
      for (std::size_t d = 0; d < dims; ++d) sums[c * dims + d] += samples[s * dims + d];
    }
    double shift = 0.0;
    for (std::size_t c = 0; c < k; ++c) {
      if (counts[c] == 0) continue;
      for (std::size_t d = 0; d < dims; ++d) {
        const double next = sums[c * dims + d] / static_cast<double>(counts[c]);
        shift += (next - centroids[c * dims + d]) * (next - centroids[c * dims + d]);
        centroids[c * dims + d] = next;
      }
    }
    if (shift <= tolerance) break;
  }
  return Cvt(std::move(centroids), dims);
}

Cvt::Cvt(std::vector<double> centroids, std::size_t dims) : tree_([&] {
  if (dims == 0 || centroids.empty() || centroids.size() % dims != 0)
    throw std::invalid_argument("CVT centroids: none, or not whole points of " + std::to_string(dims) + " coordinates");
  for (const double v : centroids)
    if (!(v >= 0.0 && v <= 1.0)) throw std::invalid_argument("CVT centroids: a coordinate outside [0, 1]");
  return PointTree(std::move(centroids), dims);
}()) {}

std::vector<double> Cvt::centroids() const {
  std::vector<double> all;
  all.reserve(cells() * dims());
  for (std::size_t c = 0; c < cells(); ++c) {
    const auto p = centroid(c);
    all.insert(all.end(), p.begin(), p.end());
  }
  return all;
}

}  // namespace esc::evo::qd
