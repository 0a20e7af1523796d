#pragma once
// Source text helpers: UTF-8 validation and repair, lines, columns in characters.
#include <string>
#include <string_view>
#include <vector>

namespace esc::compiler {

struct CleanText {
  std::string display;      // invalid bytes replaced by U+FFFD (kept for rendering)
  std::string parser;       // invalid bytes replaced by a space (fed to the lexer)
  struct Bad {
    int line;
    int column;             // 1-based, in characters
  };
  std::vector<Bad> invalid; // first invalid byte of each line that has one
};

// Replaces every byte that is not part of valid UTF-8 by one replacement character, so
// columns agree between what the lexer sees and what diagnostics show.
[[nodiscard]] CleanText clean_utf8(std::string_view text);

// Number of characters (code points) in valid UTF-8.
[[nodiscard]] int utf8_length(std::string_view s) noexcept;

// `text` with every backquoted name longer than kLongName characters shortened to its
// start and end around `…`, followed by its length: "`abcdefgh…uvwxyz` (3000000
// characters)". A message never echoes a pasted megabyte whole. A backquoted command
// (`esc ...`) is kept whole however long: it is advice to paste, and a cut one would not run.
inline constexpr int kLongName = 64;
[[nodiscard]] std::string shorten_names(std::string_view text);

// Line `line` (1-based) of `text`, without its line break; empty when out of range.
[[nodiscard]] std::string_view line_of(std::string_view text, int line) noexcept;

}  // namespace esc::compiler
