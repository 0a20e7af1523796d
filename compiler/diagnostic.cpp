// Rendering of diagnostics in the style of Clang and rustc.
#include "compiler/diagnostic.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "compiler/text.hpp"

namespace esc::compiler {

namespace {

constexpr int kWindow = 100;   // characters shown around the caret on a long line

struct Style {
  bool on;
  [[nodiscard]] std::string bold(std::string_view s) const { return on ? fmt::format("\x1b[1m{}\x1b[0m", s) : std::string(s); }
  [[nodiscard]] std::string color(std::string_view code, std::string_view s) const {
    return on ? fmt::format("\x1b[1;{}m{}\x1b[0m", code, s) : std::string(s);
  }
};

std::string_view severity_name(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

std::string_view severity_color(Severity s) {
  switch (s) {
    case Severity::Error: return "31";
    case Severity::Warning: return "35";
    case Severity::Note: return "36";
  }
  return "31";
}

// Code points of a line, with tabs and control characters shown as one space each.
std::vector<std::string> characters(std::string_view line) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < line.size();) {
    std::size_t n = 1;
    while (i + n < line.size() && (static_cast<unsigned char>(line[i + n]) & 0xC0) == 0x80) ++n;
    const auto c = static_cast<unsigned char>(line[i]);
    if (n == 1 && (c < 0x20 || c == 0x7f)) out.emplace_back(" ");
    else out.emplace_back(line.substr(i, n));
    i += n;
  }
  return out;
}

std::string location(const SourceRange& r) {
  if (r.line <= 0) return r.file.string();
  return fmt::format("{}:{}:{}", r.file.string(), r.line, std::max(1, r.column));
}

// "  12 | text" and "     |    ^~~~" for a range, or nothing when the line is unknown.
std::string snippet(const SourceRange& r, const SourceMap& sources, const Style& st, Severity sev) {
  if (r.line <= 0) return {};
  const auto it = sources.find(r.file);
  if (it == sources.end()) return {};
  const std::string_view line = line_of(it->second, r.line);
  const std::vector<std::string> chars = characters(line);
  const int width = static_cast<int>(std::to_string(r.line).size());
  int col = std::max(1, r.column);
  int len = std::max(1, r.length);
  const int n = static_cast<int>(chars.size());
  // Window around the caret on long lines.
  int from = 0, to = n;
  if (n > 2 * kWindow) {
    from = std::max(0, col - 1 - kWindow / 2);
    to = std::min(n, from + 2 * kWindow);
  }
  std::string text = from > 0 ? "..." : "";
  for (int i = from; i < to; ++i) text += chars[static_cast<std::size_t>(i)];
  if (to < n) text += "...";
  const int shift = (from > 0 ? 3 : 0) - from;
  col += shift;
  const int end_col = std::min(std::max(col, (to - from) + (from > 0 ? 3 : 0) + 1), col + len - 1);
  len = std::max(1, end_col - col + 1);
  std::string caret = std::string(static_cast<std::size_t>(std::max(0, col - 1)), ' ') + "^" +
                      std::string(static_cast<std::size_t>(len - 1), '~');
  std::string out;
  out += fmt::format("{:>{}} | {}\n", r.line, width + 1, text);
  out += fmt::format("{:>{}} | {}\n", "", width + 1, st.color(severity_color(sev), caret));
  return out;
}

}  // namespace

std::string render(const Diagnostic& d, const SourceMap& sources, bool color) {
  const Style st{color};
  std::string out = st.bold(location(d.where) + ":") + " " + st.color(severity_color(d.severity), std::string(severity_name(d.severity)) + ":") +
                    " " + st.bold(shorten_names(d.message)) + "\n";
  out += snippet(d.where, sources, st, d.severity);
  for (const std::string& h : d.help) out += st.color("32", "help:") + " " + shorten_names(h) + "\n";
  for (const auto& [where, text] : d.notes) {
    out += st.bold(location(where) + ":") + " " + st.color(severity_color(Severity::Note), "note:") + " " +
           shorten_names(text) + "\n";
    out += snippet(where, sources, st, Severity::Note);
  }
  return out;
}

std::string render_all(const std::vector<Diagnostic>& ds, const SourceMap& sources, bool color) {
  std::string out;
  int errors = 0, warnings = 0;
  for (const Diagnostic& d : ds) {
    out += render(d, sources, color);
    if (d.severity == Severity::Error) ++errors;
    if (d.severity == Severity::Warning) ++warnings;
  }
  if (errors > 0 || warnings > 0) {
    std::vector<std::string> parts;
    if (errors > 0) parts.push_back(fmt::format("{} error{}", errors, errors == 1 ? "" : "s"));
    if (warnings > 0) parts.push_back(fmt::format("{} warning{}", warnings, warnings == 1 ? "" : "s"));
    out += fmt::format("{} generated.\n", fmt::join(parts, " and "));
  }
  return out;
}

}  // namespace esc::compiler
