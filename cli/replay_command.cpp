// `esc replay` (app/replay.hpp): replays stored controllers and says, line by line, what each
// replay wrote and whether it matched what the run stored; with --animate, an animation of
// each too (cli/replay_animation.hpp).
#include <cstdio>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "app/error.hpp"
#include "app/replay.hpp"
#include "cli/commands.hpp"
#include "cli/load.hpp"
#include "cli/replay_animation.hpp"
#include "cli/table_text.hpp"
#include "cli/terminal_events.hpp"

namespace esc::cli {

namespace {

// Prints each subject as it is done, animates it where asked, and keeps the exit status.
class ReplayPrinter final : public app::ReplayListener {
 public:
  explicit ReplayPrinter(bool animate) : animate_(animate) {}

  void replayed(const app::ReplayedSubject& s) override {
    for (const std::string& problem : s.problems) complain("esc: error: {}\n", problem);
    if (!s.problems.empty()) status_ = kExitBadInput;
    if (!s.replayed) return;
    // A member whose evaluation is not known (a state saved before origins were kept) is
    // replayed with its run's best's seed: its stored value is printed beside.
    const std::string own = s.own_fitness ? fmt::format("; {:.17g} in its own evaluation", *s.own_fitness) : std::string();
    const char* agrees = s.identical_to_stored_replay ? ", identical to the stored replay"
                         : s.as_in_own_evaluation     ? ", as in its own evaluation"
                                                      : "";
    say("esc: replayed {} run {}{} in {} (fitness {:.{}f}{}{}): {}/{}.svg, .csv\n", s.controller, s.run + 1,
        s.member.empty() ? "" : " " + s.member, s.experiment, s.fitness, fitness_decimals(s.fitness, 2), own, agrees,
        s.out.string(), s.stem);
    // A member's descriptors place it in its cell: shown, and checked against the stored.
    if (!s.member.empty() && !s.descriptors.empty())
      say("esc: {} descriptors: {}{}\n", s.member, app::descriptors_text(s.descriptors),
          s.descriptors_as_stored ? " (as stored)" : "");
    if (animate_) {
      const std::optional<std::filesystem::path> movie = write_animation(s.figure(), s.out / s.stem);
      if (!movie) {
        status_ = kExitBadInput;
        return;
      }
      say("esc: animation: {}\n", movie->string());
    }
  }

  // One line at every tenth of the run: a maze run made again takes minutes.
  void generation_made_again(const std::string& who, int done, int generations) override {
    if (done * 10 / generations != (done - 1) * 10 / generations || done == generations) {
      say("esc: {} made again: {} of {} generations\n", who, done, generations);
      std::fflush(stdout);
    }
  }

  void evaluations_replayed(const app::ReplayedEvaluations& e) override {
    say("esc: {} run {} made again, identical to the stored run in every generation: {} evaluations in {}/{}.csv{}\n",
        e.controller, e.run + 1, e.evaluations, e.out.string(), e.stem, e.svg ? ", .svg" : "");
  }

  [[nodiscard]] int status() const noexcept { return status_; }

 private:
  bool animate_;
  int status_ = kExitOk;
};

}  // namespace

int replay_command(const ReplayOptions& o) {
  TerminalEvents events;
  ReplayPrinter printer(o.animate);
  try {
    (void)app::replay(o, default_compile_options(), events, printer);
  } catch (const app::Error& e) {
    if (e.kind() != app::ErrorKind::Request) throw;
    print_error(e);
    return kExitUsage;
  }
  return printer.status();
}

}  // namespace esc::cli
