#pragma once
// Where an optimizer's members were measured (Measured), kept in its state beside its core's:
// a replay of a front member or an archive cell needs its own evaluation's seed, and a run
// resumed from the state must still know it. The core (Nsga2, qd::MapElites) is the
// algorithm and knows nothing of runs; its run-level adapter keeps the origins in step with
// it and saves both under a tag of its own. A state saved before origins were kept is the
// core's bytes alone, which begin with the core's own tag: it reads with every origin unknown.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/evo/optimizer.hpp"
#include "runtime/evo/state_bytes.hpp"

namespace esc::evo {

void put_measured(StateWriter& w, std::span<const Measured> measured);
// std::invalid_argument for a generation below -1 or a count past the end.
[[nodiscard]] std::vector<Measured> get_measured(StateReader& r);

[[nodiscard]] StateBytes save_with_measured(std::string_view tag, const StateBytes& core,
                                            std::span<const Measured> measured);

struct CoreAndMeasured {
  StateBytes core;
  std::optional<std::vector<Measured>> measured;   // none in a state saved before
};
// The core's bytes and the origins of a state save_with_measured wrote under `tag`, or of
// an older one (the core's bytes alone). std::invalid_argument for a damaged state.
[[nodiscard]] CoreAndMeasured read_with_measured(std::string_view tag, std::span<const std::uint8_t> bytes);

// The origins read from a state for `count` members (`members`: "parents", "filled cells"),
// all unknown for a state saved before they were kept; std::invalid_argument, naming `what`
// (the algorithm), when there is not one per member.
[[nodiscard]] std::vector<Measured> measured_for(std::optional<std::vector<Measured>> stored, std::size_t count,
                                                 const std::string& what, const std::string& members);

}  // namespace esc::evo
