#include "bench/plain_workloads.hpp"

#include <iterator>
#include <stdexcept>

namespace esc::bench::plain {

Result Obstacle::evaluate(std::span<const double> genome, std::uint64_t seed) {
  const Setup& s = world_.setup();
  std::mt19937_64 rng(seed);
  Result result;
  double ir[8];
  for (int epoch = 0; epoch < s.epochs; ++epoch) {
    Robot r = world_.random_start(rng);
    net_.reset();
    world_.read_ir(r, ir);
    for (int step = 0; step < s.steps; ++step) {
      double left = 0, right = 0;
      symbolic_action(logistic(net_.sums(genome.data(), ir)), left, right);
      const Robot before = r;
      const bool hit = world_.step(r, left, right, nullptr);
      world_.read_ir(r, ir);
      result.fitness += world_.forward_term(before, r);
      ++result.steps;
      if (hit) break;
    }
  }
  return result;
}

namespace {

// The energy workloads' epoch: a zone, a start, then steps of (inputs -> command) until the
// accumulator is empty. `control` maps the 17 inputs (8 IR, 8 light, level) to a command;
// `reset` starts an epoch.
template <class Reset, class Control>
void energy_epochs(World& world, std::mt19937_64& rng, Result& result, Reset&& reset, Control&& control) {
  const Setup& s = world.setup();
  double in[17];
  const auto sense = [&](const Robot& r, const Accumulator& a) {
    world.read_ir(r, in);
    world.read_light(r, in + 8);
    in[16] = a.level();
  };
  for (int epoch = 0; epoch < s.epochs; ++epoch) {
    world.place_zone(rng);
    Robot r = world.random_start(rng);
    Accumulator energy(s);
    reset();
    sense(r, energy);
    for (int step = 0; step < s.steps; ++step) {
      double left = 0, right = 0;
      control(in, left, right);
      const Robot before = r;
      world.step(r, left, right, &energy);
      sense(r, energy);
      if (!world.in_zone(r)) result.fitness += world.forward_term(before, r);
      ++result.steps;
      if (energy.units == 0) break;
    }
  }
}

}  // namespace

Result Energy::evaluate(std::span<const double> genome, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Result result;
  energy_epochs(world_, rng, result, [&] { net_.reset(); }, [&](const double* in, double& left, double& right) {
    const Vector<2> out = net_.sums(genome.data(), in).array().tanh();
    left = out[0];
    right = out[1];
  });
  return result;
}

Supervisor::Supervisor(const Setup& s, std::vector<std::vector<double>> behaviors)
    : world_(s), genomes_(std::move(behaviors)) {
  constexpr std::size_t sizes[] = {decltype(avoid_)::kWeights, decltype(follow_)::kWeights, decltype(stop_)::kWeights,
                                   decltype(sweep_)::kWeights};
  if (genomes_.size() != std::size(sizes)) throw std::invalid_argument("the plain supervisor takes four behaviors");
  for (std::size_t b = 0; b < genomes_.size(); ++b)
    if (genomes_[b].size() != sizes[b])
      throw std::invalid_argument("a plain supervisor's behavior genome has the wrong size");
}

Result Supervisor::evaluate(std::span<const double> genome, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Result result;
  energy_epochs(world_, rng, result, [&] { net_.reset(); }, [&](const double* in, double& left, double& right) {
    const Vector<4> choice = logistic(net_.sums(genome.data(), in));
    int b = 0;
    for (int i = 1; i < 4; ++i)
      if (choice[i] > choice[b]) b = i;
    const double* g = genomes_[static_cast<std::size_t>(b)].data();
    const Vector<6> sums = b == 0   ? avoid_.sums(g, in)
                           : b == 1 ? follow_.sums(g, in)
                           : b == 2 ? stop_.sums(g, in)
                                    : sweep_.sums(g, in);
    symbolic_action(logistic(sums), left, right);
  });
  return result;
}

}  // namespace esc::bench::plain
