#pragma once
// Running the `esc` binary from end-to-end tests: its exit status and output, scratch
// directories, and reading what it wrote.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace cli_test {

namespace fs = std::filesystem;

struct Outcome {
  int status = -1;
  std::string output;   // stdout and stderr together
};

inline Outcome shell(const std::string& cmd) {
  Outcome o;
  FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return o;
  std::array<char, 4096> buf{};
  for (std::size_t n; (n = fread(buf.data(), 1, buf.size(), pipe)) > 0;) o.output.append(buf.data(), n);
  const int raw = pclose(pipe);
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  return o;
}

inline Outcome esc(const std::string& args) { return shell(std::string(ESC_BINARY) + " " + args); }

// A fresh, empty path under the temporary directory, per test process and name.
inline fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("esc-cli-test-" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d.parent_path());
  return d;
}

inline std::string tiny() { return std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tiny.esc"; }
// A network and two tree controllers, evolved by the ES and by GP (tests/cli/data/tiny_gp.esc).
inline std::string tiny_gp() { return std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tiny_gp.esc"; }

// The DOM of DIR/report.html once headless Chromium (ESC_CHROMIUM, empty where not
// configured) has run its script for 3 s of virtual time, its profile in DIR/profile.
inline Outcome report_dom(const fs::path& dir) {
  return shell("timeout 60 " + std::string(ESC_CHROMIUM) +
               " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --user-data-dir=" +
               (dir / "profile").string() + " --virtual-time-budget=3000 --dump-dom file://" +
               (dir / "report.html").string() + " 2>/dev/null");
}

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(slurp(p)); }

}  // namespace cli_test
