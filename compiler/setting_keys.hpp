#pragma once
// Every key of `esc run --set KEY=VALUE`, each read by the table of its group (the
// experiment's own settings, each algorithm's: the ES's bare, `gp.*`, `cmaes.*`, ...;
// `robot.*`, `arena.*`) with the script's spellings, units and checks; the checks of a
// whole experiment's settings (options that relate, each algorithm's, the tree operators',
// the runtime's rules for the robot and the arena); and the
// resolved settings. `apply_setting` (compiler.hpp) is set_setting + check_settings on
// text; a script construct that varies a key over values written in the script can call
// the same two functions with its own values and locations.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/rule_messages.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

// `text` without the spaces and tabs around it, as a `--set` key or value is read.
[[nodiscard]] std::string trimmed(std::string_view text);

// Every `--set` key, for "did you mean" and the documentation.
[[nodiscard]] std::vector<std::string> setting_keys();

// The groups of settings: `robot.NAME` is read by the robot's table, and so on; each
// algorithm's, `gp.NAME`, by its own (algorithm_options.hpp).
inline constexpr std::string_view kRobotGroup = "robot.", kArenaGroup = "arena.";

// Whether `word` begins the keys of a group of settings: `robot`, `arena`, `body2`, `gp`,
// `cmaes`, ...
[[nodiscard]] bool is_setting_group(std::string_view word);

// `body2.KEY`: robot setting KEY of one body of a group alone, by its place in the group's list
// (`body1` the first; `robot.KEY` sets every body). A key that names a body by a number with a
// leading zero (`body02`) is one too, refused when set: it would be a second name for `body2`.
struct BodyKey {
  std::size_t body = 0;    // from 0
  std::string_view name;   // KEY
  bool leading_zero = false;
};
[[nodiscard]] std::optional<BodyKey> body_key(std::string_view key);
// Whether `word` is what begins such a key: `body` and digits.
[[nodiscard]] bool is_body_group(std::string_view word);

// Why keys a and b cannot be set together, or nullopt: `robot.KEY` sets every body, so that with
// `bodyN.KEY` one would silently override the other, in whichever order they came.
[[nodiscard]] std::optional<RuleMessage> overlapping_keys(std::string_view a, std::string_view b);

// Whether `key`'s value is a range (`bounds`, `gp.init_depth`).
[[nodiscard]] bool setting_takes_range(std::string_view key);

// Sets `key` of `spec` to `value` (written as in a script: `50ms`, `on`, `comma`,
// `[-1, 1]`); reports an unknown key at `key`, a wrong value at `value`. False when refused.
// `scope`: what the script wrote before the key (`energy.`), shown in an unknown key's message.
bool set_setting(eval::ExperimentSpec& spec, const ast::Name& key, const ast::Value& value, Sink& sink,
                 std::string_view scope = {});

// The checks of the settings together, reported at `where`: an algorithm's options that
// relate (the ES's comma needs lambda >= mu), its settings against the controllers it
// evolves, the tree operators against the trees' primitives, and the runtime's
// rules for the robot, the arena and the robot in it. False when one fails.
bool check_settings(const eval::ExperimentSpec& spec, const SourceRange& where, Sink& sink);
// The items a group's errors point at, where given (else at check_group's `where`).
struct GroupItems {
  const SourceRange* formation = nullptr;
  const SourceRange* roles = nullptr;
};
// What a group (`robot NAME x N`, `--set robots=N`) needs: roles no more than its robots, each a
// network of fixed topology; a formation its robots can take, else room for its random starts
// (its robots' discs at most 40% of the arena's free floor); one error each.
void check_group(const eval::ExperimentSpec& spec, const SourceRange& where, Sink& sink, GroupItems items = {});

// Rewrites the keys of resolved_settings that the spec's fields determine, the settings a
// study gives its dependencies among them (`energy.generations`); keeps the others (robot
// name, fitness sources).
void resolve_settings(eval::ExperimentSpec& spec);

}  // namespace esc::compiler
