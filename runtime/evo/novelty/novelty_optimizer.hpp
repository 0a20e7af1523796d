#pragma once
// Novelty search (Lehman & Stanley 2011) as an Optimizer of a network's weights or of trees
// (with the GP's operators, as NSGA-II breeds them: nsga2_optimizer.hpp): NSGA-II's
// selection and variation (nsga2.hpp) on one objective, the novelty of each controller's
// descriptors (novelty_archive.hpp), or on two, novelty and the fitness (Mouret's
// "novelty-based multiobjectivization", as the issue asks: `objectives novelty_fitness`).
//
// Novelty depends on the archive, which grows: at every tell, the parents and the new
// candidates are scored together against the archive (each one's k nearest among both and
// the archive), the candidates' novelty decides which of them enter the archive, and the
// parents' scores are replaced by their new ones (Nsga2::rescore) before survival. The
// random draws of the archive's random mode come from Rng(seed, Breed, g, 1), apart from the
// generation's variation stream.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/novelty/novelty_archive.hpp"
#include "runtime/evo/novelty/novelty_options.hpp"
#include "runtime/evo/nsga2/nsga2.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

struct NoveltyRunSettings {
  bool with_fitness = false;    // objectives: novelty alone, or novelty and the fitness
  int k = 15;
  bool random_archive = false;  // archive: by threshold (adapted), or at random
  double threshold = 0.03;      // in descriptor units scaled to [0, 1] (novelty_archive.hpp)
  double random_probability = 0.001;
  // NSGA-II's (nsga2.hpp), flat so that options name them as NSGA-II's do.
  int population = 100;
  double crossover = 0.9;
  double eta_crossover = 20.0;
  double eta_mutation = 20.0;
  double mutation = 0.0;
  double lower = -1.0;
  double upper = 1.0;
};

[[nodiscard]] Nsga2Settings variation_of(const NoveltyRunSettings& settings);

[[nodiscard]] std::unique_ptr<Optimizer> make_novelty(const NoveltyRunSettings& settings, const Problem& problem);
[[nodiscard]] std::size_t novelty_population(const NoveltyRunSettings& settings, const Problem& problem);
// What one run holds while a tell scores and ranks: NSGA-II's memory (nsga2_memory_bytes)
// with its one or two objectives; the descriptors of parents and children, copied, and the
// parents' kept; the kd-tree over them and the archive, an archive of one generation's
// candidates (the first generation's update can archive them all; what a long run archives
// later is not counted).
[[nodiscard]] MemoryPeak novelty_memory_peak(const NoveltyRunSettings& settings, const Problem& problem);
// Why the settings cannot run on `problem` (no descriptors, ...), or "".
[[nodiscard]] std::string novelty_problem(const NoveltyRunSettings& settings, const Problem& problem);

// Novelty search as the registry holds it (registry.hpp): its name, the genomes it evolves,
// and how its settings make an optimizer, size a generation, weigh in memory and read in
// scripts.
struct NoveltyAlgorithm {
  using Settings = NoveltyRunSettings;
  std::string_view name = "novelty";
  std::string_view what = "novelty search";
  genome::GenomeKinds kinds{genome::GenomeKind::Vector, genome::GenomeKind::Tree, genome::GenomeKind::Graph};
  std::uint32_t state_format = 1;

  [[nodiscard]] std::unique_ptr<Optimizer> make(const Settings& s, const Problem& p) const { return make_novelty(s, p); }
  [[nodiscard]] std::size_t population(const Settings& s, const Problem& p) const { return novelty_population(s, p); }
  [[nodiscard]] MemoryPeak memory(const Settings& s, const Problem& p, int /*generations*/) const {
    return novelty_memory_peak(s, p);
  }
  [[nodiscard]] const std::vector<AlgorithmOption>& options() const { return novelty_options(); }
  [[nodiscard]] std::string problem(const Settings& s, const Problem& p) const { return novelty_problem(s, p); }
};

}  // namespace esc::evo
