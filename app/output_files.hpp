#pragma once
// The files the commands write beside results (replays, their animations, exported tables):
// written as the store writes its own views, whole or not at all, so that a reader never
// meets half a file. The clients write through this, not the store's header.
#include "runtime/store/run_directory.hpp"

namespace esc::app {

// `text` into `file` through a temporary file beside it, renamed over it.
using store::write_atomically;

}  // namespace esc::app
