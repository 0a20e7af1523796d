#pragma once
// An experiment's success test: `success when NAME CMP THRESHOLD` -> eval::SuccessSpec.
// NAME is the fitness, a further objective or a descriptor of the experiment; THRESHOLD is
// read in the unit of NAME's declared range (`reach_goal ... in [-1.2m, 0]`: a length), so a
// threshold of another dimension is an error at its unit. Lowered after the objectives and
// descriptors, whose names and ranges it reads.
#include "compiler/ast.hpp"
#include "compiler/lower_objectives.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

// Fills x.success from `item`; reports every mistake. False when one was found.
bool lower_success(const ast::ExpItem& item, const ObjectiveItems& objectives, Sink& sink, eval::ExperimentSpec& x);

// The resolved setting `success` ("reach_goal > -0.0171875"), added only when declared so that
// other experiments resolve as before.
void resolve_success(eval::ExperimentSpec& x);

}  // namespace esc::compiler
