#include "app/stored_sources.hpp"

#include <stdlib.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "app/compile.hpp"
#include "runtime/store/run_directory.hpp"

namespace esc::app {

namespace fs = std::filesystem;

namespace {

// How many `..` a relative name starts with: its copy goes that deep below the root, so
// that it stays inside it.
std::size_t leading_parents(const fs::path& name) {
  std::size_t n = 0;
  for (const fs::path& part : name) {
    if (part != "..") break;
    ++n;
  }
  return n;
}

// Whether `name` (as the compiler reported it when the run started) names `script`, the
// absolute path the run recorded.
bool names_script(const fs::path& name, const fs::path& script) {
  if (name.is_absolute()) return name.lexically_normal() == script.lexically_normal();
  const fs::path normal = name.lexically_normal();
  auto s = script.end();
  for (auto n = normal.end(); n != normal.begin();) {
    --n;
    if (s == script.begin() || *--s != *n) return *n == "..";
  }
  return true;
}

}  // namespace

StoredSources::StoredSources(const store::StoredExperiment& stored) {
  std::string pattern = (fs::temp_directory_path() / "esc-sources-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error(fmt::format("cannot create a temporary directory in {}", fs::temp_directory_path().string()));
  root_ = pattern;
  std::size_t depth = 0;
  for (const store::SourceFile& s : stored.sources) depth = std::max(depth, leading_parents(s.name));
  fs::path base = root_;
  for (std::size_t i = 0; i < depth; ++i) base /= "up";
  for (const store::SourceFile& s : stored.sources) {
    const fs::path copy = (s.name.is_absolute() ? root_ / s.name.relative_path() : base / s.name).lexically_normal();
    fs::create_directories(copy.parent_path());
    store::write_atomically(copy, s.text);
    if (main_.empty() && names_script(s.name, stored.script)) main_ = copy;
    for (fs::path dir = copy.parent_path(); dir != root_ && dir.has_relative_path(); dir = dir.parent_path())
      if (std::find(import_paths_.begin(), import_paths_.end(), dir) == import_paths_.end()) import_paths_.push_back(dir);
  }
  std::stable_sort(import_paths_.begin(), import_paths_.end(), [](const fs::path& a, const fs::path& b) {
    return std::distance(a.begin(), a.end()) > std::distance(b.begin(), b.end());
  });
  if (main_.empty()) throw store::StoreError(fmt::format("the run's sources do not hold its script {}", stored.script.string()));
}

StoredSources::~StoredSources() {
  std::error_code ec;
  fs::remove_all(root_, ec);
}

compiler::CompileResult StoredSources::compile(compiler::CompileOptions options, Events& events) const {
  options.import_paths.insert(options.import_paths.begin(), import_paths_.begin(), import_paths_.end());
  return app::compile(main_, options, events);
}

}  // namespace esc::app
