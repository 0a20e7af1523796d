#pragma once
// What the module raises as esc.Error (esc/errors.py): a problem with the caller's input that
// is neither a script error (returned as diagnostics) nor a wrong argument (ValueError), with
// the message the CLI prints after "esc: error:". runtime/store's StoreError is raised the same way.
#include <stdexcept>

namespace esc::python {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace esc::python
