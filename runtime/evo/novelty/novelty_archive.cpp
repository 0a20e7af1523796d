#include "runtime/evo/novelty/novelty_archive.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "runtime/evo/map_elites/point_tree.hpp"

namespace esc::evo::qd {

namespace {

constexpr std::string_view kFormat = "esc-novelty";
constexpr std::uint32_t kVersion = 1;

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("novelty: " + message);
}

}  // namespace

NoveltyArchive::NoveltyArchive(const NoveltySettings& settings, DescriptorSpace space)
    : s_(settings), space_(std::move(space)), threshold_(settings.threshold) {
  require(s_.k >= 1 && s_.k <= 100'000, "k must be 1 to 100,000");
  require(std::isfinite(s_.threshold) && s_.threshold > 0.0, "threshold must be a positive number");
  require(s_.threshold_floor >= 0.0 && s_.threshold_floor <= s_.threshold, "threshold_floor must be in [0, threshold]");
  require(s_.raise_factor >= 1.0 && s_.raise_factor <= 100.0, "raise_factor must be in [1, 100]");
  require(s_.lower_factor > 0.0 && s_.lower_factor <= 1.0, "lower_factor must be in (0, 1]");
  require(s_.stall_generations >= 1, "stall_generations must be at least 1");
  require(s_.random_probability >= 0.0 && s_.random_probability <= 1.0, "random_probability must be in [0, 1]");
}

std::vector<double> NoveltyArchive::scores(std::span<const std::vector<double>> population) const {
  const std::size_t dims = space_.size();
  const std::size_t n = population.size();
  std::vector<double> unit((n + points_.size()) * dims);
  for (std::size_t i = 0; i < n; ++i) space_.to_unit(population[i], std::span(unit).subspan(i * dims, dims));
  for (std::size_t j = 0; j < points_.size(); ++j) space_.to_unit(points_[j], std::span(unit).subspan((n + j) * dims, dims));

  std::vector<double> novelty(n, 0.0);
  if (n == 0) return novelty;
  const PointTree tree(std::move(unit), dims);
  std::vector<std::uint32_t> indices;
  std::vector<double> squared;
  for (std::size_t i = 0; i < n; ++i) {
    // k + 1 nearest: the individual itself is among them at distance 0 (or a twin is, at the
    // same distance), so their sum is the sum over its k nearest others.
    tree.nearest(tree.point(i), s_.k + 1, indices, squared);
    if (indices.size() < 2) continue;
    double sum = 0.0;
    for (const double d2 : squared) sum += std::sqrt(d2);
    novelty[i] = sum / static_cast<double>(indices.size() - 1);
  }
  return novelty;
}

std::size_t NoveltyArchive::update(std::span<const std::vector<double>> population, std::span<const double> novelty, Rng& rng) {
  require(population.size() == novelty.size(), "a novelty per individual expected");
  for (const auto& d : population) (void)space_.to_unit(d);  // checks every descriptor first
  std::size_t added = 0;
  for (std::size_t i = 0; i < population.size(); ++i) {
    const bool add = s_.mode == NoveltyMode::Threshold ? novelty[i] > threshold_ : rng.uniform() < s_.random_probability;
    if (!add) continue;
    points_.push_back(population[i]);
    ++added;
  }
  if (s_.mode == NoveltyMode::Threshold) {
    stalled_ = added == 0 ? stalled_ + 1 : 0;
    if (stalled_ >= s_.stall_generations) {
      threshold_ = std::max(s_.threshold_floor, threshold_ * s_.lower_factor);
      stalled_ = 0;
    }
    if (added > s_.raise_above) threshold_ *= s_.raise_factor;
  }
  return added;
}

StateBytes NoveltyArchive::save() const {
  StateWriter w;
  w.put(std::string(kFormat));
  w.put(kVersion);
  w.put(static_cast<std::uint64_t>(space_.size()));
  for (const Range& r : space_.ranges()) {
    w.put(r.lower);
    w.put(r.upper);
  }
  w.put(static_cast<std::uint64_t>(s_.k));
  w.put(static_cast<std::uint8_t>(s_.mode));
  w.put(threshold_);
  w.put(static_cast<std::uint64_t>(stalled_));
  w.put(static_cast<std::uint64_t>(points_.size()));
  for (const auto& p : points_)
    for (const double v : p) w.put(v);
  return std::move(w).take();
}

void NoveltyArchive::load(std::span<const std::uint8_t> bytes) {
  StateReader r(bytes);
  const auto fail = [](const std::string& why) { throw std::invalid_argument("novelty state: " + why); };
  if (r.text() != kFormat) fail("not a novelty archive");
  if (const auto v = r.get<std::uint32_t>(); v != kVersion) fail("format version " + std::to_string(v) + ", expected 1");
  if (r.get<std::uint64_t>() != space_.size()) fail("saved with another number of descriptors");
  for (const Range& range : space_.ranges()) {
    const double lower = r.get<double>();
    const double upper = r.get<double>();
    if (!(Range{lower, upper} == range)) fail("saved with other descriptor ranges");
  }
  if (r.get<std::uint64_t>() != s_.k) fail("k differs from the saved one");
  if (r.get<std::uint8_t>() != static_cast<std::uint8_t>(s_.mode)) fail("mode differs from the saved one");
  const auto threshold = r.get<double>();
  const auto stalled = r.get<std::uint64_t>();
  if (!std::isfinite(threshold) || !(threshold > 0.0)) fail("a threshold that is not a positive number");
  std::vector<std::vector<double>> points(r.count(space_.size() * sizeof(double)));
  for (auto& p : points) {
    p.resize(space_.size());
    for (double& v : p) v = r.get<double>();
    if (!std::all_of(p.begin(), p.end(), [](double v) { return std::isfinite(v); })) fail("a descriptor that is not finite");
  }
  r.finish();
  points_ = std::move(points);
  threshold_ = threshold;
  stalled_ = static_cast<std::size_t>(stalled);
}

Members behavior_members(const NoveltyArchive& archive, std::size_t from) {
  Members m{MemberKind::Archive, 0U, archive.space().size(), {}, {}, {}, {}};
  const std::vector<std::vector<double>>& points = archive.points();
  for (std::size_t i = from; i < points.size(); ++i) m.members.push_back({static_cast<std::int64_t>(i), {}, points[i], {}, {}});
  return m;
}

}  // namespace esc::evo::qd
