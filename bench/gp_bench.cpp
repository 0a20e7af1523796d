// GP tree evaluation: the flat postfix program (runtime/genome/tree/program.hpp) against the
// plain recursive walker (recursive.hpp) and the script expression VM (expr::Program, via
// convert.hpp), on random Number trees of about 15, 50 and 150 nodes. One item = one tree
// evaluated on one frame.
#include <cstddef>
#include <vector>

#include <benchmark/benchmark.h>

#include "runtime/core/rng.hpp"
#include "runtime/genome/tree/convert.hpp"
#include "runtime/genome/tree/init.hpp"
#include "runtime/genome/tree/program.hpp"
#include "runtime/genome/tree/recursive.hpp"

namespace {

using namespace esc;
using namespace esc::genome::tree;

PrimitiveSet bench_set() {
  using expr::Op;
  std::vector<Primitive> p;
  for (Op op : {Op::Add, Op::Sub, Op::Mul, Op::Div, Op::Min, Op::Max, Op::Abs, Op::Lt, Op::Gt, Op::And})
    p.push_back(prim::function(op));
  p.push_back(prim::if_then_else(Type::Number));
  p.push_back(prim::erc(-1.0, 1.0));
  for (const char* name : {"ir[0]", "ir[1]", "ir[2]", "ir[3]", "ir[4]", "ir[5]", "speed"})
    p.push_back(*prim::observable(name));
  return PrimitiveSet(std::move(p), Type::Number);
}

struct Workload {
  PrimitiveSet set = bench_set();
  std::vector<Tree> trees;
  std::vector<expr::Frame> frames;
  std::size_t nodes = 0;
};

// 64 trees whose sizes lie within 20% of `size`, and 256 frames of sensor readings.
const Workload& workload(std::size_t size) {
  static std::vector<std::pair<std::size_t, Workload>> cache;
  for (const auto& [s, w] : cache)
    if (s == size) return w;
  Workload w;
  Rng rng(size, {7});
  while (w.trees.size() < 64) {
    const int depth = 2 + static_cast<int>(rng.below(12));
    Tree t = rng.uniform() < 0.5 ? grow(w.set, Type::Number, depth, rng) : full(w.set, Type::Number, depth, rng);
    if (t.size() * 5 < size * 4 || t.size() * 5 > size * 6) continue;
    w.nodes += t.size();
    w.trees.push_back(std::move(t));
  }
  for (int k = 0; k < 256; ++k) {
    expr::Frame f{};
    for (double& v : f) v = rng.uniform();
    w.frames.push_back(f);
  }
  cache.emplace_back(size, std::move(w));
  return cache.back().second;
}

void report(benchmark::State& state, const Workload& w) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * w.trees.size() * w.frames.size()));
  state.counters["nodes/tree"] = static_cast<double>(w.nodes) / static_cast<double>(w.trees.size());
}

void BM_GpFlat(benchmark::State& state) {
  const Workload& w = workload(static_cast<std::size_t>(state.range(0)));
  std::vector<FlatProgram> progs;
  for (const Tree& t : w.trees) progs.push_back(compile(t, w.set));
  FlatProgram::Stack stack{};
  for (auto _ : state) {
    double sum = 0.0;
    for (const FlatProgram& p : progs)
      for (const expr::Frame& f : w.frames) sum += p.run(f, stack).value;
    benchmark::DoNotOptimize(sum);
  }
  report(state, w);
}

void BM_GpRecursive(benchmark::State& state) {
  const Workload& w = workload(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    double sum = 0.0;
    for (const Tree& t : w.trees)
      for (const expr::Frame& f : w.frames) sum += evaluate_number(t, w.set, f, t.root());
    benchmark::DoNotOptimize(sum);
  }
  report(state, w);
}

void BM_GpExprProgram(benchmark::State& state) {
  const Workload& w = workload(static_cast<std::size_t>(state.range(0)));
  std::vector<expr::Program> progs;
  for (const Tree& t : w.trees) progs.push_back(to_expr_program(t, w.set, t.root()));
  for (auto _ : state) {
    double sum = 0.0;
    for (const expr::Program& p : progs)
      for (const expr::Frame& f : w.frames) sum += p.eval(f);
    benchmark::DoNotOptimize(sum);
  }
  report(state, w);
}

}  // namespace

BENCHMARK(BM_GpFlat)->Arg(15)->Arg(50)->Arg(150);
BENCHMARK(BM_GpRecursive)->Arg(15)->Arg(50)->Arg(150);
BENCHMARK(BM_GpExprProgram)->Arg(15)->Arg(50)->Arg(150);
