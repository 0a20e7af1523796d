#include "runtime/evo/map_elites/point_tree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <nanoflann.hpp>

namespace esc::evo::qd {

namespace {

// nanoflann's view of the points: it reads them through these three calls.
struct Points {
  std::vector<double> values;
  std::size_t dims = 0;
  [[nodiscard]] std::size_t kdtree_get_point_count() const { return values.size() / dims; }
  [[nodiscard]] double kdtree_get_pt(std::uint32_t i, std::size_t d) const { return values[i * dims + d]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;  // nanoflann computes it
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Points>, Points, -1, std::uint32_t>;

}  // namespace

// The tree keeps a reference to its points, so both live together at one address.
struct PointTree::Index {
  Points points;
  Tree tree;
  Index(std::vector<double> values, std::size_t dims)
      : points{std::move(values), dims},
        tree(static_cast<int>(dims), points, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}
};

PointTree::PointTree(std::vector<double> points, std::size_t dims) {
  if (dims == 0 || dims > 1024) throw std::invalid_argument("point tree: dimensions must be 1 to 1024");
  if (points.size() % dims != 0) throw std::invalid_argument("point tree: values are not whole points");
  if (points.size() / dims >= std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("point tree: more than 2^32 - 1 points");
  index_ = std::make_shared<const Index>(std::move(points), dims);
}

std::size_t PointTree::size() const noexcept { return index_->points.kdtree_get_point_count(); }
std::size_t PointTree::dims() const noexcept { return index_->points.dims; }

std::span<const double> PointTree::point(std::size_t i) const {
  const std::size_t d = dims();
  return std::span<const double>(index_->points.values).subspan(i * d, d);
}

void PointTree::nearest(std::span<const double> query, std::size_t k, std::vector<std::uint32_t>& indices,
                        std::vector<double>& squared) const {
  if (query.size() != dims()) throw std::invalid_argument("point tree: query of another dimension");
  const std::size_t count = std::min(k, size());
  indices.resize(count);
  squared.resize(count);
  if (count == 0) return;
  nanoflann::KNNResultSet<double, std::uint32_t> result(count);
  result.init(indices.data(), squared.data());
  index_->tree.findNeighbors(result, query.data(), nanoflann::SearchParams());
}

std::size_t PointTree::nearest_one(std::span<const double> query) const {
  if (query.size() != dims()) throw std::invalid_argument("point tree: query of another dimension");
  if (size() == 0) throw std::logic_error("point tree: no points");
  // Two nearest, on the stack: this runs for every insert and every k-means sample.
  std::array<std::uint32_t, 2> indices{};
  std::array<double, 2> squared{};
  nanoflann::KNNResultSet<double, std::uint32_t> result(std::min<std::size_t>(2, size()));
  result.init(indices.data(), squared.data());
  index_->tree.findNeighbors(result, query.data(), nanoflann::SearchParams());
  if (result.size() == 1 || squared[0] < squared[1]) return indices[0];
  // A tie: every point at that distance, then the lowest index. A radius search keeps
  // distances strictly below its radius, hence the next double up.
  std::vector<std::pair<std::uint32_t, double>> tied;
  nanoflann::RadiusResultSet<double, std::uint32_t> within(
      std::nextafter(squared[0], std::numeric_limits<double>::infinity()), tied);
  index_->tree.findNeighbors(within, query.data(), nanoflann::SearchParams());
  std::uint32_t best = indices[0];
  for (const auto& [i, d] : tied)
    if (d == squared[0] && i < best) best = i;
  return best;
}

double PointTree::memory_bytes() const {
  const Tree& t = index_->tree;
  return static_cast<double>(index_->points.values.capacity() * sizeof(double) + t.pool.usedMemory +
                             t.pool.wastedMemory + t.vAcc.capacity() * sizeof(std::uint32_t));
}

double squared_distance(std::span<const double> a, std::span<const double> b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double diff = a[i] - b[i];
    s += diff * diff;
  }
  return s;
}

}  // namespace esc::evo::qd
