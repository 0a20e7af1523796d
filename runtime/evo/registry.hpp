#pragma once
// Every optimizer a script can name, in one table: its name, what it evolves, how to make
// one, and the version of the state it saves. Adding an algorithm is a folder of its own
// under runtime/evo/ and a row in registry.cpp (docs/optimizers.md).
#include <any>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/algorithm_options.hpp"
#include "runtime/evo/memory_peak.hpp"
#include "runtime/evo/optimizer.hpp"
#include "runtime/genome/kind.hpp"

namespace esc::evo {

struct Algorithm {
  std::string_view name;          // as scripts and stored states name it
  // The layout of save()'s bytes: a stored state of another format is refused, not misread.
  std::uint32_t state_format = 1;
  genome::GenomeKinds kinds;      // what it evolves: a network's weights, trees, ...
  // A fresh optimizer for one run; `settings` holds the algorithm's own settings type (as
  // the compiler made it). Throws std::invalid_argument on impossible settings.
  std::unique_ptr<Optimizer> (*make)(const std::any& settings, const Problem& problem) = nullptr;
  // Candidates of a run's first generation for `problem` (its genome_size 0 for a tree):
  // what the campaign sizes its rounds by. These three read only the problem's sizes and
  // declared ranges, never its seed or start.
  std::size_t (*population)(const std::any& settings, const Problem& problem) = nullptr;
  // What one run of `generations` holds at its peak (memory_peak.hpp): what the campaign's
  // memory check counts for it, and names when it cannot fit.
  MemoryPeak (*memory)(const std::any& settings, const Problem& problem, int generations) = nullptr;
  // Its options as scripts write them, its default settings, and why settings cannot run on
  // `problem` ("" when they can: an archive's cells need declared descriptors, ...). Null
  // for the paper's ES and GP, whose options the compiler keeps in tables of their own
  // (their historic keys).
  std::string_view what = {};     // in messages: "CMA-ES", "the ES"
  const std::vector<AlgorithmOption>& (*options)() = nullptr;
  std::any (*defaults)() = nullptr;
  std::string (*problem)(const std::any& settings, const Problem& problem) = nullptr;
};

[[nodiscard]] const std::vector<Algorithm>& algorithms();
// The algorithm called `name`, or null.
[[nodiscard]] const Algorithm* find_algorithm(std::string_view name) noexcept;

// The state a run evaluating a stored genome keeps (none), named so that the store tells it
// from an algorithm's.
inline constexpr std::string_view kEvaluateOnly = "evaluate";

}  // namespace esc::evo
