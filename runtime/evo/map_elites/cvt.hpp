#pragma once
// CVT-MAP-Elites' cells (Vassiliades, Chatzilygeroudis & Mouret 2018, IEEE TEVC 22(4)): k
// centroids spread evenly over the descriptor space by a centroidal Voronoi tessellation;
// a descriptor belongs to the cell of its nearest centroid, so the number of cells is set
// by hand whatever the number of descriptors.
//
// The centroids are computed once, in unit coordinates (each descriptor scaled by its
// declared range, DescriptorSpace), by Lloyd's k-means over uniform samples, as the paper
// and pyribs do: `samples` points drawn uniformly in the unit cube from the Rng given
// (coordinate after coordinate, sample after sample), the first k of them as the initial
// centroids (pyribs' init="random": i.i.d. samples make the first k as random as any k),
// then Lloyd iterations (assign every sample to its nearest centroid; move each centroid to
// the mean of its samples; a centroid with no sample stays) until no assignment changes, the
// centroids move less than scikit-learn's tolerance (sum of squared shifts <= 1e-4 times the
// mean per-coordinate variance of the samples), or `iterations` have run. An archive
// stores its centroids with its state, so a resumed run never depends on recomputing them.
#include <cstddef>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/evo/map_elites/point_tree.hpp"

namespace esc::evo::qd {

struct CvtSettings {
  // pyribs' CVTArchive default (100,000); Vassiliades et al. note that more samples give a
  // better approximation of the CVT.
  std::size_t samples = 100'000;
  // scikit-learn's k_means default max_iter, which pyribs uses.
  std::size_t iterations = 300;
};

inline constexpr std::size_t kMaxCvtSamples = 10'000'000;

class Cvt {
 public:
  // k centroids over `dims` descriptors. Throws std::invalid_argument naming the setting:
  // "cells" (k from 1 to samples), "descriptors" (1 to 1024), "samples" (up to 10^7),
  // "iterations" (at least 1).
  [[nodiscard]] static Cvt compute(std::size_t dims, std::size_t k, Rng& rng, const CvtSettings& settings = {});

  // Given centroids in unit coordinates, row after row (a stored state, a shared file).
  // Throws std::invalid_argument for none, a count that is not whole points, or a coordinate
  // outside [0, 1].
  Cvt(std::vector<double> centroids, std::size_t dims);

  [[nodiscard]] std::size_t cells() const noexcept { return tree_.size(); }
  [[nodiscard]] std::size_t dims() const noexcept { return tree_.dims(); }
  [[nodiscard]] std::span<const double> centroid(std::size_t cell) const { return tree_.point(cell); }
  // Every centroid, row after row.
  [[nodiscard]] std::vector<double> centroids() const;
  // The cell of the nearest centroid to a descriptor in unit coordinates; among equally near
  // centroids the lowest index.
  [[nodiscard]] std::size_t cell_of(std::span<const double> unit) const { return tree_.nearest_one(unit); }
  [[nodiscard]] double memory_bytes() const { return tree_.memory_bytes(); }

  friend bool operator==(const Cvt& a, const Cvt& b) { return a.dims() == b.dims() && a.centroids() == b.centroids(); }

 private:
  PointTree tree_;
};

}  // namespace esc::evo::qd
