#pragma once
// Running the `esc` binary from end-to-end tests: its exit status and output, scratch
// directories, and reading what it wrote.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

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

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(slurp(p)); }

// Generations committed so far, read through `esc export` while the run writes.
inline int committed_generations(const fs::path& dir) {
  const Outcome o = esc("export " + dir.string() + " --format csv");
  if (o.status != 0) return 0;
  int lines = 0;
  for (char ch : o.output) lines += ch == '\n' ? 1 : 0;
  return lines - 1;
}

// Starts `esc ARGS... --out OUT` and kills it with SIGKILL once at least `generations`
// generations are committed in OUT (or after a minute). Returns how many were committed
// when it was killed, or -1 if it had already finished.
inline int run_and_kill(std::vector<std::string> args, const fs::path& out, int generations) {
  args.insert(args.begin(), ESC_BINARY);
  args.push_back("--out");
  args.push_back(out.string());
  const pid_t child = fork();
  if (child < 0) return -1;
  if (child == 0) {
    if (std::freopen("/dev/null", "w", stdout) == nullptr) std::_Exit(127);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(ESC_BINARY, argv.data());
    std::_Exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int seen = 0;
  while ((seen = committed_generations(out)) < generations && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  int status = 0;
  const bool still_running = waitpid(child, &status, WNOHANG) == 0;
  kill(child, SIGKILL);
  waitpid(child, &status, 0);
  return still_running ? seen : -1;
}

}  // namespace cli_test
