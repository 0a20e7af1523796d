#pragma once
// What an experiment's results depend on, as canonical text: every resolved setting, the
// arena's geometry, the fitness and behavior programs, the controllers (with the frozen
// genomes of evolved behaviors and the genomes a run starts from). Two experiments with
// the same fingerprint give the same results, so a stored run can stand in for a new one;
// a comment, a renamed file or an unrelated declaration in the script does not change it.
// Floating-point values are written exactly (hexadecimal).
#include <string>

#include "runtime/eval/experiment.hpp"

namespace esc::eval {

// What the code computes, as opposed to what the script asks: bump it with every change
// that alters results (the simulator, observables, evaluation, the evolution loops), so
// cached runs made by an earlier build are not reused. 2: sphere body, closed-form
// sphere-box contact, free-space substeps (results differ in the last digits).
inline constexpr int kResultsRevision = 2;

// Starts with kResultsRevision.
[[nodiscard]] std::string fingerprint(const ExperimentSpec& spec);

}  // namespace esc::eval
