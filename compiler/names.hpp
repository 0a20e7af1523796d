#pragma once
// Name lookup helpers: "did you mean" suggestions by edit distance.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace esc::compiler {

// Levenshtein distance (insertions, deletions, substitutions, adjacent transpositions).
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

// The closest candidate when it is close enough to be a plausible misspelling of `word`.
[[nodiscard]] std::optional<std::string> closest(std::string_view word,
                                                 const std::vector<std::string>& candidates);

// "did you mean `x`?" when a candidate is close, else nullopt.
[[nodiscard]] std::optional<std::string> did_you_mean(std::string_view word,
                                                      const std::vector<std::string>& candidates);

// "`a`, `b` or `c`".
[[nodiscard]] std::string quoted_list(const std::vector<std::string>& items,
                                      std::string_view last_sep = " or ");

}  // namespace esc::compiler
