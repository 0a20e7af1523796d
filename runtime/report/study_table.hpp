#pragma once
// A study's results as one table: the runs' best fitness of each controller in each
// condition, and the one family of comparisons shown with it (Holm's correction over all of
// them): within each condition every pair of its controllers, then, for each controller,
// every pair of the conditions that compare it (controllers are paired by name). Where both
// cells of a pair declare a success test, its success is compared too, over the same pairs
// (success_comparisons.hpp; a family of its own for each test). The end table of `esc run`
// and the report read the same.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "runtime/report/comparisons.hpp"
#include "runtime/report/success_comparisons.hpp"

namespace esc::report {

// What a condition compares: each controller's name and its runs' best fitness.
struct ConditionSamples {
  std::string name;
  std::vector<std::pair<std::string, std::vector<double>>> controllers;
  // Per controller, in the same order, when the condition declares a success test; else empty.
  std::vector<SuccessSample> success{};
};

struct StudyCell {
  std::size_t condition = 0, controller = 0;
  std::vector<double> best;
  std::optional<SuccessSample> success{};
};

struct StudyTable {
  std::vector<std::string> conditions;
  std::vector<std::string> controllers;    // in the order they first appear
  std::vector<StudyCell> cells;            // condition by condition
  std::vector<Comparison> comparisons;     // a and b index `cells`
  // The pairs of `comparisons` whose cells both have a success sample, in the same order.
  std::vector<SuccessComparison> success_comparisons;

  // The cell of controller `controller` in condition `condition`, or null.
  [[nodiscard]] const StudyCell* cell(std::size_t condition, std::size_t controller) const;
  // "no_inertia: SC vs CC" within a condition, "SC: no_inertia vs inertia" across.
  [[nodiscard]] std::string label(std::size_t a, std::size_t b) const;
  [[nodiscard]] std::string label(const Comparison& c) const { return label(c.a, c.b); }
};

[[nodiscard]] StudyTable study_table(const std::vector<ConditionSamples>& conditions);

// What the family of a study's comparisons holds, for a note under the table.
inline constexpr const char* kStudyFamily =
    "within each condition every pair of controllers, and for each controller every pair of conditions";

}  // namespace esc::report
