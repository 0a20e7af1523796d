#pragma once
// The paper's algorithms' settings an experiment holds (ExperimentSpec::algorithm_settings:
// the ES's in every compiled experiment, GP's where it gives `evolve gp`), for tests that
// read or change them. In eval's namespace, so that a call on an experiment finds them
// from any test's namespace.
#include <any>

#include "runtime/eval/experiment.hpp"
#include "runtime/evo/es/es.hpp"
#include "runtime/evo/gp/gp.hpp"

namespace esc::eval {

inline evo::EsSettings& es_of(ExperimentSpec& x) {
  return std::any_cast<evo::EsSettings&>(x.algorithm_settings.at(ExperimentSpec::kDefaultNetworks));
}
inline const evo::EsSettings& es_of(const ExperimentSpec& x) {
  return std::any_cast<const evo::EsSettings&>(x.algorithm_settings.at(ExperimentSpec::kDefaultNetworks));
}
inline evo::gp::GpSettings& gp_of(ExperimentSpec& x) {
  return std::any_cast<evo::gp::GpSettings&>(x.algorithm_settings.at(ExperimentSpec::kTreeOperators));
}
inline const evo::gp::GpSettings& gp_of(const ExperimentSpec& x) {
  return std::any_cast<const evo::gp::GpSettings&>(x.algorithm_settings.at(ExperimentSpec::kTreeOperators));
}

}  // namespace esc::eval
