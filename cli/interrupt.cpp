#include "cli/interrupt.hpp"

#include <array>
#include <atomic>
#include <csignal>

#include <unistd.h>

#include <fmt/format.h>

namespace esc::cli {

namespace {

// What the handler writes, made beforehand: a signal handler may only write. The counts
// are written digit by digit there (snprintf is not async-signal-safe).
struct Lines {
  std::string resume;    // after the count: where the run is and how to continue it
  std::string restart;   // stopped before its first generation was stored
};
std::atomic<const Lines*> lines{nullptr};
std::atomic<std::int64_t> generations_stored{0};
std::atomic<std::int64_t> total{0};
std::atomic<bool> storing{false};   // a generation's commit is under way
std::atomic<int> deferred{0};       // the signal that came during it
// Set by the handler that says the line: a signal sent twice (GNU timeout signals the
// process and its group) reaches two threads at once, whose lines interleaved ("stopped
// after  after 11 of  of 2020 ..."). The first says it and ends the process; the other
// returns.
std::atomic<bool> saying{false};

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
  if (storing.load() && deferred.exchange(signal) == 0) return;   // stops when the commit ends
  if (saying.exchange(true)) return;
  if (const Lines* text = lines.load()) {
    // Past the live progress line, if one is open.
    put("\nesc: stopped");
    if (const std::int64_t d = generations_stored.load(), t = total.load(); d == 0) {
      put(text->restart);
    } else {
      if (t > 0) {
        put(" after ");
        put(d);
        put(" of ");
        put(t);
        put(t == 1 ? " generation" : " generations");
        put(" (all runs together)");
      }
      put(text->resume);
    }
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void on_interrupt_name(const std::filesystem::path& dir, std::int64_t generations, std::int64_t stored_already,
                       const std::string& restart) {
  // Kept for the life of the process: the handler may read it at any moment.
  static Lines text;
  lines.store(nullptr);
  total.store(generations);
  generations_stored.store(stored_already);
  text.resume = fmt::format("; {} holds every generation finished: `esc run --resume {}` continues it\n",
                            dir.string(), dir.string());
  text.restart = fmt::format(" before its first generation was stored; {} holds nothing to resume: {} (finished "
                             "dependencies in its deps/ are reused)\n",
                             dir.string(),
                             restart.empty() ? std::string("start it again as it was started")
                                             : fmt::format("`{}` starts it again", restart));
  lines.store(&text);
  std::signal(SIGINT, interrupted);
  std::signal(SIGTERM, interrupted);
}

StoringGeneration::StoringGeneration() { storing.store(true); }

StoringGeneration::~StoringGeneration() {
  storing.store(false);
  if (const int signal = deferred.exchange(0)) interrupted(signal);
}

void StoringGeneration::stored() { generations_stored.fetch_add(1); }

}  // namespace esc::cli
