#pragma once
// The ES's options as scripts write them (`evolve es(mu 30, lambda 150, comma)`, `--set
// mu=30`, `--set selection=plus`; docs/language.md): the paper's keys, bare, and a choice's
// words written alone in `es(...)`; and the check of the options that relate.
#include <vector>

#include "runtime/evo/algorithm_options.hpp"
#include "runtime/evo/es/es.hpp"

namespace esc::evo {

[[nodiscard]] const std::vector<AlgorithmOption>& es_options();

// Options that do not go together (comma selection needs lambda >= mu, a step floor wider
// than the bounds), with what to do; empty when they do.
[[nodiscard]] OptionRefusal es_conflict(const EsSettings& s);

}  // namespace esc::evo
