#include "cli/interrupt.hpp"

#include <array>
#include <atomic>
#include <csignal>
#include <string>

#include <unistd.h>

#include <fmt/format.h>

namespace esc::cli {

namespace {

// What the handler writes, made beforehand: a signal handler may only write. The counts
// are written digit by digit there (snprintf is not async-signal-safe).
std::atomic<const std::string*> line{nullptr};
std::atomic<std::int64_t> done{-1};
std::atomic<std::int64_t> total{0};

void put(std::string_view s) { (void)!::write(STDERR_FILENO, s.data(), s.size()); }

void put(std::int64_t n) {
  std::array<char, 24> digits{};
  std::size_t at = digits.size();
  do {
    digits[--at] = static_cast<char>('0' + n % 10);
    n /= 10;
  } while (n > 0 && at > 0);
  put(std::string_view(digits.data() + at, digits.size() - at));
}

extern "C" void interrupted(int signal) {
  if (const std::string* text = line.load()) {
    // Past the live progress line, if one is open.
    put("\nesc: stopped");
    if (const std::int64_t d = done.load(), t = total.load(); d >= 0 && t > 0) {
      put(" after ");
      put(d);
      put(" of ");
      put(t);
      put(t == 1 ? " generation" : " generations");
      put(" (all runs together)");
    }
    put(*text);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void on_interrupt_name(const std::filesystem::path& dir) {
  // Kept for the life of the process: the handler may read it at any moment.
  static std::string text;
  line.store(nullptr);
  done.store(-1);
  text = fmt::format("; {} holds every generation finished: `esc run --resume {}` continues it\n", dir.string(),
                     dir.string());
  line.store(&text);
  std::signal(SIGINT, interrupted);
  std::signal(SIGTERM, interrupted);
}

void on_interrupt_count(std::int64_t generations_done, std::int64_t generations) {
  total.store(generations);
  done.store(generations_done);
}

}  // namespace esc::cli
