#include "app/error.hpp"

namespace esc::app {

namespace {

// The problems, or a failing script's diagnostics (without color) when there are none.
std::string joined(const std::vector<Problem>& problems, const compiler::CompileResult* script) {
  if (problems.empty() && script != nullptr) return compiler::render_all(script->diagnostics, script->sources, false);
  std::string text;
  for (const Problem& p : problems) {
    if (!text.empty()) text += '\n';
    text += p.message;
    if (!p.help.empty()) text += "\nhelp: " + p.help;
  }
  return text;
}

}  // namespace

Error::Error(ErrorKind kind, std::vector<Problem> problems, std::vector<std::string> details,
             std::shared_ptr<const compiler::CompileResult> script)
    : std::runtime_error(joined(problems, script.get())),
      kind_(kind),
      problems_(std::move(problems)),
      details_(std::move(details)),
      script_(std::move(script)) {}

Error::Error(ErrorKind kind, std::string message, std::string help)
    : Error(kind, std::vector<Problem>{{std::move(message), std::move(help)}}) {}

Error follower_error(ErrorKind kind) { return Error(kind, std::vector<Problem>{}); }

void Problems::throw_if_any(ErrorKind kind) {
  if (!list_.empty()) throw Error(kind, std::move(list_));
}

}  // namespace esc::app
