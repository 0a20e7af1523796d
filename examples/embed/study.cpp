// Using esc's application layer: run a small study into a directory, as `esc run` would,
// with progress reported through events, then read what it stored.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "app/error.hpp"
#include "app/import_path.hpp"
#include "app/run.hpp"

namespace {

constexpr const char* kScript = R"(
import "lib/khepera.esc"
arena box { size 50cm x 50cm  cylinder at (25cm, 25cm) radius 3cm  start random }
fitness avoid { step: max(forward_speed, 0) * (1 - sqrt(wheel_diff))  stop epoch when collision }
controller SC = symbolic(mlp(ir[0..7] -> hidden 4), actions [forward, left, right])
controller CC = mlp(ir[0..7] -> hidden 4 -> wheels)
experiment demo { arena box  robot khepera  epochs 2 x 100 steps  fitness avoid
                  evolve es(mu 5, lambda 20) for 3 generations  runs 2  compare SC, CC }
study inertia {
  condition with_inertia = demo { robot.inertia on }
  condition without = demo { robot.inertia off }
}
)";

// Prints one line per finished generation: what a progress bar or a notebook would show.
class Generations final : public esc::app::Progress {
 public:
  using Progress::Progress;
  void generation_done(const esc::control::ControllerSpec& c, int run, const esc::eval::GenerationStats& g) override {
    Progress::generation_done(c, run, g);   // the run directory stores it
    std::cout << "  " << c.name << " run " << run + 1 << " generation " << g.generation << ": best " << g.best << "\n";
  }
};

class Printed final : public esc::app::Events {
 public:
  void note(const esc::app::Note& n) override { std::cout << n.text << "\n"; }
  std::unique_ptr<esc::app::Progress> progress(const esc::eval::ExperimentSpec&, const std::string&,
                                               esc::eval::CampaignListener& next, std::int64_t) override {
    return std::make_unique<Generations>(next);
  }
};

}  // namespace

int main() {
  const std::filesystem::path work = std::filesystem::temp_directory_path() / "esc-embed-study";
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  const std::filesystem::path script = work / "study.esc";
  std::ofstream(script) << kScript;

  esc::app::RunRequest request;
  request.script = script;
  request.experiment = "inertia";   // the script declares experiment demo first
  request.out = work / "out";
  request.execution.threads = 2;
  Printed events;
  try {
    const esc::app::Outcome outcome = esc::app::run(request, esc::app::compile_options(ESC_STDLIB_DIR), events);
    for (const esc::app::ConditionOutcome& c : outcome.conditions)
      for (const esc::eval::ControllerResult& r : c.result.controllers)
        std::cout << "condition " << c.name << " " << r.name << ": best fitness " << r.runs.front().best_fitness
                  << " (run 1)\n";
    std::cout << "stored in " << outcome.dir.string() << "\n";
  } catch (const esc::app::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
