#pragma once
// The `esc` subcommands. Each returns the process exit status:
// 0 success, 1 bad input (script, settings, files, parameters), 2 bad command line.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/replay.hpp"

namespace esc::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitUsage = 2;

int check_command(const std::vector<std::filesystem::path>& files);

struct RunOptions {
  std::filesystem::path file;                // with --resume: optional, else the stored script path
  std::filesystem::path resume;              // non-empty: continue this run directory
  std::string experiment;                    // an experiment or a study; empty: the first declared
  std::optional<int> runs;
  std::optional<int> generations;
  std::optional<std::uint64_t> seed;
  int threads = 0;                           // 0: all cores
  int runs_at_once = 0;                      // 0: as many as keep every worker busy
  std::filesystem::path out;                 // empty: runs/<experiment or study>-<timestamp>
  std::vector<std::string> settings;         // KEY=VALUE
  std::vector<std::string> controllers;      // empty: every compared controller
  std::filesystem::path cache;               // empty: <out>/deps (dependency experiments' runs)
  bool verbose = false;                      // a refused resume's details, beside its one line
};

int run_command(const RunOptions& options);

struct ExportOptions {
  std::vector<std::filesystem::path> dirs;   // run directories, experiments or studies
  std::string format = "csv";                // "csv" or "json"
  std::string table;                         // "" (csv: generations, json: everything) or "usage"
  std::filesystem::path out;                 // empty: standard output
};

int export_command(const ExportOptions& options);

struct ReportOptions {
  std::vector<std::filesystem::path> dirs;   // run directories, experiments or studies: one report
  std::filesystem::path out;                 // empty: DIR/report.html (one directory only)
};

int report_command(const ReportOptions& options);

// The command line fills the application layer's request itself: the options are its fields.
using ReplayOptions = app::ReplayRequest;

int replay_command(const ReplayOptions& options);

struct BenchOptions {
  int max_threads = 0;                       // 0: all cores
  double min_time_s = 0.5;
  std::vector<std::string> benchmark_args;   // passed to Google Benchmark
  std::filesystem::path campaign;            // estimate this script's campaign instead
  std::string profile;                       // run this one loop only (for a profiler)
  int evaluations = 200;                     // items of --profile's loop
};

int bench_command(const BenchOptions& options);

}  // namespace esc::cli
