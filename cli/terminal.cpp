#include "cli/terminal.hpp"

#include <cstdlib>

#include <sys/ioctl.h>
#include <unistd.h>

namespace esc::cli {

namespace {

bool continuation_byte(char c) { return (static_cast<unsigned char>(c) & 0xC0U) == 0x80U; }

}  // namespace

int terminal_columns(int fd) {
  winsize size{};
  if (ioctl(fd, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  if (const char* env = std::getenv("COLUMNS")) {
    char* end = nullptr;
    const long columns = std::strtol(env, &end, 10);
    if (end != env && *end == '\0' && columns > 0 && columns < 100000) return static_cast<int>(columns);
  }
  return 80;
}

std::size_t display_width(std::string_view text) {
  std::size_t width = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\033') {   // CSI: ESC [ parameters final-byte
      if (i + 1 < text.size() && text[i + 1] == '[') {
        i += 2;
        while (i < text.size() && (text[i] < 0x40 || text[i] > 0x7E)) ++i;
      }
      continue;
    }
    if (!continuation_byte(text[i]) && text[i] != '\r' && text[i] != '\n') ++width;
  }
  return width;
}

std::string fit_width(std::string_view text, std::size_t columns) {
  std::size_t width = 0;
  std::size_t end = 0;
  for (; end < text.size(); ++end) {
    if (continuation_byte(text[end])) continue;
    if (width == columns) break;
    ++width;
  }
  return std::string(text.substr(0, end));
}

}  // namespace esc::cli
