#pragma once
// The archive of MAP-Elites (Mouret & Clune 2015) and CVT-MAP-Elites (Vassiliades et al.
// 2018): one elite per cell, the cell found from the behavior descriptor by a grid or a CVT
// (grid.hpp, cvt.hpp) over the declared descriptor ranges (descriptor_space.hpp). It stores
// genomes of any length, so a GP tree encoded as doubles fits as a network's weights do;
// how new genomes are made is not its business (selection.hpp, iso_line_dd.hpp).
//
// insert() puts a candidate in its cell when the cell is empty or the candidate is strictly
// fitter than the incumbent; a tie keeps the incumbent (pymap_elites' rule), and a fitness
// that is not a finite number is rejected, as CMA-ES ranks NaN last.
//
// The QD-score is the sum over filled cells of (fitness - fitness_offset), with the offset a
// lower bound of the fitness that the caller declares (pyribs' qd_score_offset), so that
// filling a cell never lowers it; a fitness below the offset (the bound was wrong) counts
// 0, so the score still never decreases. The sum saturates at the largest double, so that
// it stays finite (and never decreases) whatever fitnesses far outside the declared range
// the elites hold. Coverage is filled / cells.
//
// Every change since the last take_changes() (cell and its new elite, one per cell, in cell
// order) can be stored per generation, and replay() rebuilds the archive of any generation
// from them.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "runtime/evo/map_elites/cvt.hpp"
#include "runtime/evo/map_elites/descriptor_space.hpp"
#include "runtime/evo/map_elites/grid.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/evo/state_bytes.hpp"

namespace esc::evo::qd {

struct Elite {
  Genome genome;
  double fitness = 0.0;
  std::vector<double> descriptor;  // as evaluated, before clamping to the ranges
  friend bool operator==(const Elite&, const Elite&) = default;
};

enum class Insertion : std::uint8_t { NewCell, Improved, Rejected };

struct InsertResult {
  Insertion status = Insertion::Rejected;
  std::size_t cell = 0;
  friend bool operator==(const InsertResult&, const InsertResult&) = default;
};

// A cell's new elite.
struct Change {
  std::size_t cell = 0;
  Elite elite;
  friend bool operator==(const Change&, const Change&) = default;
};

using Tessellation = std::variant<Grid, Cvt>;

class Archive {
 public:
  // Throws std::invalid_argument when the tessellation has another number of descriptors
  // than the space ("bins" or "cells"), or the offset is not finite ("fitness_offset").
  Archive(DescriptorSpace space, Tessellation tessellation, double fitness_offset);

  // Throws std::invalid_argument for an empty genome or one with a value that is not
  // finite, and for a descriptor of another size or not finite.
  InsertResult insert(Genome genome, double fitness, std::span<const double> descriptor);
  [[nodiscard]] std::size_t cell_of(std::span<const double> descriptor) const;

  [[nodiscard]] std::size_t cells() const noexcept { return slots_.size(); }
  [[nodiscard]] std::size_t filled() const noexcept { return filled_.size(); }
  // The cell's elite, or null while it is empty; std::out_of_range beyond cells().
  [[nodiscard]] const Elite* elite(std::size_t cell) const;
  // The filled cells in increasing order.
  [[nodiscard]] std::span<const std::size_t> filled_cells() const noexcept { return filled_; }
  [[nodiscard]] double qd_score() const;
  [[nodiscard]] double coverage() const noexcept;
  // The best fitness of any elite; none while the archive is empty.
  [[nodiscard]] std::optional<double> best() const;

  [[nodiscard]] const DescriptorSpace& space() const noexcept { return space_; }
  [[nodiscard]] const Tessellation& tessellation() const noexcept { return tessellation_; }
  [[nodiscard]] double fitness_offset() const noexcept { return offset_; }

  // The changes since the last call, one per cell (its elite now), in cell order.
  [[nodiscard]] std::vector<Change> take_changes();
  // Puts a stored change back: the cell gets that elite whatever it held. Throws
  // std::invalid_argument when the elite could not be in that cell.
  void apply(const Change& change);

  // The whole archive: space, tessellation (a CVT's centroids included), offset, elites and
  // the changes not yet taken. load() takes a state of an archive of the same kind, ranges,
  // number of cells (bins, or k) and offset, a CVT's centroids from the bytes; anything else
  // throws std::invalid_argument and leaves the archive as it was.
  [[nodiscard]] StateBytes save() const;
  void load(std::span<const std::uint8_t> bytes);
  // The same, inside a larger state (MapElites).
  void write(StateWriter& w) const;
  [[nodiscard]] Archive read_like(StateReader& r) const;

  // The bytes it holds now (vectors' capacities, the kd-tree), without allocator overhead.
  [[nodiscard]] double memory_bytes() const;

 private:
  void put(std::size_t cell, Elite elite);
  void check_elite(const Elite& e) const;

  DescriptorSpace space_;
  Tessellation tessellation_;
  double offset_;
  std::vector<std::optional<Elite>> slots_;
  std::vector<std::size_t> filled_;        // increasing
  std::vector<std::size_t> changed_;       // since take_changes, in no order
  std::vector<std::uint8_t> is_changed_;   // per cell
};

// An upper bound of what an archive of `cells` cells holds once `filled` of them hold an
// elite of a genome of `genome_size` doubles and `descriptors` descriptors, allocator
// overhead and a CVT's centroids and kd-tree included (`cvt`); a run checks it against the
// memory it may use before it starts.
[[nodiscard]] double archive_memory_bytes(std::size_t cells, std::size_t genome_size, std::size_t descriptors,
                                          double filled, bool cvt);

// `base` with `changes` applied in order: the archive of a generation, from the archive
// before it (an empty one for the first) and the changes taken after each generation.
[[nodiscard]] Archive replay(Archive base, std::span<const Change> changes);

}  // namespace esc::evo::qd
