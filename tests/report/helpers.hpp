#pragma once
// Shared by the report's figure tests: how often a piece of markup occurs in a rendered
// figure (non-overlapping).
#include <cstddef>
#include <string>

namespace esc::report::test {

inline std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = 0; (at = text.find(what, at)) != std::string::npos; at += what.size()) ++n;
  return n;
}

}  // namespace esc::report::test
