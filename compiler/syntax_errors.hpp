#pragma once
// Turns ANTLR's lexer and parser errors into located Diagnostics in our own words: no
// ANTLR text ("mismatched input ... expecting {...}") ever reaches a user.
#include <cstddef>
#include <filesystem>
#include <string_view>
#include <vector>

#include <antlr4-runtime.h>

#include "compiler/sink.hpp"

namespace esc::compiler {

class SyntaxErrorListener final : public antlr4::BaseErrorListener {
 public:
  SyntaxErrorListener(std::filesystem::path file, std::string_view text, Sink& sink)
      : file_(std::move(file)), text_(text), sink_(sink) {}

  void syntaxError(antlr4::Recognizer* recognizer, antlr4::Token* offending, std::size_t line,
                   std::size_t column, const std::string& msg, std::exception_ptr e) override;

  // Token indices at which the parser reported an error (for poisoning declarations).
  [[nodiscard]] const std::vector<std::size_t>& error_tokens() const noexcept { return error_tokens_; }
  [[nodiscard]] int count() const noexcept { return count_; }
  void set_tokens(antlr4::TokenStream* tokens) noexcept { tokens_ = tokens; }

 private:
  void lexer_error(std::size_t line, std::size_t column);
  void parser_error(antlr4::Parser* parser, antlr4::Token* offending, std::exception_ptr e);
  bool admit(int line, bool always = false);

  std::filesystem::path file_;
  std::string_view text_;
  Sink& sink_;
  antlr4::TokenStream* tokens_ = nullptr;
  std::vector<std::size_t> error_tokens_;
  int count_ = 0;
  int last_line_ = 0;
};

// A range covering token `t` (length in characters, at least 1).
[[nodiscard]] SourceRange token_range(const std::filesystem::path& file, const antlr4::Token* t);

}  // namespace esc::compiler
