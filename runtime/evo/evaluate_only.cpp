#include "runtime/evo/evaluate_only.hpp"

#include <stdexcept>

namespace esc::evo {

namespace {

class EvaluateOnly final : public Optimizer {
 public:
  explicit EvaluateOnly(Genome genome) : genome_(std::move(genome)) {}
  std::vector<Genome> ask(int /*generation*/) override { return {genome_}; }
  void tell(std::span<const Outcome> /*outcomes*/) override {}
  StateBytes save() const override { return {}; }
  void load(std::span<const std::uint8_t> state) override {
    if (!state.empty()) throw std::invalid_argument("evaluating a stored genome keeps no state, found one");
  }

 private:
  Genome genome_;
};

}  // namespace

std::unique_ptr<Optimizer> make_evaluate_only(const Problem& problem) {
  if (problem.start == nullptr) throw std::invalid_argument("evaluating a stored genome needs the genome");
  return std::make_unique<EvaluateOnly>(*problem.start);
}

}  // namespace esc::evo
