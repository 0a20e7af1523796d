#pragma once
// Diagnostics in the style of Clang and rustc:
//   file:line:col: error: one clear sentence
//     12 |   controller c = mlp(ir[0..7] -> hiden 3 -> wheels)
//        |                                  ^~~~~
//   help: did you mean `hidden`?
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace esc::compiler {

enum class Severity { Error, Warning, Note };

struct SourceRange {
  std::filesystem::path file;   // as the user named it (relative stays relative)
  int line = 0;                 // 1-based
  int column = 0;               // 1-based, in characters
  int length = 1;               // characters underlined on that line
};

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceRange where;
  std::string message;              // one sentence, no trailing period
  std::vector<std::string> help;    // "did you mean `hidden`?", ...
  std::vector<std::pair<SourceRange, std::string>> notes;   // "first declared here"
};

// Text of the files a compilation read, keyed by the path used in SourceRange::file.
using SourceMap = std::map<std::filesystem::path, std::string>;

// Renders one diagnostic with its source line and caret (and `color` escapes when asked).
[[nodiscard]] std::string render(const Diagnostic& d, const SourceMap& sources, bool color = false);

// Renders all diagnostics, then a line like "2 errors generated." when there are errors.
[[nodiscard]] std::string render_all(const std::vector<Diagnostic>& ds, const SourceMap& sources,
                                     bool color = false);

}  // namespace esc::compiler
