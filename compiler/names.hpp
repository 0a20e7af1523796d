#pragma once
// Name lookup helpers: edit distance and every "did you mean" of the compiler (`suggest`).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/diagnostic.hpp"

namespace esc::compiler {

// Levenshtein distance (insertions, deletions, substitutions, adjacent transpositions).
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

// The closest candidate when it is close enough to be a plausible misspelling of `word`.
[[nodiscard]] std::optional<std::string> closest(std::string_view word,
                                                 const std::vector<std::string>& candidates);

// What `suggest` adds besides the suggestion.
struct Suggestion {
  std::string_view prefix = {};   // written before the suggested name (`gp.`, `robot.`)
  std::string otherwise = {};     // a help line when no candidate is close ("" for none)
  bool always = false;            // add `otherwise` even after a suggestion
};

// Appends "; did you mean `PREFIXx`?" to `d`'s message when a candidate is close to `word`,
// and adds `how.otherwise` as a help line when none is (or always). True when it suggested.
bool suggest(Diagnostic& d, std::string_view word, const std::vector<std::string>& candidates,
             const Suggestion& how = {});

// "`a`, `b` or `c`".
[[nodiscard]] std::string quoted_list(const std::vector<std::string>& items,
                                      std::string_view last_sep = " or ");

}  // namespace esc::compiler
