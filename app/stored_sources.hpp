#pragma once
// The script of a stored run, compiled back from the sources its database holds (the very
// text it ran, whatever has happened to the files since). The files are written under a
// temporary directory at their own paths, so imports resolve among them as they did: beside
// the importing file, or (for a file the run found in $ESC_PATH or the standard library)
// from a directory of the copies.
#include <filesystem>
#include <vector>

#include "app/events.hpp"
#include "compiler/compiler.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::app {

class StoredSources {
 public:
  // Throws std::runtime_error when the temporary directory cannot be written.
  explicit StoredSources(const store::StoredExperiment& stored);
  ~StoredSources();   // removes the copies
  StoredSources(const StoredSources&) = delete;
  StoredSources& operator=(const StoredSources&) = delete;

  // Compiles the run's script from the copies, their directories searched before those of
  // `options`; throws Error (kind Script) when it does not compile.
  [[nodiscard]] compiler::CompileResult compile(compiler::CompileOptions options, Events& events) const;

 private:
  std::filesystem::path root_;
  std::filesystem::path main_;
  std::vector<std::filesystem::path> import_paths_;   // directories of the copies, deepest first
};

}  // namespace esc::app
