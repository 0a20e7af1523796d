#pragma once
// The streams every optimizer draws from (optimizer.hpp's contract), in one place: what a
// run starts from, Rng(seed, Init), and generation g's candidates, Rng(seed, Breed, g).
#include <cstdint>

#include "runtime/core/rng.hpp"
#include "runtime/evo/optimizer.hpp"

namespace esc::evo {

[[nodiscard]] inline Rng init_stream(std::uint64_t seed) {
  return Rng(seed, {static_cast<std::uint64_t>(Stream::Init)});
}

[[nodiscard]] inline Rng breed_stream(std::uint64_t seed, int generation) {
  return Rng(seed, {static_cast<std::uint64_t>(Stream::Breed), static_cast<std::uint64_t>(generation)});
}

// Starts a core that samples its first generation (CMA-ES, NSGA-II) as every run starts:
// from the run's start genome when it has one, else from the init stream.
template <class Core>
void start_core(Core& core, const Problem& problem) {
  if (problem.start != nullptr) {
    core.start(*problem.start);
  } else {
    Rng init = init_stream(problem.seed);
    core.start(init);
  }
}

}  // namespace esc::evo
