#pragma once
// What this esc binary is (`esc --version`): its version, the commit it was built from, the
// optional parts built in, and where it finds its standard library.
#include <string>

namespace esc::cli {

// `git describe` of the sources at build time, or the commit a `git archive` tarball records;
// empty when the sources record none (a generated file, cmake/BuildInfo.cmake).
extern const char* const kCommit;

[[nodiscard]] std::string version_text();

}  // namespace esc::cli
