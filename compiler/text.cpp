#include "compiler/text.hpp"

#include <algorithm>

namespace esc::compiler {

namespace {

// Length of the valid UTF-8 sequence starting at s[i], or 0 when it is invalid.
std::size_t valid_sequence(std::string_view s, std::size_t i) noexcept {
  const auto b0 = static_cast<unsigned char>(s[i]);
  if (b0 < 0x80) return 1;
  std::size_t n = 0;
  unsigned int cp = 0;
  if ((b0 & 0xE0) == 0xC0) { n = 2; cp = b0 & 0x1Fu; }
  else if ((b0 & 0xF0) == 0xE0) { n = 3; cp = b0 & 0x0Fu; }
  else if ((b0 & 0xF8) == 0xF0) { n = 4; cp = b0 & 0x07u; }
  else return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const auto b = static_cast<unsigned char>(s[i + k]);
    if ((b & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (b & 0x3Fu);
  }
  // Overlong forms, surrogates and values past U+10FFFF are invalid.
  if ((n == 2 && cp < 0x80) || (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000)) return 0;
  if (cp >= 0xD800 && cp <= 0xDFFF) return 0;
  if (cp > 0x10FFFF) return 0;
  return n;
}

}  // namespace

CleanText clean_utf8(std::string_view text) {
  CleanText out;
  out.display.reserve(text.size());
  out.parser.reserve(text.size());
  int line = 1, column = 1, last_bad_line = 0;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t n = valid_sequence(text, i);
    if (n == 0) {
      if (last_bad_line != line) {
        out.invalid.push_back({line, column});
        last_bad_line = line;
      }
      out.display += "\xEF\xBF\xBD";
      out.parser += ' ';
      ++i;
      ++column;
      continue;
    }
    out.display.append(text.substr(i, n));
    out.parser.append(text.substr(i, n));
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
    i += n;
  }
  return out;
}

int utf8_length(std::string_view s) noexcept {
  int n = 0;
  for (char c : s)
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++n;
  return n;
}

std::string_view line_of(std::string_view text, int line) noexcept {
  if (line < 1) return {};
  std::size_t pos = 0;
  for (int l = 1; l < line; ++l) {
    const std::size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) return {};
    pos = nl + 1;
  }
  std::size_t end = text.find('\n', pos);
  if (end == std::string_view::npos) end = text.size();
  std::string_view s = text.substr(pos, end - pos);
  if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
  return s;
}

namespace {

// The first `n` characters of valid UTF-8 `s`, as bytes.
std::size_t bytes_of_first(std::string_view s, int n) noexcept {
  std::size_t i = 0;
  for (int k = 0; k < n && i < s.size(); ++k) {
    ++i;
    while (i < s.size() && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) ++i;
  }
  return i;
}

}  // namespace

std::string shorten_names(std::string_view text) {
  constexpr int kHead = 40, kTail = 16;
  std::string out;
  out.reserve(std::min<std::size_t>(text.size(), 4096));
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t open = text.find('`', i);
    const std::size_t close = open == std::string_view::npos ? open : text.find('`', open + 1);
    if (close == std::string_view::npos) {
      out += text.substr(i);
      break;
    }
    const std::string_view name = text.substr(open + 1, close - open - 1);
    out += text.substr(i, open + 1 - i);
    const int length = utf8_length(name);
    if (length <= kLongName || name.starts_with("esc ")) {
      out += name;
      out += '`';
    } else {
      out += name.substr(0, bytes_of_first(name, kHead));
      out += "\xE2\x80\xA6";   // …
      out += name.substr(bytes_of_first(name, length - kTail));
      out += "` (" + std::to_string(length) + " characters)";
    }
    i = close + 1;
  }
  return out;
}

}  // namespace esc::compiler
