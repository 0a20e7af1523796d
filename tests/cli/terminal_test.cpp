// The terminal measures behind the live progress line: widths in columns, not bytes, and
// the terminal's width from $COLUMNS when the stream is not a terminal that says.
#include "cli/terminal.hpp"

#include <unistd.h>

#include <cstdlib>

#include <gtest/gtest.h>

namespace esc::cli {
namespace {

TEST(Terminal, WidthCountsCodePointsNotBytesNorEscapes) {
  EXPECT_EQ(display_width("abc"), 3U);
  EXPECT_EQ(display_width("█░░ 5%"), 6U);   // 3-byte block characters
  EXPECT_EQ(display_width("\r\033[Kgen 1"), 5U);
}

TEST(Terminal, FitCutsBetweenCharacters) {
  EXPECT_EQ(fit_width("█████ run", 3), "███");
  EXPECT_EQ(fit_width("short", 80), "short");
  EXPECT_EQ(display_width(fit_width("█░ abcdefghij", 7)), 7U);
}

TEST(Terminal, ColumnsFromTheEnvironmentWhenNotATerminal) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  ASSERT_EQ(setenv("COLUMNS", "57", 1), 0);
  EXPECT_EQ(terminal_columns(fds[1]), 57);
  ASSERT_EQ(setenv("COLUMNS", "wide", 1), 0);
  EXPECT_EQ(terminal_columns(fds[1]), 80);
  ASSERT_EQ(unsetenv("COLUMNS"), 0);
  EXPECT_EQ(terminal_columns(fds[1]), 80);
  close(fds[0]);
  close(fds[1]);
}

}  // namespace
}  // namespace esc::cli
