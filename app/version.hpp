#pragma once

namespace esc::app {

// esc's version: stored with every run, and part of every dependency cache key.
[[nodiscard]] const char* version() noexcept;

}  // namespace esc::app
