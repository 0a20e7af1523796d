#include "runtime/report/study_table.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace esc::report {

const StudyCell* StudyTable::cell(std::size_t condition, std::size_t controller) const {
  for (const StudyCell& c : cells)
    if (c.condition == condition && c.controller == controller) return &c;
  return nullptr;
}

std::string StudyTable::label(std::size_t cell_a, std::size_t cell_b) const {
  const StudyCell& a = cells.at(cell_a);
  const StudyCell& b = cells.at(cell_b);
  if (a.condition == b.condition)
    return fmt::format("{}: {} vs {}", conditions[a.condition], controllers[a.controller], controllers[b.controller]);
  return fmt::format("{}: {} vs {}", controllers[a.controller], conditions[a.condition], conditions[b.condition]);
}

StudyTable study_table(const std::vector<ConditionSamples>& conditions) {
  StudyTable t;
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    t.conditions.push_back(conditions[i].name);
    const ConditionSamples& c = conditions[i];
    for (std::size_t k = 0; k < c.controllers.size(); ++k) {
      const auto& [name, best] = c.controllers[k];
      auto at = std::find(t.controllers.begin(), t.controllers.end(), name);
      if (at == t.controllers.end()) at = t.controllers.insert(at, name);
      t.cells.push_back({i, static_cast<std::size_t>(at - t.controllers.begin()), best,
                         k < c.success.size() ? std::optional(c.success[k]) : std::nullopt});
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
  // Success: the pairs whose cells both declare it, as one family per test.
  std::vector<SuccessSample> success(n);
  std::vector<std::pair<std::size_t, std::size_t>> succeeding;
  for (std::size_t k = 0; k < n; ++k)
    if (t.cells[k].success) success[k] = *t.cells[k].success;
  for (const auto& [a, b] : pairs)
    if (t.cells[a].success && t.cells[b].success) succeeding.emplace_back(a, b);
  t.success_comparisons = compare_success(success, succeeding);
  return t;
}

}  // namespace esc::report
