#include "cli/interrupt.hpp"

#include <atomic>
#include <csignal>
#include <string>

#include <unistd.h>

#include <fmt/format.h>

namespace esc::cli {

namespace {

// The line to print, made beforehand: a signal handler may only write it.
std::atomic<const std::string*> line{nullptr};

extern "C" void interrupted(int signal) {
  if (const std::string* text = line.load()) {
    // Past the live progress line, if one is open.
    (void)!::write(STDERR_FILENO, text->data(), text->size());
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void on_interrupt_name(const std::filesystem::path& dir) {
  // Kept for the life of the process: the handler may read it at any moment.
  static std::string text;
  line.store(nullptr);
  text = fmt::format("\nesc: stopped; {} holds every generation finished so far: `esc run --resume {}` continues "
                     "it\n",
                     dir.string(), dir.string());
  line.store(&text);
  std::signal(SIGINT, interrupted);
  std::signal(SIGTERM, interrupted);
}

}  // namespace esc::cli
