#pragma once
// Collects the diagnostics of one compilation.
#include <string>
#include <utility>
#include <vector>

#include "compiler/diagnostic.hpp"

namespace esc::compiler {

class Sink {
 public:
  // The returned reference is valid until the next call that adds a diagnostic.
  Diagnostic& error(const SourceRange& where, std::string message) {
    return add(Severity::Error, where, std::move(message));
  }
  Diagnostic& warning(const SourceRange& where, std::string message) {
    return add(Severity::Warning, where, std::move(message));
  }
  Diagnostic& add(Severity s, const SourceRange& where, std::string message) {
    items_.push_back(Diagnostic{s, where, std::move(message), {}, {}});
    if (s == Severity::Error) ++errors_;
    return items_.back();
  }
  [[nodiscard]] int errors() const noexcept { return errors_; }
  [[nodiscard]] std::vector<Diagnostic>& items() noexcept { return items_; }

 private:
  std::vector<Diagnostic> items_;
  int errors_ = 0;
};

}  // namespace esc::compiler
