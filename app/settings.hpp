#pragma once
// Settings given for a run beside its script (esc's --runs, --generations, --seed, --set,
// --controllers, --cache): applied to an experiment, stored with the run, read back and
// applied again when it resumes.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/eval/experiment.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::app {

struct Overrides {
  std::optional<int> runs;
  std::optional<int> generations;
  std::optional<std::uint64_t> seed;
  std::vector<std::string> set;            // KEY=VALUE, as the script would say KEY VALUE
  std::vector<std::string> controllers;    // run only these compared controllers; empty: all
  std::filesystem::path cache;             // where dependencies run; empty: the run's deps/
};

// runs, generations, seed and each of `set` as (key, value). Throws Error (kind Setting) for
// an entry of `set` without `=`.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> setting_pairs(const Overrides& o);

// The overrides an experiment's dependencies take: every setting but one body's own
// (`bodyN.KEY`), since a dependency's body N may be another robot, or absent; `robot.KEY`
// reaches them as every other setting does.
[[nodiscard]] Overrides for_dependencies(Overrides o);

// Applies the settings of `o` (not its choice of controllers: a dependency takes the
// settings alone) to `spec`. Throws Error (kind Setting) with every problem, each after
// `where` (`condition `x`: `).
void apply_settings(const Overrides& o, eval::ExperimentSpec& spec, std::string_view where = {});

// Keeps the controllers of `spec` named in `names`, in that order, with the dependencies
// that fill their behaviors; no-op for an empty list. Every controller of a run draws from
// the same streams, so a controller's results do not depend on which others run beside it.
// Throws Error (kind Setting) naming each unknown or repeated name.
void select_controllers(const std::vector<std::string>& names, eval::ExperimentSpec& spec, std::string_view where = {});

// Throws Error (kind Memory) when the campaign of `spec` does not fit in this machine's
// memory (runtime/eval/memory_need.hpp). Asked before any directory is made.
void check_memory(const eval::ExperimentSpec& spec);

// As stored in a run's database, and read back (throws store::StoreError when damaged).
[[nodiscard]] nlohmann::ordered_json to_json(const Overrides& o);
[[nodiscard]] Overrides stored_overrides(const store::StoredExperiment& stored, const std::filesystem::path& dir);
[[nodiscard]] Overrides overrides_from_json(const nlohmann::ordered_json& ov, const std::filesystem::path& dir);

// The generations a carry-on took the stored run to (the experiment alone, not what it
// depends on); nullopt when it never was. Throws store::StoreError when damaged.
[[nodiscard]] std::optional<int> stored_carry_on(const store::StoredExperiment& stored, const std::filesystem::path& dir);

// `spec` run for `generations` (every algorithm's) when given; false when refused.
[[nodiscard]] bool set_generations(eval::ExperimentSpec& spec, std::optional<int> generations);

}  // namespace esc::app
