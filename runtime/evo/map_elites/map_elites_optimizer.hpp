#pragma once
// MAP-Elites (map_elites.hpp) as an Optimizer of a network's weights, or of trees with the
// GP's mutations (genome/tree/tree_variation.hpp, settings from problem.tree.operators; genomes
// encoded), registered twice:
// `map_elites` over a grid of `bins` cells per descriptor (1 to 3 descriptors), and
// `cvt_map_elites` over `cells` centroids of a CVT of the descriptor space (any number of
// descriptors). The fitness is the Outcome's first objective, the cell its descriptors
// within their declared ranges; the QD-score counts each elite's fitness above the fitness's
// declared lower bound, which both therefore need (`fitness F in [lo, hi]`).
//
// The CVT's centroids are drawn from a stream of their own, Rng(kCvtStream), not from the
// run's seed: every run of an experiment shares one tessellation, so that archives of
// different runs compare cell by cell. They are computed once per process for each (number
// of descriptors, cells, samples) and stored in every run's state.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/map_elites/map_elites.hpp"
#include "runtime/evo/map_elites/map_elites_options.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

inline constexpr std::uint64_t kCvtStream = 2000;   // apart from rng.hpp's Streams

// What scripts set (map_elites_options.hpp); `cvt` is fixed by the algorithm's name.
struct MapElitesRunSettings {
  bool cvt = false;
  int bins = 10;           // grid: cells per descriptor
  int cells = 1000;        // CVT: centroids
  int samples = 100'000;   // CVT: uniform samples its k-means runs on
  int batch = 100;
  int initial = 100;
  double sigma_iso = 0.01;
  double sigma_line = 0.2;
  double lower = -1.0;
  double upper = 1.0;
};

[[nodiscard]] std::unique_ptr<Optimizer> make_map_elites(const MapElitesRunSettings& settings, const Problem& problem);
// Candidates of the first generation: `initial`.
[[nodiscard]] std::size_t map_elites_population(const MapElitesRunSettings& settings, const Problem& problem);
// What a run of `generations` holds at its peak (qd::map_elites_memory_bytes): the archive's
// cells, as many of them filled as the run evaluates candidates (all, at most), with where
// each elite was measured; a generation's candidates; a CVT's k-means samples.
[[nodiscard]] MemoryPeak map_elites_memory_peak(const MapElitesRunSettings& settings, const Problem& problem,
                                                int generations);
// Why the settings cannot run on `problem` (no declared fitness range, no descriptors, more
// than 3 for a grid, too many cells, ...), or "".
[[nodiscard]] std::string map_elites_problem(const MapElitesRunSettings& settings, const Problem& problem);

// MAP-Elites as the registry holds it (registry.hpp), twice: its grid archive under
// `map_elites`, and CVT-MAP-Elites (Vassiliades et al. 2018) under `cvt_map_elites`, the same
// value with the other name, options and defaults (a CVT archive), so that both share every
// line of code and keep their own names in scripts and stored states.
struct MapElitesAlgorithm {
  using Settings = MapElitesRunSettings;
  std::string_view name = "map_elites";
  std::string_view what = "MAP-Elites";
  bool cvt = false;   // its archive: a grid, or a CVT's cells
  genome::GenomeKinds kinds{genome::GenomeKind::Vector, genome::GenomeKind::Tree, genome::GenomeKind::Graph};
  std::uint32_t state_format = 1;

  // CVT-MAP-Elites.
  [[nodiscard]] static MapElitesAlgorithm centroidal() {
    return {.name = "cvt_map_elites", .what = "CVT-MAP-Elites", .cvt = true};
  }

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const {
    return make_map_elites(s, p);
  }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const { return map_elites_population(s, p); }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int generations) const {
    return map_elites_memory_peak(s, p, generations);
  }
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const {
    return cvt ? cvt_map_elites_options() : map_elites_options();
  }
  [[nodiscard]] Settings defaults() const {
    Settings s;
    s.cvt = cvt;
    return s;
  }
  [[nodiscard]] std::string problem(const Settings& s, const Problem& p) const { return map_elites_problem(s, p); }
};

}  // namespace esc::evo
