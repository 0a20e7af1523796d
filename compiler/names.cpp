#include "compiler/names.hpp"

#include <algorithm>

namespace esc::compiler {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment distance, O(|a| |b|) with three rows.
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::size_t> prev2(m + 1), prev(m + 1), cur(m + 1);
  for (std::size_t j = 0; j <= m; ++j) prev[j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        cur[j] = std::min(cur[j], prev2[j - 2] + 1);
    }
    std::swap(prev2, prev);
    std::swap(prev, cur);
  }
  return prev[m];
}

std::optional<std::string> closest(std::string_view word, const std::vector<std::string>& candidates) {
  if (word.empty() || word.size() > 64) return std::nullopt;
  std::optional<std::string> best;
  std::size_t best_d = 0;
  for (const std::string& c : candidates) {
    if (c == word || c.size() > 64) continue;
    const std::size_t d = edit_distance(word, c);
    // Allow about one edit per three characters, at least one, but keep something in
    // common: `c` is no suggestion for an unknown `d` (but `CC` is for `C`).
    const std::size_t limit = std::max<std::size_t>(1, std::max(word.size(), c.size()) / 3);
    if (d <= limit && d < std::max(word.size(), c.size()) && (!best || d < best_d)) {
      best = c;
      best_d = d;
    }
  }
  return best;
}

bool suggest(Diagnostic& d, std::string_view word, const std::vector<std::string>& candidates,
             const Suggestion& how) {
  const auto best = closest(word, candidates);
  if (best) d.message += "; did you mean `" + std::string(how.prefix) + *best + "`?";
  if ((!best || how.always) && !how.otherwise.empty()) d.help.push_back(how.otherwise);
  return best.has_value();
}

std::string quoted_list(const std::vector<std::string>& items, std::string_view last_sep) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) s += (i + 1 == items.size()) ? std::string(last_sep) : std::string(", ");
    s += '`' + items[i] + '`';
  }
  return s;
}

}  // namespace esc::compiler
