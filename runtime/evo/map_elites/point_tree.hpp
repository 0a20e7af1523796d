#pragma once
// Nearest neighbours among a fixed set of points, by nanoflann's kd-tree (exact search,
// squared Euclidean distances summed coordinate by coordinate in index order). The CVT
// archive finds a descriptor's cell with it, Lloyd's algorithm assigns its samples with it,
// and the novelty archive finds each individual's k nearest behaviors with it.
//
// The tree is immutable once built; copies share it, so a value type holding one stays
// cheap to copy. nanoflann stays inside point_tree.cpp.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace esc::evo::qd {

// nanoflann's tree per point: its index (4 bytes) and a share of the nodes (at most one
// leaf of 40 bytes per point; leaves hold up to 10), rounded up: what estimates count.
inline constexpr double kTreeBytesPerPoint = 48.0;

class PointTree {
 public:
  // `points`: size() x dims values, row after row. Throws std::invalid_argument for dims 0, a
  // count that is not a multiple of dims, or more than 2^32 - 1 points.
  PointTree(std::vector<double> points, std::size_t dims);

  [[nodiscard]] std::size_t size() const noexcept;
  [[nodiscard]] std::size_t dims() const noexcept;
  [[nodiscard]] std::span<const double> point(std::size_t i) const;

  // The min(k, size()) nearest points to `query`, nearest first, as indices and squared
  // distances (both resized to that count). Equally near points come in no set order.
  void nearest(std::span<const double> query, std::size_t k, std::vector<std::uint32_t>& indices,
               std::vector<double>& squared) const;
  // The nearest point; among equally near ones the lowest index, so a cell never depends on
  // the tree's shape. size() > 0.
  [[nodiscard]] std::size_t nearest_one(std::span<const double> query) const;
  // The bytes of the points and the tree.
  [[nodiscard]] double memory_bytes() const;

 private:
  struct Index;
  std::shared_ptr<const Index> index_;
};

// The squared Euclidean distance as the tree computes it: (a_i - b_i)^2 summed from i = 0
// up, so that a brute-force search with it finds exactly the tree's numbers.
[[nodiscard]] double squared_distance(std::span<const double> a, std::span<const double> b);

}  // namespace esc::evo::qd
