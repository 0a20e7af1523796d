#pragma once
// The lookups every settings table needs: the row called `name`, and the rows' names (for
// "did you mean" and the lists in messages).
#include <string>
#include <string_view>
#include <vector>

namespace esc::compiler {

template <class Row>
const Row* find_row(const std::vector<Row>& table, std::string_view Row::*key, std::string_view name) {
  for (const Row& r : table)
    if (r.*key == name) return &r;
  return nullptr;
}

template <class Row>
std::vector<std::string> row_names(const std::vector<Row>& table, std::string_view Row::*key) {
  std::vector<std::string> names;
  for (const Row& r : table) names.emplace_back(r.*key);
  return names;
}

}  // namespace esc::compiler
