#pragma once
#include <utility>

#include "app/error.hpp"
#include "app/ranks.hpp"
#include "runtime/dist/mpi_session.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::app {

// What `act` returns; a store::StoreError it throws (a directory missing, damaged or
// locked) becomes an Error of kind Results. In a job of several ranks it goes on as it is:
// it may have reached rank 0 alone, and the program must end the whole job.
template <typename F>
auto store_errors_typed(F&& act) -> decltype(act()) {
  try {
    return std::forward<F>(act)();
  } catch (const store::StoreError& e) {
    if (job() != nullptr && job()->size() > 1) throw;
    throw Error(ErrorKind::Results, e.what());
  }
}

}  // namespace esc::app
