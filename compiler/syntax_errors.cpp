#include "compiler/syntax_errors.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <string>

#include <fmt/format.h>

#include "compiler/names.hpp"
#include "compiler/text.hpp"
#include "grammar/EscLexer.h"
#include "grammar/EscParser.h"

namespace esc::compiler {

using grammar::EscParser;

namespace {

constexpr int kMaxSyntaxErrors = 30;

bool is_wordish(std::size_t type) {
  switch (type) {
    case EscParser::ID: case EscParser::X: case EscParser::STEPS: case EscParser::STEP:
    case EscParser::EPOCH: case EscParser::EPOCHS: case EscParser::STOP: case EscParser::WHEN:
    case EscParser::AT: case EscParser::RADIUS: case EscParser::SIZE: case EscParser::BOX:
    case EscParser::ANGLE: case EscParser::START: case EscParser::RANDOM:
    case EscParser::HEADING: case EscParser::CYLINDER: case EscParser::BLOCK:
    case EscParser::MLP: case EscParser::NEAT: case EscParser::SYMBOLIC: case EscParser::ACTIONS:
    case EscParser::FOR: case EscParser::GENERATIONS: case EscParser::RUNS:
    case EscParser::SEED: case EscParser::COMPARE: case EscParser::EVOLVE: case EscParser::LIGHT:
    case EscParser::ABOVE: case EscParser::HEIGHT: case EscParser::INTENSITY: case EscParser::ZONE:
    case EscParser::CIRCLE: case EscParser::RECT: case EscParser::VISIBLE: case EscParser::INVISIBLE:
    case EscParser::RECHARGE: case EscParser::SWEEP_CELL: case EscParser::REACH_RADIUS:
    case EscParser::ELMAN: case EscParser::SUPERVISOR: case EscParser::BEHAVIORS: case EscParser::ON:
    case EscParser::OFF: case EscParser::EVOLVED: case EscParser::FROM: case EscParser::TREE:
    case EscParser::FUNCTIONS: case EscParser::TERMINALS: case EscParser::EVALUATE:
    case EscParser::CONDITIONS: case EscParser::CONDITION: case EscParser::SWEEP: case EscParser::AS:
    case EscParser::BY: case EscParser::EVALUATION: case EscParser::OBJECTIVE: case EscParser::MAXIMIZE:
    case EscParser::MINIMIZE: case EscParser::DESCRIPTOR: case EscParser::IN: case EscParser::WALL:
    case EscParser::GOAL: case EscParser::TO: case EscParser::THICKNESS: case EscParser::SUCCESS:
    case EscParser::OVER: case EscParser::FORMATION: case EscParser::ROLES: case EscParser::PER_BODY: return true;
    default: return false;
  }
}

bool is_soft_keyword(std::size_t type) { return type != EscParser::ID && is_wordish(type); }

std::string literal(const antlr4::dfa::Vocabulary& v, std::size_t type) {
  std::string s = v.getLiteralName(type);
  if (s.size() >= 2 && s.front() == '\'' && s.back() == '\'') s = s.substr(1, s.size() - 2);
  return s;
}

bool is_word(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || c == '_';
  });
}

std::string shown(const antlr4::Token* t) {
  if (t == nullptr || t->getType() == antlr4::Token::EOF) return "end of file";
  std::string s = t->getText();
  if (utf8_length(s) > 30) {
    // Cut on a character boundary.
    std::size_t cut = 27;
    while (cut < s.size() && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) ++cut;
    s = s.substr(0, cut) + "...";
  }
  return "`" + s + "`";
}

struct Expected {
  std::string phrase;                 // "a name", "`{`", "an expression", ...
  std::vector<std::string> words;     // keywords expected, for "did you mean"
  bool closer = false;                // `}`, `)` or `]` is among them
  std::string closer_text;
};

// "a, b or c".
std::string listed(const std::vector<std::string>& items) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) s += (i + 1 == items.size()) ? " or " : ", ";
    s += items[i];
  }
  return s;
}

// What the loop of rule `rule` reads, item by item, each starting with a keyword; empty for
// the other rules. The keywords themselves come from the parser's expected set, so a
// keyword added to the grammar appears in every message without an edit here.
std::string_view items_of(std::size_t rule) {
  switch (rule) {
    case EscParser::RuleScript: return "a declaration";
    case EscParser::RuleArenaDecl: return "an arena item";
    case EscParser::RuleFitnessDecl: return "a fitness item";
    case EscParser::RuleExperimentDecl: return "an experiment item";
    case EscParser::RuleLibraryDecl: return "a library member";
    case EscParser::RulePrimitivesDecl: return "a primitives item";
    case EscParser::RuleStudyDecl: return "a study item";
    default: return {};
  }
}

bool is_binary_operator(std::size_t t) {
  switch (t) {
    case EscParser::CARET: case EscParser::STAR: case EscParser::SLASH: case EscParser::PLUS: case EscParser::MINUS:
    case EscParser::LT: case EscParser::LE: case EscParser::GT: case EscParser::GE: case EscParser::EQ:
    case EscParser::NE: case EscParser::AND: case EscParser::OR: return true;
    default: return false;
  }
}

// `set`, the tokens the parser could take at an error in rule `rule`, in words: every
// keyword of it, nothing cut.
Expected describe(const antlr4::misc::IntervalSet& set, const antlr4::dfa::Vocabulary& v, std::size_t rule) {
  Expected e;
  auto has = [&](std::size_t t) { return set.contains(t); };
  const bool name = has(EscParser::ID);
  for (ssize_t raw : set.toList()) {
    if (raw < 0) continue;
    const auto t = static_cast<std::size_t>(raw);
    const std::string lit = literal(v, t);
    if (is_word(lit)) e.words.push_back(lit);
    if (t == EscParser::RBRACE || t == EscParser::RPAREN || t == EscParser::RBRACK) {
      if (!e.closer) e.closer_text = lit;
      e.closer = true;
    }
  }
  if (has(EscParser::NUMBER) && has(EscParser::LPAREN) && has(EscParser::NOT) && name) {
    e.phrase = "an expression";
    return e;
  }
  if (const std::string_view kind = items_of(rule); !kind.empty() && !name && !e.words.empty()) {
    std::vector<std::string> quoted;
    for (const std::string& w : e.words) quoted.push_back("`" + w + "`");
    e.phrase = fmt::format("{} ({})", kind, listed(quoted));
    if (e.closer) e.phrase += " or `" + e.closer_text + "`";
    return e;
  }
  std::vector<std::string> items;
  const bool operators = has(EscParser::STAR) && has(EscParser::PLUS) && has(EscParser::AND);
  if (operators) items.emplace_back("an operator");
  for (ssize_t raw : set.toList()) {
    if (raw < 0) {
      items.emplace_back("end of file");
      continue;
    }
    const auto t = static_cast<std::size_t>(raw);
    if ((name && is_soft_keyword(t)) || (operators && is_binary_operator(t))) continue;
    switch (t) {
      case EscParser::ID: items.emplace_back("a name"); break;
      case EscParser::NUMBER: items.emplace_back("a number"); break;
      case EscParser::STRING: items.emplace_back("a string"); break;
      case EscParser::UNIT: items.emplace_back("a unit"); break;
      default: {
        const std::string lit = literal(v, t);
        if (!lit.empty()) items.push_back("`" + lit + "`");
      }
    }
  }
  if (items.empty()) items.emplace_back("something else");
  e.phrase = listed(items);
  return e;
}

// Whether the token is the name of a declaration: `<keyword> <name>`.
std::string decl_name_kind(antlr4::TokenStream* ts, const antlr4::Token* prev) {
  if (ts == nullptr || prev == nullptr || !is_wordish(prev->getType())) return {};
  const std::size_t i = prev->getTokenIndex();
  if (i == 0 || i == static_cast<std::size_t>(-1)) return {};
  const antlr4::Token* kw = ts->get(i - 1);
  switch (kw->getType()) {
    case EscParser::ARENA: return "arena";
    case EscParser::ROBOT: return "robot";
    case EscParser::BEHAVIOR: return "behavior";
    case EscParser::FITNESS: return "fitness";
    case EscParser::CONTROLLER: return "controller";
    case EscParser::EXPERIMENT: return "experiment";
    case EscParser::PRIMITIVES: return "primitives";
    case EscParser::STUDY: return "study";
    default: return {};
  }
}

}  // namespace

SourceRange token_range(const std::filesystem::path& file, const antlr4::Token* t) {
  SourceRange r;
  r.file = file;
  if (t == nullptr) return r;
  r.line = static_cast<int>(t->getLine());
  r.column = static_cast<int>(t->getCharPositionInLine()) + 1;
  r.length = t->getType() == antlr4::Token::EOF ? 1 : std::max(1, utf8_length(t->getText()));
  return r;
}

bool SyntaxErrorListener::admit(int line, bool always) {
  if (count_ >= kMaxSyntaxErrors) return false;
  if (line == last_line_ && !always) return false;   // one error per line: the rest are follow-ons
  last_line_ = line;
  ++count_;
  return true;
}

void SyntaxErrorListener::syntaxError(antlr4::Recognizer* recognizer, antlr4::Token* offending,
                                      std::size_t line, std::size_t column, const std::string& /*antlr_message*/,
                                      std::exception_ptr e) {
  try {
    if (auto* parser = dynamic_cast<antlr4::Parser*>(recognizer))
      parser_error(parser, offending, e);
    else
      lexer_error(line, column);
  } catch (...) {
    // Never let a diagnostic problem escape; report a plain error at the position.
    if (admit(static_cast<int>(line))) {
      SourceRange r{file_, static_cast<int>(line), static_cast<int>(column) + 1, 1};
      sink_.error(r, "syntax error");
    }
  }
}

void SyntaxErrorListener::lexer_error(std::size_t line, std::size_t column) {
  const int l = static_cast<int>(line);
  const int c = static_cast<int>(column) + 1;
  // The offending character, from the text shown to the user.
  const std::string_view src = line_of(text_, l);
  std::string ch;
  int col = 1;
  for (std::size_t i = 0; i < src.size();) {
    std::size_t n = 1;
    while (i + n < src.size() && (static_cast<unsigned char>(src[i + n]) & 0xC0) == 0x80) ++n;
    if (col == c) {
      ch = std::string(src.substr(i, n));
      break;
    }
    ++col;
    i += n;
  }
  if (!admit(l)) return;
  SourceRange r{file_, l, c, 1};
  if (ch == "\"") {
    sink_.error(r, "unterminated string").help.push_back("close the string with `\"` on the same line");
    return;
  }
  std::string desc;
  if (ch.empty()) {
    desc = "character";
  } else if (ch.size() == 1 && (static_cast<unsigned char>(ch[0]) < 0x20 || ch[0] == 0x7f)) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(static_cast<unsigned char>(ch[0])));
    desc = std::string("character ") + buf;
  } else {
    desc = "character `" + ch + "`";
  }
  Diagnostic& d = sink_.error(r, "unexpected " + desc);
  if (ch == "&") d.help.push_back("write `and` for a logical and");
  else if (ch == "|") d.help.push_back("write `or` for a logical or");
  else if (ch == "!") d.help.push_back("write `not` for a negation, `!=` for inequality");
  else if (ch == "#") d.help.push_back("comments start with `//`");
  else if (ch == "%") d.help.push_back("there is no `%` operator; units are written after numbers: `60cm`");
  else if (ch == ".") d.help.push_back("write numbers with digits on both sides of the point: `0.5`");
  else if (ch == "'") d.help.push_back("strings use double quotes: \"lib/khepera.esc\"");
}

void SyntaxErrorListener::parser_error(antlr4::Parser* parser, antlr4::Token* offending,
                                       std::exception_ptr) {
  if (offending == nullptr) return;
  error_tokens_.push_back(offending->getTokenIndex());
  antlr4::TokenStream* ts = tokens_ != nullptr ? tokens_ : parser->getTokenStream();
  const antlr4::Token* prev = nullptr;
  const std::size_t idx = offending->getTokenIndex();
  if (idx != static_cast<std::size_t>(-1) && idx > 0 && ts != nullptr) prev = ts->get(idx - 1);

  antlr4::misc::IntervalSet set;
  try {
    set = parser->getExpectedTokens();
  } catch (...) {
  }
  const std::size_t rule = parser->getContext() != nullptr ? parser->getContext()->getRuleIndex() : 0;
  const Expected ex = describe(set, parser->getVocabulary(), rule);

  SourceRange where = token_range(file_, offending);
  const bool at_eof = offending->getType() == antlr4::Token::EOF;
  if (at_eof && prev != nullptr) {
    // Point just past the last token, on its line.
    where = token_range(file_, prev);
    where.column += where.length;
    where.length = 1;
  }
  if (!admit(where.line, at_eof)) return;

  std::string after;
  if (prev != nullptr) {
    const std::string kind = decl_name_kind(ts, prev);
    after = kind.empty() ? " after " + shown(prev) : " after the " + kind + " name";
  }

  if (at_eof) {
    if (ex.closer) {
      Diagnostic& d = sink_.error(where, "unexpected end of file: missing `" + ex.closer_text + "`");
      // Point at the bracket left open.
      if (ts != nullptr && idx != static_cast<std::size_t>(-1)) {
        std::vector<const antlr4::Token*> open;
        for (std::size_t i = 0; i < idx; ++i) {
          const antlr4::Token* t = ts->get(i);
          const std::size_t ty = t->getType();
          if (ty == EscParser::LBRACE || ty == EscParser::LPAREN || ty == EscParser::LBRACK)
            open.push_back(t);
          else if ((ty == EscParser::RBRACE || ty == EscParser::RPAREN || ty == EscParser::RBRACK) &&
                   !open.empty())
            open.pop_back();
        }
        if (!open.empty())
          d.notes.emplace_back(token_range(file_, open.back()),
                               "to match this `" + open.back()->getText() + "`");
      }
    } else {
      sink_.error(where, "unexpected end of file: expected " + ex.phrase + after);
    }
    return;
  }

  const std::size_t ot = offending->getType();
  const bool decl_keyword = ot == EscParser::IMPORT || ot == EscParser::ARENA || ot == EscParser::ROBOT ||
                            ot == EscParser::BEHAVIOR || ot == EscParser::FITNESS || ot == EscParser::CONTROLLER ||
                            ot == EscParser::EXPERIMENT || ot == EscParser::PRIMITIVES || ot == EscParser::STUDY;
  if (decl_keyword && ex.closer && ex.closer_text == "}" && set.contains(static_cast<std::size_t>(EscParser::RBRACE)) &&
      !set.contains(ot)) {
    // A declaration starts inside an unclosed block: the `}` is missing.
    Diagnostic& d = sink_.error(where, "missing `}` before " + shown(offending));
    if (ts != nullptr && idx != static_cast<std::size_t>(-1)) {
      std::vector<const antlr4::Token*> open;
      for (std::size_t i = 0; i < idx; ++i) {
        const antlr4::Token* t = ts->get(i);
        if (t->getType() == EscParser::LBRACE) open.push_back(t);
        else if (t->getType() == EscParser::RBRACE && !open.empty()) open.pop_back();
      }
      if (!open.empty()) d.notes.emplace_back(token_range(file_, open.back()), "to match this `{`");
    }
    return;
  }
  if (is_wordish(offending->getType()) && !ex.words.empty()) {
    if (closest(offending->getText(), ex.words)) {
      suggest(sink_.error(where, "unknown word " + shown(offending)), offending->getText(), ex.words,
              {.otherwise = "expected " + ex.phrase + after, .always = true});
      return;
    }
  }
  Diagnostic& d = sink_.error(where, "expected " + ex.phrase + after + ", found " + shown(offending));
  if (offending->getType() == EscParser::ELSE || offending->getType() == EscParser::THEN)
    d.help.push_back("a conditional is written `if c then a else b`");
  else if (offending->getType() == EscParser::UNIT)
    d.help.push_back("a unit goes right after its number, as in `60cm`");
  else if (offending->getType() == EscParser::STRING && prev == nullptr)
    d.help.push_back("an import is written `import \"lib/khepera.esc\"`");
}

}  // namespace esc::compiler
