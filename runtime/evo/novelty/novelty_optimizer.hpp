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
#include <memory>
#include <string>

#include "runtime/evo/novelty/novelty_archive.hpp"
#include "runtime/evo/nsga2/nsga2.hpp"
#include "runtime/evo/optimizer.hpp"

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

}  // namespace esc::evo
