#pragma once
// The options of `evolve es(...)` (runtime/evo/es.hpp's EsSettings): one table for scripts,
// `esc run --set KEY=VALUE`, resolved settings and the documentation, with one spelling per
// value (a choice's words, `comma`, `no_recombination`, are written alone in `es(...)` and
// as `--set selection=comma`), and every check of ES settings: each option's own value
// (read_es_option) and the ones that relate options (es_problem).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/setting_values.hpp"
#include "compiler/sink.hpp"
#include "runtime/evo/es.hpp"

namespace esc::compiler {

struct EsOption {
  // In `es(...)` (a choice: the group, whose words are written alone), `--set KEY` and
  // resolved_settings, unless `own_key` is false (`generations`: `--set generations` and
  // the resolved `generations` are the experiment's, for the ES and the GP alike).
  std::string_view key;
  OptionShape shape;
  std::string_view summary;
  // Reads `v`, checks it alone and stores it; reports at `v`.
  bool (*read)(const EsOption& o, evo::EsSettings& s, const ast::Value& v, Sink& sink);
  std::string (*text)(const EsOption& o, const evo::EsSettings& s);
  std::vector<std::string> words = {};   // a choice's values
  bool own_key = true;
};

[[nodiscard]] const std::vector<EsOption>& es_options();
// The option written `word` in `es(...)`: its key, or one of a choice's words.
[[nodiscard]] const EsOption* find_es_option_word(std::string_view word);
// The option of `--set` key `key`.
[[nodiscard]] const EsOption* find_es_option_key(std::string_view key);
// Every word `es(...)` accepts, for "did you mean" and the documentation.
[[nodiscard]] std::vector<std::string> es_option_words();

// A problem between options (comma selection needs lambda >= mu), or nullopt.
struct EsProblem {
  std::string message, help;
};
[[nodiscard]] std::optional<EsProblem> es_problem(const evo::EsSettings& s);

// `evolve es(...) [for N generations]` -> `es`; problems reported.
void lower_es_item(const ast::ExpItem& item, evo::EsSettings& es, Sink& sink);

}  // namespace esc::compiler
