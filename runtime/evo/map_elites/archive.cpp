#include "runtime/evo/map_elites/archive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace esc::evo::qd {

namespace {

constexpr std::string_view kFormat = "esc-qd-archive";
constexpr std::uint32_t kVersion = 1;
constexpr std::uint8_t kGrid = 0;
constexpr std::uint8_t kCvt = 1;

// glibc's malloc: a chunk header and 16-byte alignment per allocation (a genome, a
// descriptor).
constexpr double kHeapOverhead = 16.0;

bool all_finite(std::span<const double> v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

std::size_t dims_of(const Tessellation& t) {
  return std::visit([](const auto& cells) { return cells.dims(); }, t);
}

std::size_t cells_of(const Tessellation& t) {
  return std::visit([](const auto& cells) { return cells.cells(); }, t);
}

[[noreturn]] void refuse(const std::string& why) { throw std::invalid_argument("archive state: " + why); }

}  // namespace

Archive::Archive(DescriptorSpace space, Tessellation tessellation, double fitness_offset)
    : space_(std::move(space)), tessellation_(std::move(tessellation)), offset_(fitness_offset) {
  if (dims_of(tessellation_) != space_.size())
    throw std::invalid_argument(std::string(std::holds_alternative<Grid>(tessellation_) ? "bins" : "cells") + ": " +
                                std::to_string(dims_of(tessellation_)) + " descriptors, the ranges declare " +
                                std::to_string(space_.size()));
  if (!std::isfinite(offset_)) throw std::invalid_argument("fitness_offset: not a finite number");
  slots_.resize(cells_of(tessellation_));
  is_changed_.resize(slots_.size());
}

std::size_t Archive::cell_of(std::span<const double> descriptor) const {
  const std::vector<double> unit = space_.to_unit(descriptor);
  return std::visit([&](const auto& cells) { return cells.cell_of(unit); }, tessellation_);
}

void Archive::check_elite(const Elite& e) const {
  if (e.genome.empty()) throw std::invalid_argument("genome: empty");
  if (!all_finite(e.genome)) throw std::invalid_argument("genome: a value that is not a finite number");
  if (e.descriptor.size() != space_.size() || !all_finite(e.descriptor))
    throw std::invalid_argument("descriptor: " + std::to_string(space_.size()) + " finite numbers expected");
}

InsertResult Archive::insert(Genome genome, double fitness, std::span<const double> descriptor) {
  Elite candidate{std::move(genome), fitness, {descriptor.begin(), descriptor.end()}};
  check_elite(candidate);
  const std::size_t cell = cell_of(descriptor);
  const std::optional<Elite>& incumbent = slots_[cell];
  if (!std::isfinite(fitness) || (incumbent && !(fitness > incumbent->fitness))) return {Insertion::Rejected, cell};
  const Insertion status = incumbent ? Insertion::Improved : Insertion::NewCell;
  put(cell, std::move(candidate));
  return {status, cell};
}

void Archive::put(std::size_t cell, Elite elite) {
  if (!slots_[cell]) filled_.insert(std::lower_bound(filled_.begin(), filled_.end(), cell), cell);
  slots_[cell] = std::move(elite);
  if (!is_changed_[cell]) {
    is_changed_[cell] = 1;
    changed_.push_back(cell);
  }
}

const Elite* Archive::elite(std::size_t cell) const {
  if (cell >= slots_.size()) throw std::out_of_range("archive: cell " + std::to_string(cell) + " of " + std::to_string(slots_.size()));
  return slots_[cell] ? &*slots_[cell] : nullptr;
}

double Archive::qd_score() const {
  double score = 0.0;
  constexpr double largest = std::numeric_limits<double>::max();
  for (const std::size_t cell : filled_)
    score = std::min(score + std::max(0.0, slots_[cell]->fitness - offset_), largest);
  return score;
}

double Archive::coverage() const noexcept {
  return static_cast<double>(filled_.size()) / static_cast<double>(slots_.size());
}

std::optional<double> Archive::best() const {
  std::optional<double> best;
  for (const std::size_t cell : filled_)
    if (!best || slots_[cell]->fitness > *best) best = slots_[cell]->fitness;
  return best;
}

std::vector<Change> Archive::take_changes() {
  std::sort(changed_.begin(), changed_.end());
  std::vector<Change> changes;
  changes.reserve(changed_.size());
  for (const std::size_t cell : changed_) {
    changes.push_back({cell, *slots_[cell]});
    is_changed_[cell] = 0;
  }
  changed_.clear();
  return changes;
}

void Archive::apply(const Change& change) {
  check_elite(change.elite);
  if (change.cell >= slots_.size() || cell_of(change.elite.descriptor) != change.cell)
    throw std::invalid_argument("change: the elite's descriptor does not lie in cell " + std::to_string(change.cell));
  if (!std::isfinite(change.elite.fitness)) throw std::invalid_argument("change: the elite's fitness is not finite");
  put(change.cell, change.elite);
}

void Archive::write(StateWriter& w) const {
  w.put(std::string(kFormat));
  w.put(kVersion);
  w.put(std::holds_alternative<Grid>(tessellation_) ? kGrid : kCvt);
  w.put(static_cast<std::uint64_t>(space_.size()));
  for (const Range& r : space_.ranges()) {
    w.put(r.lower);
    w.put(r.upper);
  }
  if (const auto* grid = std::get_if<Grid>(&tessellation_)) {
    for (const std::size_t b : grid->bins()) w.put(static_cast<std::uint64_t>(b));
  } else {
    w.put(std::span<const double>(std::get<Cvt>(tessellation_).centroids()));
  }
  w.put(offset_);
  w.put(static_cast<std::uint64_t>(filled_.size()));
  for (const std::size_t cell : filled_) {
    const Elite& e = *slots_[cell];
    w.put(static_cast<std::uint64_t>(cell));
    w.put(e.fitness);
    w.put(std::span<const double>(e.genome));
    w.put(std::span<const double>(e.descriptor));
  }
  std::vector<std::size_t> changed = changed_;
  std::sort(changed.begin(), changed.end());
  w.put(static_cast<std::uint64_t>(changed.size()));
  for (const std::size_t cell : changed) w.put(static_cast<std::uint64_t>(cell));
}

Archive Archive::read_like(StateReader& r) const {
  if (r.text() != kFormat) refuse("not a quality-diversity archive");
  if (const auto v = r.get<std::uint32_t>(); v != kVersion)
    refuse("format version " + std::to_string(v) + ", expected " + std::to_string(kVersion));
  const bool grid = std::holds_alternative<Grid>(tessellation_);
  if (r.get<std::uint8_t>() != (grid ? kGrid : kCvt))
    refuse(std::string("saved by another kind of archive, this one is a ") + (grid ? "grid" : "CVT"));
  if (r.get<std::uint64_t>() != space_.size()) refuse("saved with another number of descriptors");
  for (const Range& range : space_.ranges()) {
    const double lower = r.get<double>();
    const double upper = r.get<double>();
    if (!(Range{lower, upper} == range)) refuse("saved with other descriptor ranges");
  }
  Archive next(space_, tessellation_, offset_);
  if (grid) {
    for (const std::size_t b : std::get<Grid>(tessellation_).bins())
      if (r.get<std::uint64_t>() != b) refuse("saved with other bins");
  } else {
    std::vector<double> centroids = r.doubles();
    if (centroids.size() != cells() * space_.size()) refuse("saved with another number of cells");
    try {
      next.tessellation_ = Cvt(std::move(centroids), space_.size());
    } catch (const std::invalid_argument& e) {
      refuse(e.what());
    }
  }
  if (r.get<double>() != offset_) refuse("saved with another fitness_offset");

  const std::size_t filled = r.count(8);
  for (std::size_t i = 0; i < filled; ++i) {
    const auto cell = r.get<std::uint64_t>();
    Elite e;
    e.fitness = r.get<double>();
    e.genome = r.doubles();
    e.descriptor = r.doubles();
    if (cell >= cells() || (!next.filled_.empty() && cell <= next.filled_.back())) refuse("cells out of order or range");
    if (!std::isfinite(e.fitness)) refuse("a fitness that is not a finite number");
    try {
      next.apply({static_cast<std::size_t>(cell), std::move(e)});
    } catch (const std::invalid_argument& ex) {
      refuse(ex.what());
    }
  }
  // apply() marked every elite as changed: the saved list says which were.
  for (const std::size_t cell : next.changed_) next.is_changed_[cell] = 0;
  next.changed_.clear();
  const std::size_t changed = r.count(8);
  for (std::size_t i = 0; i < changed; ++i) {
    const auto cell = r.get<std::uint64_t>();
    if (cell >= cells() || !next.slots_[cell] || (!next.changed_.empty() && cell <= next.changed_.back()))
      refuse("a changed cell out of order or empty");
    next.changed_.push_back(cell);
    next.is_changed_[cell] = 1;
  }
  return next;
}

StateBytes Archive::save() const {
  StateWriter w;
  write(w);
  return std::move(w).take();
}

void Archive::load(std::span<const std::uint8_t> bytes) {
  StateReader r(bytes);
  Archive next = read_like(r);
  r.finish();
  *this = std::move(next);
}

double Archive::memory_bytes() const {
  double bytes = static_cast<double>(slots_.capacity() * sizeof(std::optional<Elite>) +
                                     (filled_.capacity() + changed_.capacity()) * sizeof(std::size_t) +
                                     is_changed_.capacity());
  for (const std::size_t cell : filled_)
    bytes += static_cast<double>((slots_[cell]->genome.capacity() + slots_[cell]->descriptor.capacity()) * sizeof(double));
  if (const auto* cvt = std::get_if<Cvt>(&tessellation_)) bytes += cvt->memory_bytes();
  return bytes;
}

double archive_memory_bytes(std::size_t cells, std::size_t genome_size, std::size_t descriptors, double filled,
                            bool cvt) {
  const double slot = sizeof(std::optional<Elite>) + 1.0;   // slot, changed flag
  // Genome and descriptor, and the filled cell in the two lists of cells.
  const double elite =
      static_cast<double>(genome_size + descriptors) * sizeof(double) + 2.0 * kHeapOverhead + 2.0 * sizeof(std::size_t);
  const double centroid = cvt ? static_cast<double>(descriptors) * sizeof(double) + kTreeBytesPerPoint : 0.0;
  return static_cast<double>(cells) * (slot + centroid) + std::min(filled, static_cast<double>(cells)) * elite;
}

Archive replay(Archive base, std::span<const Change> changes) {
  for (const Change& c : changes) base.apply(c);
  return base;
}

}  // namespace esc::evo::qd
