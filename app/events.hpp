#pragma once
// What the application layer tells as it goes, to whoever drives it: the esc program prints
// it, the Python module calls back, an embedding program does what it likes. Every member
// does nothing by default; events reach rank 0 of an MPI job only.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "compiler/compiler.hpp"
#include "runtime/eval/campaign.hpp"

namespace esc::app {

// One line of what is being done, as `esc` prints it.
struct Note {
  enum class Kind {
    Start,        // a run or study starts into its directory
    Resume,       // a run or study resumes or is carried on
    Complete,     // a directory to resume has nothing left to do
    Condition,    // a study's condition starts
    Dependency,   // a dependency reused, run, continued, frozen or read
    Warning,      // something was set aside and the work goes on
  };
  Kind kind;
  std::string text;
  std::filesystem::path dir{};   // Start and Resume: the directory being written
  // Start and Resume: the generations of every run the directory is to hold (a study's:
  // every condition's), and how many of them it has stored already.
  std::int64_t generations = 0;
  std::int64_t generations_stored = 0;
  // Start: the command that starts the run again into `dir`, the way to go on when it stops
  // before its first generation is stored (nothing to resume then).
  std::string restart{};
};

// Sees a campaign's events before its run directory stores them: passes each on to `next`
// (the directory); an override watches what it likes and calls the base to pass it on.
class Progress : public eval::CampaignListener {
 public:
  explicit Progress(eval::CampaignListener& next) : next_(&next) {}
  void round_progress(const eval::RoundProgress& p) override { next_->round_progress(p); }
  void round_evaluated(const eval::RoundStats& round) override { next_->round_evaluated(round); }
  void candidates_evaluated(const control::ControllerSpec& c, int run, int generation,
                            std::span<const evo::Outcome> outcomes) override {
    next_->candidates_evaluated(c, run, generation, outcomes);
  }
  void generation_done(const control::ControllerSpec& c, int run, const eval::GenerationStats& g) override {
    next_->generation_done(c, run, g);
  }
  void checkpoint(const control::ControllerSpec& c, const eval::RunState& state) override { next_->checkpoint(c, state); }
  void best_traced(const control::ControllerSpec& c, const eval::RunResult& run,
                   std::span<const eval::TraceStep> trace) override {
    next_->best_traced(c, run, trace);
  }
  void run_done(const control::ControllerSpec& c, const eval::RunResult& run) override { next_->run_done(c, run); }
  // The campaign has ended (or failed): nothing more comes.
  virtual void close() {}

 private:
  eval::CampaignListener* next_;
};

class Events {
 public:
  virtual ~Events() = default;
  // A script compiled with warnings (its diagnostics; a failing script is an Error).
  virtual void warnings(const compiler::CompileResult& /*compiled*/) {}
  virtual void note(const Note& /*note*/) {}
  // A campaign begins: what sees its events, forwarding each to `next`; null: nothing.
  // `condition`: the study condition it runs (empty for an experiment); `already_done`:
  // generations finished before this process (a resumed run).
  virtual std::unique_ptr<Progress> progress(const eval::ExperimentSpec& /*spec*/, const std::string& /*condition*/,
                                             eval::CampaignListener& /*next*/, std::int64_t /*already_done*/) {
    return nullptr;
  }
  // An experiment's campaign has ended: one a run was asked for, or one it depends on (a
  // study's conditions end with the study).
  virtual void experiment_done(const eval::ExperimentSpec& /*spec*/, const eval::CampaignResult& /*result*/) {}
};

}  // namespace esc::app
