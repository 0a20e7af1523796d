#include "runtime/report/pair_rows.hpp"

#include <cmath>

#include <fmt/format.h>

#include "runtime/store/export.hpp"

namespace esc::report {

std::string number_text(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return fmt::format("{:.17g}", x);
}

nlohmann::ordered_json number_json(double x) {
  if (std::isnan(x)) return nullptr;
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

std::string pair_names_csv(const PairNames& n) {
  return fmt::format("{},{},{},{},{},{},", store::csv_field(n.study), store::csv_field(n.experiment),
                     store::csv_field(n.condition_a), store::csv_field(n.controller_a), store::csv_field(n.condition_b),
                     store::csv_field(n.controller_b));
}

nlohmann::ordered_json pair_names_json(const PairNames& n) {
  return {{"study", n.study},         {"experiment", n.experiment},     {"condition_a", n.condition_a},
          {"controller_a", n.controller_a}, {"condition_b", n.condition_b}, {"controller_b", n.controller_b}};
}

}  // namespace esc::report
