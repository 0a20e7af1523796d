#include "runtime/evo/neat/neat_optimizer.hpp"

#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "runtime/evo/neat/neat.hpp"
#include "runtime/evo/neat/neat_options.hpp"
#include "runtime/evo/map_elites/descriptor_space.hpp"
#include "runtime/evo/map_elites/point_tree.hpp"
#include "runtime/evo/novelty/novelty_archive.hpp"
#include "runtime/evo/run_streams.hpp"
#include "runtime/genome/graph/codec.hpp"

namespace esc::evo {

namespace gg = genome::graph;

namespace {

qd::NoveltySettings archive_settings(const NeatSettings& s) {
  qd::NoveltySettings a;
  a.k = static_cast<std::size_t>(s.novelty_k);
  a.threshold = s.novelty_threshold;
  return a;
}

// Scored by novelty, the state is NEAT's followed by the archive's.
constexpr std::string_view kNoveltyFormat = "esc-neat-novelty";
constexpr std::uint32_t kNoveltyVersion = 1;

class NeatOptimizer final : public Optimizer {
 public:
  NeatOptimizer(const NeatSettings& settings, const NeatProblem& problem)
      : neat_(settings, problem.inputs, problem.outputs, problem.output_activation), seed_(problem.seed) {
    if (settings.score == NeatScore::Novelty) {
      archive_.emplace(archive_settings(settings), qd::descriptor_space_of(problem.descriptors));
    }
    gg::Graph start;
    if (problem.start != nullptr) {
      if (const std::string why = gg::decode(*problem.start, start); !why.empty())
        throw std::invalid_argument("NEAT: the start genome is not a graph genome: " + why);
      if (gg::count_nodes(start, gg::NodeKind::Input) != problem.inputs ||
          gg::count_nodes(start, gg::NodeKind::Output) != problem.outputs)
        throw std::invalid_argument(
            fmt::format("NEAT: the start genome has {} inputs and {} outputs, the problem {} and {}",
                        gg::count_nodes(start, gg::NodeKind::Input), gg::count_nodes(start, gg::NodeKind::Output),
                        problem.inputs, problem.outputs));
    }
    Rng init = init_stream(seed_);
    neat_.start(problem.start != nullptr ? &start : nullptr, init);
  }

  std::vector<Genome> ask(int generation) override {
    if (generation != neat_.breedings()) {
      if (generation != neat_.breedings() + 1 || !neat_.told())
        throw std::logic_error(
            fmt::format("NEAT: generation {} asked after {} breedings", generation, neat_.breedings()));
      Rng rng = breed_stream(seed_, generation);
      neat_.breed(rng);
    }
    std::vector<Genome> out;
    out.reserve(neat_.population().size());
    for (const gg::Graph& g : neat_.population()) out.push_back(gg::encode(g));
    return out;
  }

  // Scored by novelty, each network's novelty among its generation and the archive, which
  // the generation's novel ones then enter (the archive's random draws, unused by its
  // threshold mode, from Rng(seed, Breed, g, 1) as novelty search's).
  void tell(std::span<const Outcome> outcomes) override {
    std::vector<double> f(outcomes.size());
    if (archive_) {
      std::vector<std::vector<double>> descriptors;
      descriptors.reserve(outcomes.size());
      for (const Outcome& o : outcomes) descriptors.push_back(o.descriptors);
      f = archive_->scores(descriptors);
      Rng rng(seed_, {static_cast<std::uint64_t>(Stream::Breed), static_cast<std::uint64_t>(neat_.breedings()), 1});
      archived_before_ = archive_->size();
      archive_->update(descriptors, f, rng);
    } else {
      for (std::size_t i = 0; i < f.size(); ++i) f[i] = outcomes[i].objectives.front();
    }
    neat_.tell(f);
  }

  std::vector<Metric> metrics() const override {
    double hidden = 0.0, links = 0.0;
    for (const gg::Graph& g : neat_.population()) {
      hidden += static_cast<double>(gg::count_nodes(g, gg::NodeKind::Hidden));
      links += static_cast<double>(gg::enabled_links(g));
    }
    const auto n = static_cast<double>(neat_.population().size());
    std::vector<Metric> m{{"species", static_cast<double>(neat_.species().size())},
                          {"hidden_nodes", hidden / n},
                          {"enabled_links", links / n},
                          {"threshold", neat_.threshold()}};
    if (archive_) {
      m.push_back({"archive", static_cast<double>(archive_->size())});
      m.push_back({"novelty_threshold", archive_->threshold()});
    }
    return m;
  }

  // Scored by novelty: the archive of behaviors, as novelty search's (no genomes, no
  // fitness); a generation's changes are the behaviors it added.
  std::optional<Members> members(bool changes) const override {
    if (!archive_) return std::nullopt;
    return qd::behavior_members(*archive_, changes ? archived_before_ : 0);
  }

  StateBytes save() const override {
    if (!archive_) return neat_.save();
    StateWriter w;
    w.put(std::string(kNoveltyFormat));
    w.put(kNoveltyVersion);
    const StateBytes neat = neat_.save(), archive = archive_->save();
    w.put(std::span<const std::uint8_t>(neat));
    w.put(std::span<const std::uint8_t>(archive));
    return std::move(w).take();
  }

  // Both parts are read and checked before either changes: a refused state leaves the
  // optimizer as it was.
  void load(std::span<const std::uint8_t> state) override {
    if (!archive_) {
      neat_.load(state);
      return;
    }
    StateReader r(state);
    if (r.text() != kNoveltyFormat) throw std::invalid_argument("NEAT: not a state of NEAT scored by novelty");
    if (const auto version = r.get<std::uint32_t>(); version != kNoveltyVersion)
      throw std::invalid_argument(fmt::format("NEAT: format version {}, expected {}", version, kNoveltyVersion));
    const std::string neat = r.text(), archive = r.text();
    r.finish();
    Neat n = neat_;
    n.load(std::span(reinterpret_cast<const std::uint8_t*>(neat.data()), neat.size()));
    qd::NoveltyArchive a = *archive_;
    a.load(std::span(reinterpret_cast<const std::uint8_t*>(archive.data()), archive.size()));
    neat_ = std::move(n);
    archive_ = std::move(a);
    archived_before_ = archive_->size();
  }

 private:
  Neat neat_;
  std::uint64_t seed_;
  std::optional<qd::NoveltyArchive> archive_;   // scored by novelty
  // The archive's size before the last tell added to it (after a load: all of it).
  std::size_t archived_before_ = 0;
};

}  // namespace

std::unique_ptr<Optimizer> make_neat(const NeatSettings& settings, const NeatProblem& problem) {
  return std::make_unique<NeatOptimizer>(settings, problem);
}

std::size_t neat_population(const NeatSettings& settings) { return static_cast<std::size_t>(settings.population); }

MemoryPeak neat_memory_peak(const NeatSettings& settings, std::size_t inputs, std::size_t outputs) {
  const double pop = static_cast<double>(settings.population);
  const double links = 2.0 * static_cast<double>((inputs + 1) * outputs);
  const double nodes = static_cast<double>(inputs + 1 + 2 * outputs);
  const double graph =
      sizeof(gg::Graph) + heap_bytes(nodes * sizeof(gg::NodeGene)) + heap_bytes(links * sizeof(gg::LinkGene));
  const double flat =
      static_cast<double>(gg::encoded_size(static_cast<std::size_t>(nodes), static_cast<std::size_t>(links)));
  // The saved state: each genome's flat form with its length, its fitness and species index.
  const double state = pop * (flat + 3.0) * sizeof(double);
  const double bytes = 2.0 * pop * graph + rows_bytes(pop, flat) + pop * 3.0 * sizeof(double) + writer_bytes(state);
  return {bytes, pop,
          fmt::format("NEAT's {} networks of about {:.0f} links, parents and children", settings.population, links),
          "neat.population"};
}

namespace {

NeatProblem neat_problem_of(const Problem& p) {
  return {p.graph.inputs, p.graph.outputs, p.seed, p.start, p.graph.output_activation, p.descriptors};
}

}  // namespace

std::unique_ptr<Optimizer> make_neat_run(const NeatSettings& settings, const Problem& problem) {
  if (std::string why = neat_run_problem(settings, problem); !why.empty()) throw std::invalid_argument("NEAT: " + why);
  return make_neat(settings, neat_problem_of(problem));
}

std::size_t neat_run_population(const NeatSettings& settings, const Problem& /*problem*/) {
  return neat_population(settings);
}

MemoryPeak neat_run_memory_peak(const NeatSettings& settings, const Problem& problem) {
  MemoryPeak m = neat_memory_peak(settings, problem.graph.inputs, problem.graph.outputs);
  if (settings.score == NeatScore::Novelty) {
    // A generation's descriptors copied and archived (the first update can take them all),
    // the kd-tree's unit points and nodes over both, their scores; what a long run archives
    // later is not counted, as novelty search's.
    const double pop = static_cast<double>(settings.population);
    const double d = static_cast<double>(problem.descriptors.size());
    m.bytes += rows_bytes(2.0 * pop, d) + 2.0 * pop * (d * sizeof(double) + qd::kTreeBytesPerPoint) +
               pop * sizeof(double);
  }
  return m;
}

std::string neat_run_problem(const NeatSettings& settings, const Problem& problem) {
  if (!problem.graph.graphs()) return "NEAT evolves graph genomes: a `neat(...)` controller";
  if (std::string why = neat_problem(settings, problem.graph.inputs, problem.graph.outputs); !why.empty()) return why;
  if (settings.score != NeatScore::Novelty) return {};
  if (problem.descriptors.empty())
    return "score novelty is measured between behavior descriptors: declare some (`descriptor NAME: EXPR in [lo, hi]`)";
  return rejection(
      [&] { (void)qd::NoveltyArchive(archive_settings(settings), qd::descriptor_space_of(problem.descriptors)); });
}

}  // namespace esc::evo
