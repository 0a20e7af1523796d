#include "runtime/report/study_table.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace esc::report {

const StudyCell* StudyTable::cell(std::size_t condition, std::size_t controller) const {
  for (const StudyCell& c : cells)
    if (c.condition == condition && c.controller == controller) return &c;
  return nullptr;
}

std::string StudyTable::label(const Comparison& c) const {
  const StudyCell& a = cells.at(c.a);
  const StudyCell& b = cells.at(c.b);
  if (a.condition == b.condition)
    return fmt::format("{}: {} vs {}", conditions[a.condition], controllers[a.controller], controllers[b.controller]);
  return fmt::format("{}: {} vs {}", controllers[a.controller], conditions[a.condition], conditions[b.condition]);
}

StudyTable study_table(const std::vector<ConditionSamples>& conditions) {
  StudyTable t;
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    t.conditions.push_back(conditions[i].name);
    for (const auto& [name, best] : conditions[i].controllers) {
      auto at = std::find(t.controllers.begin(), t.controllers.end(), name);
      if (at == t.controllers.end()) at = t.controllers.insert(at, name);
      t.cells.push_back({i, static_cast<std::size_t>(at - t.controllers.begin()), best});
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  const std::size_t n = t.cells.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (t.cells[a].condition == t.cells[b].condition) pairs.emplace_back(a, b);
  for (std::size_t k = 0; k < t.controllers.size(); ++k)
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        if (t.cells[a].controller == k && t.cells[b].controller == k) pairs.emplace_back(a, b);
  std::vector<std::vector<double>> samples;
  for (const StudyCell& c : t.cells) samples.push_back(c.best);
  t.comparisons = compare(samples, pairs);
  return t;
}

}  // namespace esc::report
