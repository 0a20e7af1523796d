#include "app/version.hpp"

namespace esc::app {

const char* version() noexcept { return ESC_VERSION_STRING; }

}  // namespace esc::app
