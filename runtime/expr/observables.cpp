#include "runtime/expr/observables.hpp"

#include <fmt/format.h>

namespace esc::expr {

std::optional<std::string> observable_name(Slot s) {
  for (const Observable& o : kObservables)
    if (s >= o.first && s < o.first + o.count)
      return o.indexed ? fmt::format("{}[{}]", o.name, s - o.first) : std::string(o.name);
  return std::nullopt;
}

}  // namespace esc::expr
