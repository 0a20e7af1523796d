// Quality diversity's archive work (docs/quality-diversity.md): insert into a full archive
// of 10,000 cells (a 100 x 100 grid, or a CVT of 10,000 centroids over 2 descriptors) with
// genomes of 100 doubles; one MAP-Elites generation of 100 children (uniform selection,
// Iso+LineDD, insertion); computing the CVT; novelty scores of a population of 150 against
// archives of growing size, by kd-tree and, for comparison, by brute force.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <benchmark/benchmark.h>

#include "runtime/core/rng.hpp"
#include "runtime/evo/map_elites/map_elites.hpp"
#include "runtime/evo/map_elites/point_tree.hpp"
#include "runtime/evo/novelty/novelty_archive.hpp"

namespace {

using namespace esc;
using namespace esc::evo;
using namespace esc::evo::qd;

constexpr std::size_t kGenome = 100;
constexpr std::size_t kCells = 10'000;

const DescriptorSpace& square() {
  static const DescriptorSpace space({{0.0, 1.0}, {0.0, 1.0}});
  return space;
}

const Cvt& cvt_10k() {
  static const Cvt cvt = [] {
    Rng rng(1, {static_cast<std::uint64_t>(Stream::Init)});
    return Cvt::compute(2, kCells, rng);
  }();
  return cvt;
}

// An archive of 10,000 cells after 200,000 random candidates: every cell filled, the
// fitness of each elite the best of about 20 draws.
Archive full_archive(bool cvt) {
  Archive a = cvt ? Archive(square(), cvt_10k(), 0.0) : Archive(square(), Grid({100, 100}), 0.0);
  Rng rng(2);
  for (int i = 0; i < 200'000; ++i)
    (void)a.insert(Genome(kGenome, rng.uniform(-1.0, 1.0)), rng.uniform(), std::vector<double>{rng.uniform(), rng.uniform()});
  (void)a.take_changes();
  return a;
}

// One insert of a fresh candidate (genome copied in, as a caller that keeps it would):
// about 1 in 20 improves its cell, the rest are rejected.
void BM_QdInsert(benchmark::State& state) {
  const bool cvt = state.range(0) == 1;
  Archive a = full_archive(cvt);
  Rng rng(3);
  std::vector<Genome> genomes(256, Genome(kGenome));
  for (auto& g : genomes)
    for (double& v : g) v = rng.uniform(-1.0, 1.0);
  std::size_t i = 0;
  for (auto _ : state) {
    const double fitness = rng.uniform();
    const double d[2] = {rng.uniform(), rng.uniform()};
    benchmark::DoNotOptimize(a.insert(genomes[i++ % genomes.size()], fitness, d));
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["filled"] = static_cast<double>(a.filled());
  state.counters["held_MB"] = a.memory_bytes() / 1e6;
  state.counters["estimate_MB"] = archive_memory_bytes(kCells, kGenome, 2, kCells, cvt) / 1e6;
  state.SetLabel(cvt ? "cvt 10,000" : "grid 100x100");
}
BENCHMARK(BM_QdInsert)->Arg(0)->Arg(1);

// One MAP-Elites generation's archive work: ask (100 children: 2 uniform selections and
// Iso+LineDD each), tell (100 inserts of precomputed fitness and descriptors), take_changes.
void BM_QdGeneration(benchmark::State& state) {
  const bool cvt = state.range(0) == 1;
  MapElites me(MapElitesSettings{}, kGenome, full_archive(cvt));
  Rng rng(4);
  std::vector<double> fitness(100);
  std::vector<std::vector<double>> descriptors(100, std::vector<double>(2));
  std::uint64_t g = 0;
  for (auto _ : state) {
    Rng breed(5, {static_cast<std::uint64_t>(Stream::Breed), g++});
    const auto genomes = me.ask(breed);
    for (std::size_t i = 0; i < genomes.size(); ++i) {
      fitness[i] = rng.uniform();
      descriptors[i] = {rng.uniform(), rng.uniform()};
    }
    me.tell(fitness, descriptors);
    benchmark::DoNotOptimize(me.take_changes());
  }
  state.SetItemsProcessed(state.iterations() * 100);
  state.SetLabel(cvt ? "cvt 10,000" : "grid 100x100");
}
BENCHMARK(BM_QdGeneration)->Arg(0)->Arg(1);

// The CVT of 10,000 cells over 2 descriptors with the default 100,000 samples: once per run
// (and once per resume, before the state replaces the centroids).
void BM_QdCvtCompute(benchmark::State& state) {
  const auto dims = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    Rng rng(1, {static_cast<std::uint64_t>(Stream::Init)});
    benchmark::DoNotOptimize(Cvt::compute(dims, kCells, rng));
  }
}
BENCHMARK(BM_QdCvtCompute)->Arg(2)->Arg(3)->Iterations(1)->Unit(benchmark::kMillisecond);

std::vector<std::vector<double>> random_points(Rng& rng, std::size_t n) {
  std::vector<std::vector<double>> p(n, std::vector<double>(2));
  for (auto& v : p)
    for (double& x : v) x = rng.uniform();
  return p;
}

// Novelty of a population of range(0) (k = 15) against an archive of range(1) points.
void BM_QdNoveltyScores(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto m = static_cast<std::size_t>(state.range(1));
  NoveltySettings s;
  s.mode = NoveltyMode::Random;
  s.random_probability = 1.0;
  NoveltyArchive archive(s, square());
  Rng rng(6);
  (void)archive.update(random_points(rng, m), std::vector<double>(m, 0.0), rng);
  const auto population = random_points(rng, n);
  for (auto _ : state) benchmark::DoNotOptimize(archive.scores(population));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

// The same numbers by comparing every pair (partial sort of each individual's distances):
// the O(n (n + m)) search the kd-tree replaces, measured to see where it would be faster.
void BM_QdNoveltyBruteForce(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto m = static_cast<std::size_t>(state.range(1));
  Rng rng(6);
  const auto archive = random_points(rng, m);
  auto all = random_points(rng, n);
  all.insert(all.end(), archive.begin(), archive.end());
  std::vector<double> d;
  for (auto _ : state) {
    std::vector<double> novelty(n);
    for (std::size_t i = 0; i < n; ++i) {
      d.clear();
      for (std::size_t j = 0; j < all.size(); ++j)
        if (j != i) d.push_back(std::sqrt(squared_distance(all[i], all[j])));
      const std::size_t k = std::min<std::size_t>(15, d.size());
      std::partial_sort(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(k), d.end());
      double sum = 0.0;
      for (std::size_t j = 0; j < k; ++j) sum += d[j];
      novelty[i] = sum / static_cast<double>(k);
    }
    benchmark::DoNotOptimize(novelty);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

void novelty_sizes(benchmark::internal::Benchmark* b) {
  for (const auto& [n, m] : std::vector<std::pair<int, int>>{{20, 0}, {50, 0}, {150, 0}, {150, 1000}, {150, 10000}}) b->Args({n, m});
}
BENCHMARK(BM_QdNoveltyScores)->Apply(novelty_sizes);
BENCHMARK(BM_QdNoveltyBruteForce)->Apply(novelty_sizes);

}  // namespace

// Standalone runner for the local build (tests/evo: qd_bench_local); `esc bench` links
// these benchmarks into its own main.
#ifdef ESC_QD_BENCH_MAIN
BENCHMARK_MAIN();
#endif
