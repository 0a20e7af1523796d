#pragma once
// How `esc` shows the application layer's events and errors on a terminal or in a log: notes
// as `esc: ...` lines, warnings and errors on stderr (diagnostics colored on a terminal),
// progress as cli/progress.hpp draws it, each experiment's table at its end. Rank 0 of an
// MPI job alone prints.
#include "app/error.hpp"
#include "app/events.hpp"

namespace esc::cli {

class TerminalEvents final : public app::Events {
 public:
  void warnings(const compiler::CompileResult& compiled) override;
  void note(const app::Note& note) override;
  std::unique_ptr<app::Progress> progress(const eval::ExperimentSpec& spec, const std::string& condition,
                                          eval::CampaignListener& next, std::int64_t already_done) override;
  void experiment_done(const eval::ExperimentSpec& spec, const eval::CampaignResult& result) override;
};

// Prints `error` as `esc: error: ...` lines, with its hints, details and diagnostics.
void print_error(const app::Error& error);

}  // namespace esc::cli
