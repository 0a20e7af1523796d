#pragma once
// What the application layer throws when it refuses: one or more problems, each a sentence
// (the text `esc` prints after "esc: error: ") with an optional hint, and for a script that
// does not compile, its diagnostics. Every refusal leaves results and caches as they were.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/compiler.hpp"

namespace esc::app {

enum class ErrorKind {
  Script,       // the script does not compile, or lacks what was asked for
  Setting,      // a setting (given now or stored) refused
  Results,      // a run or study directory: missing, damaged, locked, not resumable
  Dependency,   // an experiment this one needs could not be prepared
  Memory,       // the campaign does not fit in this machine's memory
  Request,      // what was asked for does not fit what is there (`esc` exits with its usage status)
};

struct Problem {
  std::string message;
  std::string help;   // a hint, or empty
};

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, std::vector<Problem> problems, std::vector<std::string> details = {},
        std::shared_ptr<const compiler::CompileResult> script = nullptr);
  Error(ErrorKind kind, std::string message, std::string help = {});

  [[nodiscard]] ErrorKind kind() const noexcept { return kind_; }
  [[nodiscard]] const std::vector<Problem>& problems() const noexcept { return problems_; }
  // Lines that explain the problems further (which files changed, ...).
  [[nodiscard]] const std::vector<std::string>& details() const noexcept { return details_; }
  // The compiled script whose diagnostics belong to the error; null when none do.
  [[nodiscard]] const compiler::CompileResult* script() const noexcept { return script_.get(); }

 private:
  ErrorKind kind_;
  std::vector<Problem> problems_;
  std::vector<std::string> details_;
  std::shared_ptr<const compiler::CompileResult> script_;
};

// Thrown on the ranks of an MPI job other than rank 0 where rank 0 refused: they stop as it
// does, and have nothing to say.
[[nodiscard]] Error follower_error(ErrorKind kind);

// Problems gathered one by one (every refused setting is reported, not the first alone),
// thrown together.
class Problems {
 public:
  void add(std::string message, std::string help = {}) { list_.push_back({std::move(message), std::move(help)}); }
  [[nodiscard]] bool empty() const noexcept { return list_.empty(); }
  // Throws them as one Error of `kind` if there are any.
  void throw_if_any(ErrorKind kind);

 private:
  std::vector<Problem> list_;
};

}  // namespace esc::app
