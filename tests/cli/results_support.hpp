#pragma once
// What the end-to-end tests of stored results share: an `esc run` started in the
// background (to be killed), the rows of a CSV export, the generations a run directory has
// committed so far, and the comparison of two runs' summaries and results.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"

namespace cli_test {

// Starts `esc ARGS...` with its standard output discarded; returns its process id.
inline pid_t spawn_esc(const std::vector<std::string>& args) {
  const pid_t child = fork();
  if (child != 0) return child;
  if (std::freopen("/dev/null", "w", stdout) == nullptr) std::_Exit(127);
  std::vector<char*> argv{const_cast<char*>(ESC_BINARY)};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  execv(ESC_BINARY, argv.data());
  std::_Exit(127);
}

// The rows of a CSV export, each split at its commas, the header first.
inline std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string>& f = rows.emplace_back();
    std::stringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) f.push_back(c);
    if (!line.empty() && line.back() == ',') f.emplace_back();
  }
  return rows;
}

// Generations committed so far, read through `esc export` while the run writes.
inline int committed_generations(const fs::path& dir) {
  const Outcome o = esc("export " + dir.string() + " --format csv");
  if (o.status != 0) return 0;
  int lines = 0;
  for (char ch : o.output) lines += ch == '\n' ? 1 : 0;
  return lines - 1;
}

// Kills `child` (without warning: SIGKILL) once `dir` has `at_least` generations committed
// (or after a minute); returns whether it was still running then and the count seen.
struct Killed {
  bool still_running = false;
  int seen = 0;
};
inline Killed kill_when_committed(pid_t child, const fs::path& dir, int at_least) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  Killed k;
  while ((k.seen = committed_generations(dir)) < at_least && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  int status = 0;
  k.still_running = waitpid(child, &status, WNOHANG) == 0;
  kill(child, SIGKILL);
  waitpid(child, &status, 0);
  return k;
}

// `esc ARGS... --out DIR`, killed once `at_least` generations are committed and before all
// `total` are; wrap in ASSERT_NO_FATAL_FAILURE.
inline void run_killed(std::vector<std::string> args, const fs::path& dir, int at_least, int total) {
  args.insert(args.end(), {"--out", dir.string()});
  const pid_t child = spawn_esc(args);
  ASSERT_GE(child, 0);
  const Killed k = kill_when_committed(child, dir, at_least);
  ASSERT_TRUE(k.still_running) << "the run finished before it could be killed";
  ASSERT_GE(k.seen, at_least);
  ASSERT_LT(committed_generations(dir), total) << "nothing left to resume";
}

// `esc run SCRIPT --generations 100 --seed 5 --threads 1 EXTRA... --out DIR`, killed as
// run_killed says.
inline void run_killed_halfway(const std::string& script, const fs::path& dir, int at_least, int total,
                               const std::string& threads = "1", const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args{"run", script, "--generations", "100", "--seed", "5", "--threads", threads};
  args.insert(args.end(), extra.begin(), extra.end());
  run_killed(args, dir, at_least, total);
}

// Same experiment, same seed: summary.json equal in everything but nothing else.
inline void expect_same_summary(const fs::path& a, const fs::path& b) {
  const auto sa = read_json(a / "summary.json");
  const auto sb = read_json(b / "summary.json");
  ASSERT_EQ(sa["controllers"].size(), sb["controllers"].size());
  for (const auto& [name, c] : sa["controllers"].items()) {
    const auto& runs_a = c["runs"];
    const auto& runs_b = sb["controllers"][name]["runs"];
    ASSERT_EQ(runs_a.size(), runs_b.size()) << name;
    for (std::size_t r = 0; r < runs_a.size(); ++r) {
      EXPECT_EQ(runs_a[r]["seed"], runs_b[r]["seed"]);
      EXPECT_EQ(runs_a[r]["best_fitness"], runs_b[r]["best_fitness"]) << name << " run " << r;
      EXPECT_EQ(runs_a[r]["best"], runs_b[r]["best"]) << name << " run " << r;
      EXPECT_EQ(runs_a[r]["mean"], runs_b[r]["mean"]) << name << " run " << r;
    }
  }
  EXPECT_EQ(slurp(a / "summary.json"), slurp(b / "summary.json"));
}

// The per-generation results of a directory: the export's CSV without the wall times
// (`seconds`) and the directory's path; no field here holds a comma.
inline std::string results_without_times(const fs::path& dir) {
  const Outcome o = esc("export " + dir.string() + " --format csv");
  EXPECT_EQ(o.status, 0) << o.output;
  std::stringstream in(o.output);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    EXPECT_EQ(cells.size(), 16u) << line;
    if (cells.size() != 16) continue;
    cells.erase(cells.begin() + 14);   // directory
    cells.erase(cells.begin() + 11);   // seconds
    for (const std::string& c : cells) out += c + ",";
    out += "\n";
  }
  return out;
}

// Everything a run directory holds as results: per-generation statistics, usage table,
// summary.json and every best genome, equal between the two.
inline void expect_same_results(const fs::path& a, const fs::path& b, const std::vector<std::string>& controllers, int runs) {
  EXPECT_EQ(results_without_times(a), results_without_times(b));
  EXPECT_EQ(esc("export " + a.string() + " --table usage").output, esc("export " + b.string() + " --table usage").output);
  expect_same_summary(a, b);
  for (const std::string& c : controllers)
    for (int r = 1; r <= runs; ++r) {
      const std::string file = c + "/run-0" + std::to_string(r) + ".best.json";
      EXPECT_EQ(slurp(a / file), slurp(b / file)) << file;
    }
}

}  // namespace cli_test
