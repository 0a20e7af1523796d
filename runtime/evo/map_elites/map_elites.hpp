#pragma once
// MAP-Elites (Mouret & Clune 2015) for a network's weights in a box, as an ask/tell value
// type over a grid or CVT archive (archive.hpp): the first generation is `initial` genomes
// drawn uniformly in [lower, upper]; every later one is `batch` children, each made by
// Iso+LineDD (iso_line_dd.hpp, Vassiliades & Mouret 2018) from two elites drawn uniformly
// and independently from the filled cells (selection.hpp), then clipped to the box. While
// the archive is still empty (every candidate so far rejected) a generation is `initial`
// uniform genomes again.
//
// Over trees (MapElitesGenomes from genome/tree/tree_variation.hpp) the first generation is
// `initial` trees by ramped half-and-half and every child one elite drawn uniformly, then
// one of the GP's mutations; over NEAT networks (genome/graph/graph_variation.hpp), copies
// of NEAT's start, then NEAT's mutation of one elite; sigma_iso, sigma_line and the box are
// not used.
//
// Every random draw comes from the Rng given to ask(), in a fixed order: uniform genomes
// coordinate by coordinate; or per child, the two parents' draws, then Iso+LineDD's. A caller
// gives ask() the generation's own stream, so a state saved after a tell and loaded into a
// fresh MapElites of the same settings asks for what the uninterrupted one would.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "runtime/core/rng.hpp"
#include "runtime/evo/map_elites/archive.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/genome/representation.hpp"
#include "runtime/evo/state_bytes.hpp"

namespace esc::evo::qd {

inline constexpr std::size_t kMaxMapElitesBatch = 1'000'000;

struct MapElitesSettings {
  // Children per generation: pymap_elites' batch_size (100), the batch of its authors'
  // CVT-MAP-Elites and Iso+LineDD code.
  std::size_t batch = 100;
  // Uniform genomes of the first generation: one batch. pymap_elites draws batches of 100
  // until 10 % of the cells are filled; a run here sets it to that many when it wants it.
  std::size_t initial = 100;
  // Iso+LineDD's sigma_1 = 0.01 and sigma_2 = 0.2 (Vassiliades & Mouret 2018; pymap_elites'
  // iso_sigma and line_sigma, on genomes in [0, 1]); sigma_iso is a fraction of the box
  // width upper - lower, so the default is the paper's step whatever the box.
  double sigma_iso = 0.01;
  double sigma_line = 0.2;
  double lower = -1.0;  // every genome lies in [lower, upper], in each coordinate
  double upper = 1.0;
};

// What MAP-Elites' genomes are: the first ones and the check of a stored one, and how a
// child is made from the archive (drawing from the Rng given).
struct MapElitesGenomes {
  std::shared_ptr<const genome::Representation> representation;
  std::function<Genome(const Archive&, Rng&)> child;
  // When set, shown the archive before a generation's children are bred from it (graph
  // genomes number their new structure past the elites': graph_variation.hpp).
  std::function<void(const Archive&)> begin = {};
};

class MapElites {
 public:
  // The archive may hold elites already (a seeded run), of genome_size each. Throws
  // std::invalid_argument naming the setting out of range ("batch", "initial", "sigma_iso",
  // "sigma_line", "lower", "upper", "genome size") or for an elite of another size.
  MapElites(const MapElitesSettings& settings, std::size_t genome_size, Archive archive);
  // Over other genomes (trees); an elite that is not one of them is refused.
  MapElites(const MapElitesSettings& settings, MapElitesGenomes genomes, Archive archive);

  // A given genome (`start from`) becomes candidate 0 of the next ask, unchanged. Throws
  // std::invalid_argument for another size or a value outside [lower, upper].
  void start(std::span<const double> genome);

  // This generation's candidates. Any ask replaces one not yet told.
  [[nodiscard]] std::vector<Genome> ask(Rng& rng);
  // What the last ask's candidates measured, in their order: each goes into the archive.
  // std::logic_error without an ask; std::invalid_argument for other counts or a descriptor
  // of another size or not finite (checked before anything is inserted). Returns what became
  // of each candidate, in their order.
  std::vector<InsertResult> tell(std::span<const double> fitness, std::span<const std::vector<double>> descriptors);

  [[nodiscard]] double qd_score() const { return archive_.qd_score(); }
  [[nodiscard]] double coverage() const noexcept { return archive_.coverage(); }
  [[nodiscard]] std::optional<double> best() const { return archive_.best(); }
  [[nodiscard]] const Archive& archive() const noexcept { return archive_; }
  // The archive's changes since the last call (Archive::take_changes).
  [[nodiscard]] std::vector<Change> take_changes() { return archive_.take_changes(); }
  [[nodiscard]] std::uint64_t generation() const noexcept { return generation_; }
  [[nodiscard]] const MapElitesSettings& settings() const noexcept { return s_; }

  // Everything between generations (after a tell, or as made): settings to check, the
  // generation count, a start genome not yet asked, the archive. load() refuses, with
  // std::invalid_argument, another genome size or setting, another archive (Archive::load)
  // and bytes it could not have written, and then leaves this object as it was. Over trees
  // the format is "esc-map-elites-trees" (genome size 0, no box) and every elite is checked
  // against the primitive set and the GP's limits; a state of the other representation is
  // refused by name.
  [[nodiscard]] StateBytes save() const;
  void load(std::span<const std::uint8_t> bytes);

 private:
  void write(StateWriter& w) const;
  [[nodiscard]] std::string misfit_elite(const Archive& archive) const;

  MapElitesSettings s_;
  MapElitesGenomes g_;
  std::size_t n_;
  Archive archive_;
  std::uint64_t generation_ = 0;
  Genome first_;                  // a start genome, until asked
  std::vector<Genome> pending_;   // the last ask, until told
  bool asked_ = false;
};

// What a MapElites holds at most, in bytes: its archive with `filled` elites
// (archive_memory_bytes) and one generation's candidates twice (asked, and handed out) with
// their descriptors told.
[[nodiscard]] double map_elites_memory_bytes(const MapElitesSettings& settings, std::size_t genome_size, std::size_t cells,
                                             std::size_t descriptors, double filled, bool cvt);

}  // namespace esc::evo::qd
