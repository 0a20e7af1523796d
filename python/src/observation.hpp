#pragma once
// The frame's slots as the Python module shows them: a network's inputs by their script
// names, and an Env's observation with the range each observable is documented to take
// (runtime/expr/observables.hpp, docs/language.md).
#include <string>
#include <vector>

#include "runtime/eval/experiment.hpp"
#include "runtime/expr/observables.hpp"

namespace esc::python {

// "ir[3]", "energy", "in[0]" (`in(zone)` of the arena's first zone), "reached[1]",
// "acting", "param[0]"; the IR sensors by the name `robot` reads them by ("prox[3]").
[[nodiscard]] std::string slot_name(expr::Slot slot, const sim::RobotParams& robot);

// What `robot` senses, the observation without a controller: the IR and light sensors,
// rangefinders, goal radars, ground sensors and bumpers it declares, and the accumulator.
[[nodiscard]] std::vector<expr::Slot> senses(const sim::RobotParams& robot);

struct SlotRange {
  double low = 0.0;
  double high = 0.0;
};

// The values `slot` takes in `spec`: [0, 1] for a sensor, a fraction or a boolean, [-1, 1]
// for a signed speed, the clock's range from the epoch's steps, unbounded for counts and
// parameters.
[[nodiscard]] SlotRange slot_range(expr::Slot slot, const eval::ExperimentSpec& spec);

}  // namespace esc::python
