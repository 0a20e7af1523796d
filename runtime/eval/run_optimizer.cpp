#include "runtime/eval/run_optimizer.hpp"

#include <stdexcept>
#include <string>

#include "runtime/evo/evaluate_only.hpp"

namespace esc::eval {

namespace {

std::string kind_of(const control::ControllerSpec& c) {
  return c.is_tree() ? "tree" : c.is_graph() ? "NEAT network" : "network";
}

}  // namespace

RunOptimizer make_run_optimizer(const ExperimentSpec& spec, const control::ControllerSpec& controller,
                                const evo::Problem& problem) {
  if (spec.evaluates_only()) return {evo::make_evaluate_only(problem), {std::string(evo::kEvaluateOnly), 1, {}}};
  const Evolution evolution = spec.evolution_of(controller);
  if (evolution.algorithm == nullptr)
    throw std::invalid_argument(kind_of(controller) + " controller '" + controller.name + "': no algorithm `" +
                                controller.evolved_by + "`");
  if (!evolution.settings.has_value())
    throw std::invalid_argument(kind_of(controller) + " controller '" + controller.name + "' is compared, but "
                                "experiment '" + spec.name + "' has no " +
                                (controller.is_tree() ? std::string("GP") : std::string(evolution.algorithm->name)) +
                                " settings");
  const evo::Algorithm& a = *evolution.algorithm;
  // The compiler refuses this at the controller's name; a spec built otherwise is refused here.
  if (!a.kinds.has(problem.kind()))
    throw std::invalid_argument(kind_of(controller) + " controller '" + controller.name + "': " + std::string(a.name) +
                                " does not evolve " + std::string(genome::name_of(problem.kind())) + " genomes");
  return {a.make(evolution.settings, problem), {std::string(a.name), a.state_format, {}}};
}

void load_run_state(RunOptimizer& made, const control::ControllerSpec& controller, const OptimizerState& stored) {
  if (stored.algorithm != made.empty_state.algorithm || stored.format != made.empty_state.format)
    throw std::invalid_argument(kind_of(controller) + " controller '" + controller.name +
                                "': the state to resume from was saved by " + stored.algorithm + " (format " +
                                std::to_string(stored.format) + "), not by " + made.empty_state.algorithm +
                                " (format " + std::to_string(made.empty_state.format) + ")");
  try {
    made.optimizer->load(stored.bytes);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(kind_of(controller) + " controller '" + controller.name +
                                "': the state to resume from is not one its optimizer could have saved: " + e.what());
  }
}

}  // namespace esc::eval
