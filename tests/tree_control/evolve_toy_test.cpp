// A short GP run evolving a tree controller on a toy obstacle-avoidance task: the GP
// engine (esc_gp) and the controller that runs its trees (esc_tree_control) together.
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <numbers>

#include <gtest/gtest.h>

#include "runtime/evo/gp/gp.hpp"
#include "runtime/genome/tree/print.hpp"
#include "runtime/tree_control/tree_controller.hpp"

namespace esc::evo::gp {
namespace {

using namespace genome::tree;

using expr::Op;

// A disc robot in a 1 m square, kinematic differential drive, 6 front "IR" rays that see
// the walls up to 10 cm. Fitness: the paper's V (1 - sqrt(dv)) (1 - i) summed over steps.
struct ToyWorld {
  double x = 0.5, y = 0.5, heading = 0.0;

  static constexpr double kRadius = 0.03, kRange = 0.1, kStep = 0.01;

  // Distance along a ray from (x, y) to the walls of [0, 1]^2.
  static double ray(double x, double y, double a) {
    const double dx = std::cos(a), dy = std::sin(a);
    double t = 1e9;
    if (dx > 1e-12) t = std::min(t, (1.0 - x) / dx);
    if (dx < -1e-12) t = std::min(t, -x / dx);
    if (dy > 1e-12) t = std::min(t, (1.0 - y) / dy);
    if (dy < -1e-12) t = std::min(t, -y / dy);
    return t;
  }

  void sense(expr::Frame& f) const {
    constexpr std::array<double, 6> angles = {1.2, 0.8, 0.3, -0.3, -0.8, -1.2};
    for (std::size_t k = 0; k < 6; ++k) {
      const double d = ray(x, y, heading + angles[k]) - kRadius;
      f[expr::slot::ir + k] = std::clamp(1.0 - d / kRange, 0.0, 1.0);
    }
  }

  // Moves with wheel commands in [-1, 1]; returns the step's fitness term.
  double move(control::WheelCommand c, const expr::Frame& f) {
    const double v = 0.5 * (c.left + c.right), w = (c.right - c.left) / 0.053 * 0.5;
    heading += w * kStep * 0.05;
    const double nx = x + std::cos(heading) * v * kStep, ny = y + std::sin(heading) * v * kStep;
    if (nx > kRadius && nx < 1 - kRadius && ny > kRadius && ny < 1 - kRadius) {
      x = nx;
      y = ny;
    }
    double i = 0.0;
    for (std::size_t k = 0; k < 6; ++k) i = std::max(i, f[expr::slot::ir + k]);
    const double speed = (std::abs(c.left) + std::abs(c.right)) / 2.0;
    const double dv = std::abs(c.left - c.right) / 2.0;
    return speed * (1.0 - std::sqrt(dv)) * (1.0 - i);
  }
};

double avoidance_fitness(tree_control::TreeController& ctl, std::uint64_t seed) {
  double total = 0.0;
  for (std::uint64_t epoch = 0; epoch < 3; ++epoch) {
    Rng rng(seed, {epoch});
    ToyWorld w{rng.uniform(0.2, 0.8), rng.uniform(0.2, 0.8), rng.uniform(0.0, 2 * std::numbers::pi)};
    ctl.reset();
    expr::Frame f{};
    for (int s = 0; s < 150; ++s) {
      w.sense(f);
      total += w.move(ctl.step(f), f);
    }
  }
  return total / 450.0;
}

TEST(GeneticProgramming, ObstacleAvoidanceToyImproves) {
  std::vector<Primitive> p = {prim::function(Op::Add), prim::function(Op::Sub),
                              prim::function(Op::Mul), prim::function(Op::Max),
                              prim::function(Op::Gt),  prim::if_then_else(Type::Number),
                              prim::erc(-1, 1),        prim::wheels()};
  for (int k = 0; k < 6; ++k) p.push_back(*prim::observable("ir[" + std::to_string(k) + "]"));
  const tree_control::TreeControllerSpec spec{"toy", PrimitiveSet(std::move(p), Type::Wheels), {}, {}};
  GpSettings s;
  s.population = 60;
  s.tournament = 3;
  s.elitism = 2;
  s.max_depth = 7;
  s.max_size = 40;
  s.init_max_depth = 4;
  const GeneticProgramming gp(s, spec.primitives);
  Rng init(99);
  auto pop = gp.initial(init);
  tree_control::TreeController ctl(spec, pop[0].tree);
  std::vector<double> best;
  for (int g = 0;; ++g) {
    for (Individual& ind : pop) {
      ctl.rebind(ind.tree);
      ind.fitness = avoidance_fitness(ctl, 2024);
    }
    best.push_back(pop[ranking(pop).front()].fitness);
    if (g == 12) break;
    Rng breed(99, {static_cast<std::uint64_t>(g)});
    pop = gp.breed(pop, breed);
  }
  EXPECT_GT(best.back(), best.front());
  EXPECT_GT(best.back(), 0.3);
  const Tree& champion = pop[ranking(pop).front()].tree;
  RecordProperty("best", to_script(champion, spec.primitives));
  std::cout << "toy avoidance: best " << best.front() << " -> " << best.back() << ": "
            << to_script(champion, spec.primitives) << "\n";
}

}  // namespace
}  // namespace esc::evo::gp
