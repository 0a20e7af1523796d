#pragma once
// Novelty search's archive and score (Lehman & Stanley, "Abandoning objectives: evolution
// through the search for novelty alone", Evolutionary Computation 19(2), 2011). An
// individual's novelty is the mean distance from its behavior to its k nearest neighbours
// among the current population (itself excluded) and the archive of past novel behaviors:
//
//   novelty(x) = (1/k) sum_{j=1..k} dist(x, mu_j)
//
// with dist the Euclidean distance between descriptors in unit coordinates, each descriptor
// scaled by its declared range (descriptor_space.hpp; a value outside its range counts as
// the bound). The paper's maze uses the robot's raw final (x, y); both coordinates share one
// range there, and dividing every distance by one width changes no ranking, so the scores
// order a population as the paper's do (the thresholds below are converted to this scale).
// With fewer than k other points, the mean is over those there are; with none, 0.
//
// The k nearest come from one nanoflann kd-tree over population + archive built per call:
// O((n + m) log(n + m)) instead of the O(n (n + m)) of comparing every pair.
//
// After scoring, update() adds behaviors to the archive, by mode:
//  - threshold (the paper): every individual whose novelty exceeds the threshold rho_min.
//    The threshold adapts as in the authors' maze code (noveltyset.h, add_pending(), in
//    github.com/jal278/novelty-search-cpp): after stall_generations updates in a row that add
//    nothing it is multiplied by lower_factor, never below threshold_floor; an update that
//    adds more than raise_above multiplies it by raise_factor.
//  - random: every individual with probability random_probability (one rng.uniform() each,
//    in order), the threshold untouched.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/evo/map_elites/descriptor_space.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/evo/state_bytes.hpp"

namespace esc::evo::qd {

enum class NoveltyMode : std::uint8_t { Threshold, Random };

// Defaults: the authors' maze runs (novelty-search-cpp: noveltyset.h, noveltyexp.cpp,
// maze.ne; population 250), thresholds divided by the maze's 200-unit width for unit
// coordinates. docs/quality-diversity.md has the derivations.
struct NoveltySettings {
  std::size_t k = 15;                    // neighbors = 15
  NoveltyMode mode = NoveltyMode::Threshold;
  double threshold = 0.03;               // archive_thresh = 6.0 maze units / 200
  double threshold_floor = 0.00125;      // novelty_floor = 0.25 / 200
  double raise_factor = 1.2;             // "raised by 20%"
  std::size_t raise_above = 4;           // "if over four are added"
  double lower_factor = 0.95;            // "lowered by 5%"
  std::size_t stall_generations = 10;    // time_out == 10 (the paper's 2,500 evaluations at 250 each)
  double random_probability = 0.001;     // add_to_novelty_archive() in jal278/mazerobot-python
};

class NoveltyArchive {
 public:
  // Throws std::invalid_argument naming the setting out of range.
  NoveltyArchive(const NoveltySettings& settings, DescriptorSpace space);

  // The novelty of each individual of the population, by their descriptors. Throws
  // std::invalid_argument for a descriptor of another size or not finite.
  [[nodiscard]] std::vector<double> scores(std::span<const std::vector<double>> population) const;
  // Adds individuals to the archive by the mode, from their descriptors and the novelty
  // scores() gave them, and adapts the threshold; returns how many it added.
  std::size_t update(std::span<const std::vector<double>> population, std::span<const double> novelty, Rng& rng);

  [[nodiscard]] double threshold() const noexcept { return threshold_; }
  [[nodiscard]] std::size_t size() const noexcept { return points_.size(); }
  // The archived descriptors, as evaluated, in the order they were added.
  [[nodiscard]] const std::vector<std::vector<double>>& points() const noexcept { return points_; }
  [[nodiscard]] const NoveltySettings& settings() const noexcept { return s_; }
  [[nodiscard]] const DescriptorSpace& space() const noexcept { return space_; }

  // The archive, threshold and stall count. load() refuses, with std::invalid_argument,
  // other ranges, k or mode and bytes it could not have written, and then leaves the
  // archive as it was; the adaptation settings are this object's.
  [[nodiscard]] StateBytes save() const;
  void load(std::span<const std::uint8_t> bytes);

 private:
  NoveltySettings s_;
  DescriptorSpace space_;
  std::vector<std::vector<double>> points_;
  double threshold_;
  std::size_t stalled_ = 0;  // updates in a row that added nothing
};

// The archive's behaviors from the `from`-th added on (0: all of it; the size before a
// generation's update: that generation's changes), as an optimizer's members: an archive of
// points, each its order of addition as its cell, without objectives or genome.
[[nodiscard]] Members behavior_members(const NoveltyArchive& archive, std::size_t from);

}  // namespace esc::evo::qd
