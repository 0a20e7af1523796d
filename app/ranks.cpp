#include "app/ranks.hpp"

#include <exception>

#include "app/error.hpp"
#include "runtime/dist/mpi_session.hpp"

namespace esc::app {

const dist::MpiSession* job() {
  const dist::MpiSession* mpi = dist::MpiSession::current();
  return mpi != nullptr && mpi->active() ? mpi : nullptr;
}

bool follower_rank() { return job() != nullptr && !job()->is_root(); }

bool agree(bool rank0) {
  if (job() == nullptr) return rank0;
  std::string text = rank0 ? "1" : "0";
  job()->broadcast(text);
  return text == "1";
}

void agree(std::string& text) {
  if (job() != nullptr) job()->broadcast(text);
}

void on_rank0(const std::function<void()>& act) {
  if (follower_rank()) {
    if (!job()->all_ok(true)) throw follower_error(ErrorKind::Results);
    return;
  }
  try {
    act();
  } catch (const Error&) {
    if (job() != nullptr) (void)job()->all_ok(false);
    throw;
  } catch (const std::exception& e) {   // a directory that cannot be made, a full disk
    if (job() != nullptr) (void)job()->all_ok(false);
    throw Error(ErrorKind::Results, e.what());
  }
  if (job() != nullptr) (void)job()->all_ok(true);
}

}  // namespace esc::app
