// NEAT as an Optimizer: the first population, a constant population size, species that
// partition it, determinism by seed, a resume from a saved state byte for byte, refusal of
// damaged states, fitness of any sign, and the option table's checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <optional>

#include "runtime/core/rng.hpp"
#include "runtime/evo/neat/neat.hpp"
#include "runtime/evo/neat/neat_optimizer.hpp"
#include "runtime/evo/neat/neat_options.hpp"
#include "runtime/genome/graph/codec.hpp"
#include "runtime/genome/graph/network.hpp"

namespace esc::evo {
namespace {

namespace gg = genome::graph;

// A made-up task that rewards structure and some weights, so that species form and grow:
// the sum of enabled weights' cosines plus the hidden nodes, shifted to be negative half
// the time (to exercise the shift).
std::vector<Outcome> measure(const std::vector<Genome>& candidates, int generation) {
  std::vector<Outcome> out(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    gg::Graph g;
    EXPECT_EQ(gg::decode(candidates[i], g), "");
    double f = static_cast<double>(gg::count_nodes(g, gg::NodeKind::Hidden));
    for (const gg::LinkGene& l : g.links)
      if (l.enabled) f += std::cos(l.weight);
    out[i].objectives = {generation % 2 == 0 ? f : f - 50.0};
  }
  return out;
}

NeatSettings busy() {
  NeatSettings s;
  s.population = 40;
  s.add_node_prob = 0.2;
  s.add_link_prob = 0.3;
  s.toggle_enable_prob = 0.1;
  s.reenable_prob = 0.05;
  s.recur_only_prob = 0.2;
  s.interspecies_mate_rate = 0.05;
  s.threshold = 1.0;
  s.target_species = 4;
  s.dropoff_age = 3;   // stagnation and the population's standstill both happen
  return s;
}

TEST(Neat, FirstPopulationIsTheMinimalStartWithWeightsInOneSpecies) {
  const auto opt = make_neat(NeatSettings{}, {2, 1, 7, nullptr});
  const std::vector<Genome> g0 = opt->ask(0);
  ASSERT_EQ(g0.size(), 150U);
  for (const Genome& genes : g0) {
    gg::Graph g;
    ASSERT_EQ(gg::decode(genes, g), "");
    ASSERT_EQ(g.links.size(), 3U);
    for (const gg::LinkGene& l : g.links) EXPECT_LE(std::abs(l.weight), 1.0);
  }
  EXPECT_NE(g0[0], g0[1]);
  const auto m = opt->metrics();
  ASSERT_EQ(m.size(), 4U);
  EXPECT_EQ(m[0].name, "species");
  EXPECT_EQ(m[0].value, 1.0);   // weights within [-1, 1] are all within delta_t 3
  EXPECT_EQ(m[1].value, 0.0);
  EXPECT_EQ(m[2].value, 3.0);
  EXPECT_EQ(m[3].value, 3.0);
}

TEST(Neat, PopulationStaysWholeAndSpeciesPartitionIt) {
  Neat neat(busy(), 3, 2);
  Rng init(1);
  neat.start(nullptr, init);
  std::size_t most_species = 0;
  std::size_t most_hidden = 0;
  std::size_t loops = 0;
  for (int g = 0; g < 40; ++g) {
    std::vector<Genome> flat;
    for (const gg::Graph& x : neat.population()) flat.push_back(gg::encode(x));
    const auto out = measure(flat, g);
    std::vector<double> f;
    for (const auto& o : out) f.push_back(o.objectives[0]);
    neat.tell(f);
    Rng rng(100 + static_cast<std::uint64_t>(g));
    neat.breed(rng);
    ASSERT_EQ(neat.population().size(), 40U) << g;
    std::vector<int> seen(40, 0);
    for (const Species& s : neat.species()) {
      ASSERT_FALSE(s.members.empty());
      for (const std::size_t m : s.members) ++seen.at(m);
    }
    for (const int k : seen) ASSERT_EQ(k, 1) << g;
    for (const gg::Graph& x : neat.population()) {
      ASSERT_EQ(gg::misfit(x), "");
      most_hidden = std::max(most_hidden, gg::count_nodes(x, gg::NodeKind::Hidden));
      loops += static_cast<std::size_t>(
          std::count_if(x.links.begin(), x.links.end(), [](const gg::LinkGene& l) { return l.in == l.out; }));
      gg::Network net(x);   // every evolved genome builds a network that runs, recurrent or not
      for (int t = 0; t < 3; ++t) (void)net.step(std::vector<double>{0.5, -0.5, 1.0});
      for (const double y : net.output()) ASSERT_TRUE(std::isfinite(y));
    }
    most_species = std::max(most_species, neat.species().size());
  }
  EXPECT_GT(most_species, 1U);
  EXPECT_GT(most_hidden, 1U);
  EXPECT_GT(loops, 0U);   // recur_only_prob 0.2 made recurrent links, some of them loops
  EXPECT_GE(neat.threshold(), busy().threshold_step);
}

TEST(Neat, AStandstillBreedsFromTheChampionAndKeepsTheWholePopulation) {
  NeatSettings s;
  s.population = 20;
  s.threshold = 1e6;   // one species throughout
  s.dropoff_age = 1;   // a standstill after 1 + 5 generations without a rise
  Neat neat(s, 2, 1);
  Rng init(2);
  neat.start(nullptr, init);
  const std::vector<double> flat(20, 1.0);
  for (int b = 1; b <= 6; ++b) {   // the first breeding records 1, five more see no rise
    neat.tell(flat);
    Rng rng(static_cast<std::uint64_t>(b));
    neat.breed(rng);
  }
  ASSERT_EQ(neat.species().size(), 1U);
  const gg::Graph champion = neat.population()[neat.species()[0].members[0]];   // ties: the first
  neat.tell(flat);
  Rng rng(7);
  neat.breed(rng);
  ASSERT_EQ(neat.population().size(), 20U);   // NEAT C++ would make 10 of a lone species
  int clones = 0;
  for (const gg::Graph& child : neat.population()) {
    clones += child == champion ? 1 : 0;
    EXPECT_EQ(child.nodes, champion.nodes);
    for (const gg::LinkGene& l : champion.links)   // every link of the champion's, maybe reweighted
      EXPECT_TRUE(std::any_of(child.links.begin(), child.links.end(),
                              [&](const gg::LinkGene& c) { return c.innovation == l.innovation; }));
  }
  // The last of its offspring is a plain copy; so are those whose new link found no open pair
  // (the minimal XOR net has none): 4 of 19 here.
  EXPECT_GE(clones, 1);
  EXPECT_LT(clones, 10);
}

std::vector<std::vector<Genome>> run(std::uint64_t seed, int generations) {
  const auto opt = make_neat(busy(), {3, 2, seed, nullptr});
  std::vector<std::vector<Genome>> all;
  for (int g = 0; g < generations; ++g) {
    all.push_back(opt->ask(g));
    opt->tell(measure(all.back(), g));
  }
  return all;
}

TEST(Neat, TheSameSeedGivesTheSameGenomesAndAnotherSeedOthers) {
  const auto a = run(5, 25), b = run(5, 25), c = run(6, 25);
  EXPECT_EQ(a, b);
  EXPECT_NE(a.back(), c.back());
}

TEST(Neat, ResumesFromASavedStateByteForByte) {
  const auto whole = run(9, 30);
  for (const int stop : {0, 1, 4, 11, 20}) {
    const auto first = make_neat(busy(), {3, 2, 9, nullptr});
    for (int g = 0; g <= stop; ++g) first->tell(measure(first->ask(g), g));
    const StateBytes state = first->save();
    const auto second = make_neat(busy(), {3, 2, 9, nullptr});
    second->load(state);
    EXPECT_EQ(second->save(), state) << stop;
    for (int g = stop + 1; g < 30; ++g) {
      const std::vector<Genome> asked = second->ask(g);
      ASSERT_EQ(asked, whole[static_cast<std::size_t>(g)]) << "stopped after " << stop << ", generation " << g;
      second->tell(measure(asked, g));
    }
  }
}

TEST(Neat, RefusesAStateItCouldNotHaveWritten) {
  const auto opt = make_neat(busy(), {3, 2, 9, nullptr});
  for (int g = 0; g < 6; ++g) opt->tell(measure(opt->ask(g), g));
  const StateBytes good = opt->save();
  const auto fresh = [] { return make_neat(busy(), {3, 2, 9, nullptr}); };
  const auto refuses = [&](const StateBytes& bad, const std::string& why) {
    const auto o = fresh();
    try {
      o->load(bad);
      ADD_FAILURE() << "accepted: " << why;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  for (const std::size_t at : {std::size_t{0}, std::size_t{20}, good.size() / 2, good.size() - 1}) {
    StateBytes flipped = good;
    flipped[at] ^= 0x10;
    refuses(flipped, "checksum does not match");
  }
  refuses(StateBytes(good.begin(), good.end() - 3), "checksum");
  refuses(StateBytes{}, "truncated");
  NeatSettings other = busy();
  other.population = 41;
  const auto bigger = make_neat(other, {3, 2, 9, nullptr});
  EXPECT_THROW(bigger->load(good), std::invalid_argument);
  const auto wider = make_neat(busy(), {4, 2, 9, nullptr});
  EXPECT_THROW(wider->load(good), std::invalid_argument);
  // An unharmed state still loads after all that.
  const auto o = fresh();
  EXPECT_NO_THROW(o->load(good));
}

TEST(Neat, AskingOutOfOrderIsALogicError) {
  const auto opt = make_neat(busy(), {3, 2, 1, nullptr});
  (void)opt->ask(0);
  EXPECT_THROW((void)opt->ask(1), std::logic_error);   // generation 0 not told
  EXPECT_THROW((void)opt->ask(3), std::logic_error);
}

TEST(Neat, NegativeFitnessIsShiftedSoTheWorstIsZero) {
  Neat a(NeatSettings{}, 2, 1), b(NeatSettings{}, 2, 1);
  Rng ia(3), ib(3);
  a.start(nullptr, ia);
  b.start(nullptr, ib);
  std::vector<double> f(150), g(150);
  for (std::size_t i = 0; i < f.size(); ++i) {
    f[i] = static_cast<double>(i % 7);
    g[i] = f[i] - 1000.0;
  }
  g[3] = std::nan("");   // counts as the lowest
  f[3] = 0.0;
  a.tell(f);
  b.tell(g);
  Rng ra(4), rb(4);
  a.breed(ra);
  b.breed(rb);
  EXPECT_EQ(a.population(), b.population());
}

TEST(Neat, StartsFromAGivenGenomeKeptAsCandidateZero) {
  gg::Graph start = gg::minimal_graph(2, 1, gg::Activation::Tanh);
  start.links[1].weight = 0.75;
  const Genome genes = gg::encode(start);
  const auto opt = make_neat(NeatSettings{}, {2, 1, 3, &genes});
  const auto g0 = opt->ask(0);
  EXPECT_EQ(g0[0], genes);
  EXPECT_NE(g0[1], genes);
  const Genome bad = {1.0, 0.0};
  EXPECT_THROW((void)make_neat(NeatSettings{}, {2, 1, 3, &bad}), std::invalid_argument);
  EXPECT_THROW((void)make_neat(NeatSettings{}, {3, 1, 3, &genes}), std::invalid_argument);
}

TEST(NeatOptions, EveryRowChecksItsRangeAndNamesTheOption) {
  std::any s = NeatSettings{};
  for (const AlgorithmOption& o : neat_options()) {
    EXPECT_FALSE(o.text(s).empty()) << o.key;
    if (o.form != OptionForm::Number) continue;
    OptionValue v;
    v.number = -1.0;
    EXPECT_NE(o.set(s, v).message, "") << o.key << " took -1";
  }
  NeatSettings bad;
  bad.survival_thresh = 0.0;
  EXPECT_EQ(neat_problem(bad, 2, 1), "survival_thresh must be in (0, 1], found 0");
  bad = NeatSettings{};
  bad.add_node_prob = 1.5;
  EXPECT_EQ(neat_problem(bad, 2, 1), "add_node_prob must be in [0, 1], found 1.5");
  EXPECT_EQ(neat_problem(NeatSettings{}, 0, 1), "a network needs inputs and outputs, found 0 and 1");
  EXPECT_EQ(neat_problem(NeatSettings{}, 2, 1), "");
  EXPECT_THROW((void)make_neat(bad, {2, 1, 1, nullptr}), std::invalid_argument);
  // The activation is a word.
  const auto& rows = neat_options();
  const auto act =
      std::find_if(rows.begin(), rows.end(), [](const AlgorithmOption& o) { return o.key == "activation"; });
  ASSERT_NE(act, rows.end());
  OptionValue tanh_word;
  tanh_word.word = 1;
  EXPECT_EQ(act->set(s, tanh_word).message, "");
  EXPECT_EQ(act->text(s), "tanh");
}

// Descriptors in [0, 1] x [0, 1] from a network's structure and first weight, for scoring
// by novelty.
std::vector<Outcome> measure_behavior(const std::vector<Genome>& candidates, int generation) {
  std::vector<Outcome> out = measure(candidates, generation);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    gg::Graph g;
    EXPECT_EQ(gg::decode(candidates[i], g), "");
    out[i].descriptors = {static_cast<double>(gg::enabled_links(g) % 10) / 10.0,
                          0.5 + 0.5 * std::sin(g.links.front().weight)};
  }
  return out;
}

NeatSettings by_novelty() {
  NeatSettings s = busy();
  s.score = NeatScore::Novelty;
  s.novelty_k = 5;
  s.novelty_threshold = 0.05;
  return s;
}

NeatProblem behaving(std::uint64_t seed) { return {3, 2, seed, nullptr, std::nullopt, {{0.0, 1.0}, {0.0, 1.0}}}; }

TEST(Neat, ScoredByNoveltyArchivesBehaviorsAndResumesByteForByte) {
  std::vector<std::vector<Genome>> whole;
  const auto opt = make_neat(by_novelty(), behaving(4));
  std::size_t archived = 0;
  for (int g = 0; g < 25; ++g) {
    whole.push_back(opt->ask(g));
    opt->tell(measure_behavior(whole.back(), g));
    const auto m = opt->metrics();
    ASSERT_EQ(m.size(), 6U);
    EXPECT_EQ(m[4].name, "archive");
    EXPECT_GE(m[4].value, static_cast<double>(archived));
    archived = static_cast<std::size_t>(m[4].value);
    const std::optional<Members> changes = opt->members(true);
    ASSERT_TRUE(changes.has_value());
    EXPECT_EQ(changes->kind, MemberKind::Archive);
    for (const Member& member : changes->members) EXPECT_EQ(member.descriptors.size(), 2U);
  }
  EXPECT_GT(archived, 0U);
  EXPECT_EQ(opt->members(false)->members.size(), archived);
  // Scored by novelty, another population than by the fitness from the same seed.
  const auto by_fitness = make_neat(busy(), {3, 2, 4, nullptr});
  for (int g = 0; g < 5; ++g) by_fitness->tell(measure_behavior(by_fitness->ask(g), g));
  EXPECT_NE(by_fitness->ask(5), whole[5]);
  for (const int stop : {0, 3, 12}) {
    const auto first = make_neat(by_novelty(), behaving(4));
    for (int g = 0; g <= stop; ++g) first->tell(measure_behavior(first->ask(g), g));
    const StateBytes state = first->save();
    const auto second = make_neat(by_novelty(), behaving(4));
    second->load(state);
    EXPECT_EQ(second->save(), state) << stop;
    for (int g = stop + 1; g < 25; ++g) {
      const std::vector<Genome> asked = second->ask(g);
      ASSERT_EQ(asked, whole[static_cast<std::size_t>(g)]) << "stopped after " << stop << ", generation " << g;
      second->tell(measure_behavior(asked, g));
    }
    // A state scored by the fitness is not one scored by novelty, nor the other way.
    const auto plain = make_neat(busy(), {3, 2, 4, nullptr});
    EXPECT_THROW(plain->load(state), std::invalid_argument);
    EXPECT_THROW(second->load(plain->save()), std::invalid_argument);
  }
}

TEST(Neat, NoveltyNeedsDescriptorsAndStartHiddenGrowsTheStart) {
  Problem p;
  p.graph = {3, 2, gg::Activation::NeatSigmoid};
  EXPECT_NE(neat_run_problem(by_novelty(), p).find("declare some"), std::string::npos);
  EXPECT_THROW((void)make_neat_run(by_novelty(), p), std::invalid_argument);
  p.descriptors = {{0.0, 1.0}};
  EXPECT_EQ(neat_run_problem(by_novelty(), p), "");
  // novelty-search-cpp's mazestartgenes: every sensor feeds one hidden node, which feeds
  // every output, and no sensor an output.
  NeatSettings s;
  s.start_hidden = 1;
  const auto opt = make_neat(s, {10, 2, 3, nullptr});
  gg::Graph g;
  ASSERT_EQ(gg::decode(opt->ask(0)[7], g), "");
  EXPECT_EQ(gg::count_nodes(g, gg::NodeKind::Hidden), 1U);
  ASSERT_EQ(g.links.size(), 11U + 2U);
  const gg::Id hidden = g.nodes.back().id;
  for (std::size_t i = 0; i < 11; ++i) EXPECT_EQ(g.links[i].out, hidden);
  for (std::size_t i = 11; i < 13; ++i) EXPECT_EQ(g.links[i].in, hidden);
  EXPECT_EQ(gg::misfit(g), "");
}

TEST(NeatMemoryPeak, GrowsWithThePopulationAndNamesItsSetting) {
  NeatSettings s;
  const MemoryPeak small = neat_memory_peak(s, 2, 1);
  s.population = 1500;
  const MemoryPeak large = neat_memory_peak(s, 2, 1);
  EXPECT_EQ(large.setting, "neat.population");
  EXPECT_EQ(large.candidates, 1500.0);
  // Ten times the networks; the state's writer rounds up to a power of two.
  EXPECT_GE(large.bytes / small.bytes, 10.0);
  EXPECT_LE(large.bytes / small.bytes, 13.0);
  // At least the flat copies: 150 genomes of 4 nodes and 3 links, 30 doubles each.
  EXPECT_GT(small.bytes, 150.0 * 30.0 * 8.0);
  EXPECT_EQ(neat_population(s), 1500U);
}

}  // namespace
}  // namespace esc::evo
