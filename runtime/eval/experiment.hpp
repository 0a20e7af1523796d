#pragma once
// A checked, fully resolved experiment: everything a run needs, produced by the compiler
// from a script. Runtime code sees only this, never the parse tree.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "runtime/control/controller_spec.hpp"
#include "runtime/evo/es.hpp"
#include "runtime/expr/program.hpp"
#include "runtime/sim/arena.hpp"
#include "runtime/sim/khepera_params.hpp"

namespace esc::eval {

// Fitness of one evaluation: the sum over epochs and steps of `step`, evaluated after the
// physics of each control step. An epoch ends early after the first step at which any
// `stop_when` program is non-zero (that step's term still counts).
struct FitnessSpec {
  std::string name;
  expr::Program step;
  std::vector<expr::Program> stop_when;
};

// A supervised behavior that is another experiment's evolved controller
// (`behavior avoid = evolved from experiment E controller C`): the experiment E must run
// first; the best genome of C over all its runs fills each target's FixedController.
struct Dependency {
  std::string experiment;           // E
  std::string controller;           // C, one of E's compared controllers
  // Where to put it: (index in `controllers`, index in that controller's `behaviors`).
  std::vector<std::pair<std::size_t, std::size_t>> targets;
};

struct ExperimentSpec {
  std::string name;
  std::string arena_name;
  sim::ArenaSpec arena;
  sim::KheperaParams robot;
  FitnessSpec fitness;
  int epochs = 10;
  int steps = 150;                  // control steps per epoch (at most)
  int runs = 10;
  std::uint64_t seed = 1;
  evo::EsSettings es;
  std::vector<control::ControllerSpec> controllers;   // the `compare` list, in order
  // Every setting as resolved, for the run directory ("epochs" -> "10", ...).
  std::map<std::string, std::string> resolved_settings;
  // Evolved behaviors to fill in before running, one per (experiment, controller) used.
  std::vector<Dependency> dependencies;
};

}  // namespace esc::eval
