#pragma once
// A network's weights as NSGA-II and MAP-Elites search them: n real genes, each in
// [lower, upper]; the first genomes uniform in that box.
#include "runtime/genome/representation.hpp"

namespace esc::genome {

class Box final : public Representation {
 public:
  Box(std::size_t n, double lower, double upper) : n_(n), lower_(lower), upper_(upper) {}

  [[nodiscard]] std::string_view what() const override { return "a network's weights"; }
  [[nodiscard]] std::string_view tag() const override { return ""; }
  [[nodiscard]] std::size_t genes() const override { return n_; }
  // Candidate by candidate, gene by gene: rng.uniform(lower, upper).
  [[nodiscard]] std::vector<Genome> first(std::size_t count, Rng& rng) const override;
  [[nodiscard]] std::string misfit(std::span<const double> genome) const override;
  [[nodiscard]] std::vector<FixedSetting> fixed() const override { return {{"lower", lower_}, {"upper", upper_}}; }

  [[nodiscard]] double lower() const noexcept { return lower_; }
  [[nodiscard]] double upper() const noexcept { return upper_; }

 private:
  std::size_t n_;
  double lower_;
  double upper_;
};

}  // namespace esc::genome
