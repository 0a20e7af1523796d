#pragma once
// The options of each `esc` subcommand, declared into the command line's parser (main.cpp
// parses and dispatches). Each returns its subcommand, which holds its options once parsed.
#include <filesystem>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"

namespace esc::cli {

CLI::App* add_check(CLI::App& app, std::vector<std::filesystem::path>& files);
CLI::App* add_run(CLI::App& app, RunOptions& o);
CLI::App* add_export(CLI::App& app, ExportOptions& o);
CLI::App* add_report(CLI::App& app, ReportOptions& o);
CLI::App* add_replay(CLI::App& app, ReplayOptions& o);
CLI::App* add_bench(CLI::App& app, BenchOptions& o);

}  // namespace esc::cli
