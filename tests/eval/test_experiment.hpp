#pragma once
// A small obstacle-avoidance experiment built directly from runtime objects (no compiler),
// so the evaluation layer is tested on its own.
#include "runtime/eval/experiment.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::testing {

inline expr::Program forward_only_fitness() {
  // max(forward_speed, 0) * (1 - sqrt(wheel_diff))
  expr::Program p;
  p.push_load(expr::slot::forward_speed);
  p.push_const(0.0);
  p.push_op(expr::Op::Max);
  p.push_const(1.0);
  p.push_load(expr::slot::wheel_diff);
  p.push_op(expr::Op::Sqrt);
  p.push_op(expr::Op::Sub);
  p.push_op(expr::Op::Mul);
  return p;
}

inline expr::Program load(expr::Slot s) {
  expr::Program p;
  p.push_load(s);
  return p;
}

inline eval::ExperimentSpec small_experiment() {
  eval::ExperimentSpec e;
  e.name = "small";
  e.arena.width_m = 0.5;
  e.arena.height_m = 0.4;
  e.arena.cylinders.push_back({{0.25, 0.2}, 0.03});
  e.arena.boxes.push_back({{0.1, 0.3}, {0.06, 0.03}, 0.4});
  e.fitness.name = "avoid";
  e.fitness.step = forward_only_fitness();
  e.fitness.stop_when.push_back(load(expr::slot::collision));
  e.epochs = 3;
  e.steps = 60;
  e.runs = 2;
  e.seed = 7;
  evo::EsSettings es;
  es.mu = 5;
  es.lambda = 20;
  e.algorithm_settings[eval::ExperimentSpec::kDefaultNetworks] = es;
  e.generations = 6;
  control::ControllerSpec c;
  c.name = "CC";
  for (expr::Slot i = 0; i < expr::kIrCount; ++i) c.mlp.inputs.push_back(expr::slot::ir + i);
  c.mlp.hidden = {4};
  c.head = control::Head::Classical;
  e.controllers.push_back(c);
  return e;
}

}  // namespace esc::testing
