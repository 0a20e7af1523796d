#pragma once
// What the command line's output needs to know about the terminal: whether a stream is one,
// how many columns it has, and how wide a text is there, so that a line redrawn in place
// never wraps (a wrapped line leaves its first part behind at every redraw).
#include <cstddef>
#include <string>
#include <string_view>

namespace esc::cli {

// Columns of the terminal on file descriptor `fd`: the terminal's own size, else $COLUMNS,
// else 80.
[[nodiscard]] int terminal_columns(int fd);

// Columns `text` takes on a terminal: one per UTF-8 code point (the progress line holds no
// wide characters), escape sequences excluded.
[[nodiscard]] std::size_t display_width(std::string_view text);

// Plain `text` (no escape sequences) cut to at most `columns` columns, never inside a UTF-8
// sequence.
[[nodiscard]] std::string fit_width(std::string_view text, std::size_t columns);

}  // namespace esc::cli
