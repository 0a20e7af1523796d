#include "cli/unknown_arguments.hpp"

#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "compiler/names.hpp"

namespace esc::cli {

namespace {

std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
    for (const std::string& n : o->get_snames()) names.push_back("-" + n);
  }
  return names;
}

void complain_unknown(const std::string& what, const std::string& word, const std::vector<std::string>& known) {
  fmt::print(stderr, "esc: error: {} `{}`\n", what, word);
  if (const auto near = compiler::closest(word, known)) fmt::print(stderr, "help: did you mean `{}`?\n", *near);
}

}  // namespace

bool unknown_command(const CLI::App& app, int argc, const char* const* argv) {
  if (argc < 2) return false;
  const std::string word = argv[1];
  if (word.rfind('-', 0) == 0) {
    const std::vector<std::string> options = option_names(app);
    const std::string name = word.substr(0, word.find('='));
    for (const std::string& o : options)
      if (o == name) return false;
    complain_unknown("unknown option", name, options);
  } else {
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
    for (const std::string& c : commands)
      if (c == word) return false;
    complain_unknown("unknown command", word, commands);
  }
  fmt::print(stderr, "run `esc --help` for the commands and their options\n");
  return true;
}

bool unexpected_arguments(const CLI::App& command) {
  const std::vector<std::string> extras = command.remaining();
  if (extras.empty()) return false;
  const std::string name = "esc " + command.get_name();
  for (const std::string& word : extras) {
    if (word.rfind('-', 0) == 0 && word.size() > 1)
      complain_unknown(fmt::format("`{}` has no option", name), word.substr(0, word.find('=')), option_names(command));
    else
      fmt::print(stderr, "esc: error: `{}` takes no further argument `{}`\n", name, word);
  }
  fmt::print(stderr, "run `{} --help` for its arguments and options\n", name);
  return true;
}

}  // namespace esc::cli
