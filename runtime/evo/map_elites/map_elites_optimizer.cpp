#include "runtime/evo/map_elites/map_elites_optimizer.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <variant>

#include <fmt/format.h>

#include "runtime/genome/genome_size.hpp"
#include "runtime/genome/graph/graph_variation.hpp"
#include "runtime/genome/tree/tree_variation.hpp"
#include "runtime/evo/map_elites/selection.hpp"
#include "runtime/evo/measured_state.hpp"
#include "runtime/evo/run_streams.hpp"

namespace esc::evo {

namespace {

double cells_of(const MapElitesRunSettings& s, std::size_t descriptors) {
  return s.cvt ? static_cast<double>(s.cells) : std::pow(static_cast<double>(s.bins), static_cast<double>(descriptors));
}

// The experiment's shared CVT, computed once per process (about a second for 2 or 3
// descriptors at 100,000 samples, far more for many descriptors: not once per run).
qd::Cvt shared_cvt(std::size_t dims, std::size_t cells, std::size_t samples) {
  static std::mutex mutex;
  static std::map<std::tuple<std::size_t, std::size_t, std::size_t>, qd::Cvt> made;
  const std::lock_guard lock(mutex);
  const auto key = std::make_tuple(dims, cells, samples);
  if (const auto it = made.find(key); it != made.end()) return it->second;
  Rng rng(kCvtStream);
  qd::CvtSettings cs;
  cs.samples = samples;
  return made.emplace(key, qd::Cvt::compute(dims, cells, rng, cs)).first->second;
}

qd::Archive archive_for(const MapElitesRunSettings& s, const Problem& p) {
  qd::DescriptorSpace space = qd::descriptor_space_of(p.descriptors);
  qd::Tessellation cells = s.cvt ? qd::Tessellation(shared_cvt(space.size(), static_cast<std::size_t>(s.cells),
                                                               static_cast<std::size_t>(s.samples)))
                                 : qd::Tessellation(qd::Grid(std::vector<std::size_t>(
                                       space.size(), static_cast<std::size_t>(s.bins))));
  return qd::Archive(std::move(space), std::move(cells), p.objectives.front().lower);
}

qd::MapElitesSettings core_settings(const MapElitesRunSettings& s) {
  qd::MapElitesSettings c;
  c.batch = static_cast<std::size_t>(s.batch);
  c.initial = static_cast<std::size_t>(s.initial);
  c.sigma_iso = s.sigma_iso;
  c.sigma_line = s.sigma_line;
  c.lower = s.lower;
  c.upper = s.upper;
  return c;
}

// Over trees: one elite drawn uniformly, then one of the GP's mutations; over graphs, NEAT's
// mutation, the new structure numbered past the archive's.
qd::MapElites core_for(const MapElitesRunSettings& s, const Problem& p) {
  if (p.graph.graphs()) {
    auto graphs = std::make_shared<genome::graph::GraphVariation>(p.graph.operators, p.graph);
    qd::MapElitesGenomes genomes{graphs,
                                 [graphs](const qd::Archive& archive, Rng& rng) {
                                   return graphs->mutate_one(qd::select_uniform(archive, rng).genome, rng);
                                 },
                                 [graphs](const qd::Archive& archive) {
                                   std::vector<Genome> elites;
                                   elites.reserve(archive.filled());
                                   for (const std::size_t cell : archive.filled_cells())
                                     elites.push_back(archive.elite(cell)->genome);
                                   graphs->begin(elites);
                                 }};
    return {core_settings(s), std::move(genomes), archive_for(s, p)};
  }
  if (p.tree.primitives == nullptr) return {core_settings(s), p.genome_size, archive_for(s, p)};
  auto trees = std::make_shared<const genome::tree::TreeVariation>(*p.tree.operators, *p.tree.primitives);
  qd::MapElitesGenomes genomes{trees, [trees](const qd::Archive& archive, Rng& rng) {
                                 return trees->mutate_one(qd::select_uniform(archive, rng).genome, rng);
                               }};
  return {core_settings(s), std::move(genomes), archive_for(s, p)};
}

// The run-level state's tag (measured_state.hpp): the core's state and, per filled cell in
// increasing order, where its elite was measured.
constexpr std::string_view kRunTag = "esc-map-elites-run";

// A filled cell's origin entry, beside the archive's elites (an unordered_map node and its
// bucket), counted in the run's memory estimate.
constexpr double kMeasuredBytesPerCell = 64.0;

class MapElitesOptimizer final : public Optimizer {
 public:
  MapElitesOptimizer(const MapElitesRunSettings& settings, const Problem& problem)
      : core_(core_for(settings, problem)), seed_(problem.seed) {
    if (problem.start != nullptr) core_.start(*problem.start);
  }

  std::vector<Genome> ask(int generation) override {
    generation_ = generation;
    Rng rng = breed_stream(seed_, generation);
    return core_.ask(rng);
  }

  void tell(std::span<const Outcome> outcomes) override {
    std::vector<double> fitness(outcomes.size());
    std::vector<std::vector<double>> descriptors(outcomes.size());
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      fitness[i] = outcomes[i].objectives.front();
      descriptors[i] = outcomes[i].descriptors;
    }
    // A cell's elite is the last candidate that entered it: a later one is strictly fitter.
    const std::vector<qd::InsertResult> placed = core_.tell(fitness, descriptors);
    for (std::size_t i = 0; i < placed.size(); ++i)
      if (placed[i].status != qd::Insertion::Rejected)
        measured_[placed[i].cell] = {generation_, static_cast<std::uint64_t>(i)};
    changed_.clear();
    for (const qd::Change& c : core_.take_changes()) changed_.push_back(c.cell);
  }

  std::optional<Members> members(bool changes) const override {
    const qd::Archive& archive = core_.archive();
    Members m{MemberKind::Archive, 1, archive.space().size(), {}, {}, {}, {}};
    const auto add = [&](std::size_t cell) {
      const qd::Elite& e = *archive.elite(cell);
      m.members.push_back(
          {static_cast<std::int64_t>(cell), {e.fitness}, e.descriptor, changes ? Genome{} : e.genome, measured(cell)});
    };
    if (changes) {
      for (const std::size_t cell : changed_) add(cell);
      return m;
    }
    for (const std::size_t cell : archive.filled_cells()) add(cell);
    if (const auto* grid = std::get_if<qd::Grid>(&archive.tessellation())) m.bins = grid->bins();
    else m.centroids = std::get<qd::Cvt>(archive.tessellation()).centroids();
    return m;
  }

  std::vector<Metric> metrics() const override {
    std::vector<Metric> m{{"qd_score", core_.qd_score()}, {"coverage", core_.coverage()}};
    if (const auto best = core_.best()) m.push_back({"archive_best", *best});
    return m;
  }

  StateBytes save() const override {
    std::vector<Measured> filled;
    for (const std::size_t cell : core_.archive().filled_cells()) filled.push_back(measured(cell));
    return save_with_measured(kRunTag, core_.save(), filled);
  }

  void load(std::span<const std::uint8_t> state) override {
    auto [bytes, stored] = read_with_measured(kRunTag, state);
    qd::MapElites core = core_;
    core.load(bytes);
    const std::span<const std::size_t> cells = core.archive().filled_cells();
    const std::vector<Measured> origins = measured_for(std::move(stored), cells.size(), "MAP-Elites", "filled cells");
    std::unordered_map<std::size_t, Measured> measured;
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (origins[i].known()) measured[cells[i]] = origins[i];
    core_ = std::move(core);
    measured_ = std::move(measured);
    changed_.clear();
  }

 private:
  // Unknown for a cell filled by a state saved before origins were kept.
  [[nodiscard]] Measured measured(std::size_t cell) const {
    const auto it = measured_.find(cell);
    return it == measured_.end() ? Measured{} : it->second;
  }

  qd::MapElites core_;
  std::uint64_t seed_;
  int generation_ = 0;                                  // of the last ask
  std::unordered_map<std::size_t, Measured> measured_;  // per filled cell
  std::vector<std::size_t> changed_;   // cells the last tell changed, in cell order
};

}  // namespace

std::string map_elites_problem(const MapElitesRunSettings& s, const Problem& p) {
  const std::string what = s.cvt ? "CVT-MAP-Elites" : "MAP-Elites";
  if (std::string why = genome::tree::tree_problem(p, what); !why.empty()) return why;
  if (p.tree.primitives != nullptr && genome::tree::TreeVariation(*p.tree.operators, *p.tree.primitives).mutation_sum() <= 0.0)
    return what + " varies a tree by one of the GP's mutations: subtree_mutation, point_mutation and hoist_mutation "
                  "of `evolve gp` are all 0";
  if (p.descriptors.empty())
    return what + " places each controller by its behavior descriptors: declare some (`descriptor NAME: EXPR in "
                  "[lo, hi]`)";
  if (!s.cvt && p.descriptors.size() > 3)
    return fmt::format("a grid has 1 to 3 descriptors, the experiment declares {}: use cvt_map_elites",
                       p.descriptors.size());
  if (p.objectives.empty() || !std::isfinite(p.objectives.front().lower))
    return what + "'s QD-score counts fitness above its declared lower bound: declare the fitness's range "
                  "(`fitness F in [lo, hi]`)";
  if (const Bounds& f = p.objectives.front(); !std::isfinite(cells_of(s, p.descriptors.size()) * (f.upper - f.lower)))
    return fmt::format("{}'s QD-score sums up to {} cells' fitness above {}: over the fitness's declared range "
                       "[{}, {}] it would overflow a double; declare a narrower range",
                       what, cells_of(s, p.descriptors.size()), f.lower, f.lower, f.upper);
  if (cells_of(s, p.descriptors.size()) > static_cast<double>(qd::kMaxGridCells))
    return fmt::format("{} cells are more than an archive may hold ({})", cells_of(s, p.descriptors.size()),
                       qd::kMaxGridCells);
  if (s.cvt && s.samples < s.cells)
    return fmt::format("the CVT needs at least as many samples ({}) as cells ({})", s.samples, s.cells);
  if (!(s.lower < s.upper)) return "the bounds are empty";
  return {};
}

std::unique_ptr<Optimizer> make_map_elites(const MapElitesRunSettings& settings, const Problem& problem) {
  if (std::string why = map_elites_problem(settings, problem); !why.empty()) throw std::invalid_argument(why);
  return std::make_unique<MapElitesOptimizer>(settings, problem);
}

std::size_t map_elites_population(const MapElitesRunSettings& settings, const Problem& /*problem*/) {
  return static_cast<std::size_t>(settings.initial);
}

MemoryPeak map_elites_memory_peak(const MapElitesRunSettings& settings, const Problem& problem, int generations) {
  const double cells = cells_of(settings, problem.descriptors.size());
  const std::size_t genes = genome::genes_at_most(problem);
  const double candidates = std::max(settings.batch, settings.initial);
  const std::string archive =
      settings.cvt ? fmt::format("CVT-MAP-Elites' archive of {} cells", settings.cells)
                   : fmt::format("MAP-Elites' archive of {:.0f} cells ({} bins per descriptor)", cells, settings.bins);
  const std::string setting = settings.cvt ? "cvt_map_elites.cells" : "map_elites.bins";
  // Refused by map_elites_problem anyway; the estimate must not wrap around.
  if (cells > static_cast<double>(qd::kMaxGridCells))
    return {cells * static_cast<double>(genes) * 8.0, candidates, archive, setting};
  const double filled = settings.initial + static_cast<double>(settings.batch) * std::max(generations - 1, 0);
  // A CVT's k-means: the samples and their cells, each centroid's sum and count; and the
  // process's copy of the centroids, beside the archive's.
  const double dims = static_cast<double>(problem.descriptors.size());
  const double kmeans =
      settings.cvt ? (settings.samples * (dims + 1.0) + cells * (dims + 1.0) + cells * dims) * sizeof(double) : 0.0;
  const double archived = qd::map_elites_memory_bytes(core_settings(settings), genes, static_cast<std::size_t>(cells),
                                                      problem.descriptors.size(), filled, settings.cvt) +
                          std::min(filled, cells) * kMeasuredBytesPerCell;
  const double generation = rows_bytes(2.0 * candidates, static_cast<double>(genes));
  if (generation > archived - generation)
    return {archived + kmeans, candidates,
            fmt::format("{}' {:.0f} candidates of {} genes", settings.cvt ? "CVT-MAP-Elites" : "MAP-Elites", candidates,
                        genes),
            fmt::format("{}.{}", settings.cvt ? "cvt_map_elites" : "map_elites",
                        settings.batch >= settings.initial ? "batch" : "initial")};
  return {archived + kmeans, candidates, archive, setting};
}

}  // namespace esc::evo
