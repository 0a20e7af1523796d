// Using esc as a library: compile a script, evaluate one genome, run a short campaign.
#include <iostream>
#include <vector>

#include "compiler/compiler.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/eval/evaluator.hpp"

constexpr const char* kScript = R"(
import "lib/khepera.esc"          // esc's standard library, from the installed package
arena box { size 50cm x 50cm  cylinder at (25cm, 25cm) radius 3cm  start random }
fitness avoid { step: max(forward_speed, 0) * (1 - sqrt(wheel_diff))  stop epoch when collision }
controller SC = symbolic(mlp(ir[0..7] -> hidden 4), actions [forward, left, right])
experiment demo { arena box  robot khepera  epochs 2 x 100 steps  fitness avoid
                  evolve es(mu 5, lambda 20) for 3 generations  runs 2  compare SC }
)";

int main() {
  esc::compiler::CompileOptions options;
  options.import_paths.push_back(ESC_STDLIB_DIR);
  esc::compiler::CompileResult compiled = esc::compiler::compile_source(kScript, "demo.esc", options);
  if (!compiled.ok()) {
    std::cerr << esc::compiler::render_all(compiled.diagnostics, compiled.sources);
    return 1;
  }
  esc::eval::ExperimentSpec& spec = compiled.experiments.front();
  const esc::control::ControllerSpec& sc = spec.controllers.front();

  // One genome, evaluated on seed 42: the same fitness every time, on any machine.
  const std::vector<double> genome(sc.genome_size(), 0.1);
  esc::eval::Evaluator evaluator(spec);
  const esc::eval::Evaluation e = evaluator.evaluate(sc, genome, 42);
  std::cout << "genome of " << genome.size() << " weights: fitness " << e.fitness << " in " << e.steps << " steps\n";

  // A campaign: 2 runs x 3 generations; a listener could store or print as it goes.
  esc::eval::CampaignListener quiet;
  esc::eval::CampaignOptions run_options;
  run_options.threads = 2;
  const esc::eval::CampaignResult result = esc::eval::run_campaign(spec, run_options, quiet);
  for (const esc::eval::RunResult& r : result.controllers.front().runs)
    std::cout << "run " << r.run + 1 << ": best fitness " << r.best_fitness << "\n";
  return 0;
}
