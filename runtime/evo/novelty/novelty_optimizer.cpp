#include "runtime/evo/novelty/novelty_optimizer.hpp"

#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "runtime/genome/genome_size.hpp"
#include "runtime/genome/tree/tree_variation.hpp"
#include "runtime/evo/map_elites/point_tree.hpp"
#include "runtime/evo/measured_state.hpp"
#include "runtime/evo/nsga2/nsga2_optimizer.hpp"
#include "runtime/evo/run_streams.hpp"

namespace esc::evo {

Nsga2Settings variation_of(const NoveltyRunSettings& s) {
  return {s.population, s.crossover, s.eta_crossover, s.eta_mutation, s.mutation, s.lower, s.upper};
}

namespace {

qd::NoveltySettings archive_settings(const NoveltyRunSettings& s) {
  qd::NoveltySettings a;
  a.k = static_cast<std::size_t>(s.k);
  a.mode = s.random_archive ? qd::NoveltyMode::Random : qd::NoveltyMode::Threshold;
  a.threshold = s.threshold;
  a.random_probability = s.random_probability;
  return a;
}

// 2: each parent's origin (Measured) follows the parents.
constexpr std::uint32_t kVersion = 2;

class NoveltyOptimizer final : public Optimizer {
 public:
  NoveltyOptimizer(const NoveltyRunSettings& settings, const Problem& problem)
      : core_(nsga2_core(variation_of(settings), problem)),
        archive_(archive_settings(settings), qd::descriptor_space_of(problem.descriptors)),
        seed_(problem.seed),
        with_fitness_(settings.with_fitness) {
    start_core(core_, problem);
  }

  std::vector<Genome> ask(int generation) override {
    generation_ = static_cast<std::uint64_t>(generation);
    Rng rng = breed_stream(seed_, generation);
    return core_.ask(rng);
  }

  void tell(std::span<const Outcome> outcomes) override {
    // Parents first, then the candidates: the order of Nsga2::tell's survivors.
    std::vector<std::vector<double>> descriptors = parent_descriptors_;
    std::vector<double> fitness = parent_fitness_;
    for (const Outcome& o : outcomes) {
      descriptors.push_back(o.descriptors);
      fitness.push_back(o.objectives.front());
    }
    const std::vector<double> novelty = archive_.scores(descriptors);
    const std::size_t parents = parent_descriptors_.size();
    const auto objectives_of = [&](std::size_t i) {
      return with_fitness_ ? std::vector<double>{-novelty[i], -fitness[i]} : std::vector<double>{-novelty[i]};
    };
    std::vector<std::vector<double>> now, candidates;
    for (std::size_t i = 0; i < parents; ++i) now.push_back(objectives_of(i));
    for (std::size_t i = parents; i < descriptors.size(); ++i) candidates.push_back(objectives_of(i));

    Rng rng(seed_, {static_cast<std::uint64_t>(Stream::Breed), generation_, 1});
    archived_before_ = archive_.size();
    archive_.update(std::span(descriptors).subspan(parents), std::span(novelty).subspan(parents), rng);
    core_.rescore(now);
    const std::vector<std::size_t> kept = core_.tell(candidates);
    measured_ = survivors_measured(measured_, static_cast<int>(generation_), kept);
    parent_descriptors_.clear();
    parent_fitness_.clear();
    best_novelty_ = 0.0;
    for (const std::size_t i : kept) {
      parent_descriptors_.push_back(descriptors[i]);
      parent_fitness_.push_back(fitness[i]);
      best_novelty_ = std::max(best_novelty_, novelty[i]);
    }
  }

  std::vector<Metric> metrics() const override {
    return {{"archive", static_cast<double>(archive_.size())},
            {"threshold", archive_.threshold()},
            {"novelty_max", best_novelty_}};
  }

  // Novelty and fitness: the first front of the two, with each member's behavior. Novelty
  // alone: its archive of behaviors (where the search has been), which keeps neither genomes
  // nor fitness; a generation's changes are the behaviors it added.
  std::optional<Members> members(bool changes) const override {
    if (!with_fitness_) return qd::behavior_members(archive_, changes ? archived_before_ : 0);
    Members m{MemberKind::Front, 2U, archive_.space().size(), {"novelty"}, {}, {}, {}};
    const std::vector<std::size_t> front = core_.first_front();
    for (std::size_t i = 0; i < front.size(); ++i) {
      const std::vector<double>& f = core_.objectives()[front[i]];
      m.members.push_back({static_cast<std::int64_t>(i), {-f[0], -f[1]}, parent_descriptors_[front[i]],
                           changes ? Genome{} : core_.population()[front[i]], measured_[front[i]]});
    }
    return m;
  }

  StateBytes save() const override {
    StateWriter w;
    w.put(std::string("esc-novelty"));
    w.put(kVersion);
    const StateBytes core = core_.save(), archive = archive_.save();
    w.put(std::span<const std::uint8_t>(core));
    w.put(std::span<const std::uint8_t>(archive));
    w.put(best_novelty_);
    w.put(static_cast<std::uint64_t>(parent_descriptors_.size()));
    for (std::size_t i = 0; i < parent_descriptors_.size(); ++i) {
      w.put(parent_fitness_[i]);
      w.put(std::span<const double>(parent_descriptors_[i]));
    }
    put_measured(w, measured_);
    return std::move(w).take();
  }

  // Everything is read and checked before anything changes: a refused state leaves the
  // optimizer as it was.
  void load(std::span<const std::uint8_t> state) override {
    StateReader r(state);
    // Version 1 kept no origins (measured_state.hpp): its members' are unknown.
    if (r.text() != "esc-novelty")
      throw std::invalid_argument("novelty search: not a state of novelty search");
    const auto version = r.get<std::uint32_t>();
    if (version != 1 && version != kVersion)
      throw std::invalid_argument("novelty search: format version " + std::to_string(version) + ", expected 1 or 2");
    const std::string core = r.text(), archive = r.text();
    const double best = r.get<double>();
    std::vector<std::vector<double>> descriptors(r.count(2 * sizeof(double)));
    std::vector<double> fitness(descriptors.size());
    for (std::size_t i = 0; i < descriptors.size(); ++i) {
      fitness[i] = r.get<double>();
      descriptors[i] = r.doubles();
      if (descriptors[i].size() != archive_.space().size())
        throw std::invalid_argument("novelty search: a parent's descriptors are of another size");
    }
    std::optional<std::vector<Measured>> measured;
    if (version == kVersion) measured = get_measured(r);
    r.finish();
    Nsga2 c = core_;
    c.load(std::span(reinterpret_cast<const std::uint8_t*>(core.data()), core.size()));
    if (c.population().size() != descriptors.size())
      throw std::invalid_argument("novelty search: the state's parents and their descriptors differ in number");
    std::vector<Measured> origins = measured_for(std::move(measured), descriptors.size(), "novelty search", "parents");
    qd::NoveltyArchive a = archive_;
    a.load(std::span(reinterpret_cast<const std::uint8_t*>(archive.data()), archive.size()));
    core_ = std::move(c);
    archive_ = std::move(a);
    archived_before_ = archive_.size();
    best_novelty_ = best;
    parent_descriptors_ = std::move(descriptors);
    parent_fitness_ = std::move(fitness);
    measured_ = std::move(origins);
  }

 private:
  Nsga2 core_;
  qd::NoveltyArchive archive_;
  std::uint64_t seed_;
  bool with_fitness_;
  std::uint64_t generation_ = 0;
  // The archive's size before the last tell added to it (after a load: all of it, as told).
  std::size_t archived_before_ = 0;
  std::vector<std::vector<double>> parent_descriptors_;   // aligned with core_.population()
  std::vector<double> parent_fitness_;
  std::vector<Measured> measured_;   // aligned with core_.population()
  double best_novelty_ = 0.0;
};

}  // namespace

std::string novelty_problem(const NoveltyRunSettings& settings, const Problem& problem) {
  if (std::string why = genome::tree::tree_problem(problem, "novelty search"); !why.empty()) return why;
  if (problem.descriptors.empty())
    return "novelty is measured between behavior descriptors: declare some (`descriptor NAME: EXPR in [lo, hi]`)";
  return rejection([&] {
    check_nsga2_settings(variation_of(settings));
    (void)qd::NoveltyArchive(archive_settings(settings), qd::descriptor_space_of(problem.descriptors));
  });
}

std::unique_ptr<Optimizer> make_novelty(const NoveltyRunSettings& settings, const Problem& problem) {
  if (std::string why = novelty_problem(settings, problem); !why.empty()) throw std::invalid_argument(why);
  return std::make_unique<NoveltyOptimizer>(settings, problem);
}

std::size_t novelty_population(const NoveltyRunSettings& settings, const Problem& /*problem*/) {
  return static_cast<std::size_t>(settings.population);
}

MemoryPeak novelty_memory_peak(const NoveltyRunSettings& settings, const Problem& problem) {
  const double big_n = static_cast<double>(settings.population);
  const double d = static_cast<double>(problem.descriptors.size());
  const std::size_t genes = genome::genes_at_most(problem);
  const double core = nsga2_memory_bytes(variation_of(settings), genes, settings.with_fitness ? 2 : 1);
  // Descriptors: the parents' kept, parents' and children's copied for scoring, the archive's.
  const double descriptors = rows_bytes(4.0 * big_n, d);
  // The kd-tree's points in unit coordinates and its nodes (3N points: parents, children,
  // the archive); novelty, fitness and the scores' objectives per point of parents and children.
  const double scoring = 3.0 * big_n * (d * sizeof(double) + qd::kTreeBytesPerPoint) +
                         2.0 * big_n * 2.0 * sizeof(double) + rows_bytes(2.0 * big_n, settings.with_fitness ? 2.0 : 1.0);
  return {core + descriptors + scoring + 2.0 * big_n * sizeof(Measured), big_n,
          fmt::format("novelty search's {} parents and {} children of {} genes, scored and ranked together",
                      settings.population, settings.population, genes),
          "novelty.population"};
}

}  // namespace esc::evo
