#pragma once
// The script of a stored run, compiled back from the sources its database holds (the very
// text it ran, whatever has happened to the files since). The files are written under a
// temporary directory at their own paths, so imports resolve among them as they did: beside
// the importing file, or (for a file the run found in $ESC_PATH or the standard library)
// from a directory of the copies.
#include <filesystem>
#include <vector>

#include "compiler/compiler.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::cli {

class ReplaySources {
 public:
  // Throws std::runtime_error when the temporary directory cannot be written.
  explicit ReplaySources(const store::StoredExperiment& stored);
  ~ReplaySources();   // removes the copies
  ReplaySources(const ReplaySources&) = delete;
  ReplaySources& operator=(const ReplaySources&) = delete;

  // Compiles the run's script from the copies (diagnostics printed).
  [[nodiscard]] compiler::CompileResult compile() const;

 private:
  std::filesystem::path root_;
  std::filesystem::path main_;
  std::vector<std::filesystem::path> import_paths_;   // directories of the copies, deepest first
};

}  // namespace esc::cli
