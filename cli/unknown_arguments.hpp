#pragma once
// Command-line words esc does not know, reported the way the compiler reports a misspelled
// name, with the closest known one:
//   esc: error: unknown command `runn`
//   help: did you mean `run`?
// (CLI11 alone says "A subcommand is required" for `esc runn`, and "The following arguments
// were not expected" without a suggestion.)
namespace CLI {
class App;
}

namespace esc::cli {

// Before parsing: true, after printing an error, when the first argument is neither one of
// `app`'s subcommands nor one of its own options.
[[nodiscard]] bool unknown_command(const CLI::App& app, int argc, const char* const* argv);

// After parsing a subcommand that allows extras: true, after printing one error per word,
// when it was given options it does not have or more arguments than it takes.
[[nodiscard]] bool unexpected_arguments(const CLI::App& command);

}  // namespace esc::cli
