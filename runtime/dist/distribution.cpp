#include "runtime/dist/distribution.hpp"

#include <algorithm>
#include <mutex>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <mpi.h>

#include "runtime/dist/mpi_session.hpp"

namespace esc::dist {

struct Distribution::Impl {
  MPI_Win window = MPI_WIN_NULL;
  bool serialized = false;           // any thread may call MPI, one at a time
  std::int64_t* counter = nullptr;   // on rank 0: the next item to hand out
  int rank = 0;
  int size = 1;
};

Distribution::Distribution() {
  const MpiSession* session = MpiSession::current();
  if (session == nullptr || !session->active() || session->size() < 2) return;
  impl_ = std::make_unique<Impl>();
  impl_->rank = session->rank();
  impl_->size = session->size();
  impl_->serialized = session->thread_support() >= MPI_THREAD_SERIALIZED;
  const MPI_Aint bytes = impl_->rank == 0 ? static_cast<MPI_Aint>(sizeof(std::int64_t)) : 0;
  MPI_Win_allocate(bytes, sizeof(std::int64_t), MPI_INFO_NULL, MPI_COMM_WORLD, &impl_->counter,
                   &impl_->window);
}

Distribution::~Distribution() {
  if (impl_) MPI_Win_free(&impl_->window);
}

std::size_t Distribution::workers(std::size_t threads_here) const {
  if (!impl_) return threads_here;
  auto mine = static_cast<unsigned long long>(threads_here);
  unsigned long long all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  return static_cast<std::size_t>(all);
}

void Distribution::run(std::size_t n, std::size_t width, std::size_t threads, std::span<double> results,
                       const std::function<void(std::size_t)>& evaluate) {
  if (!impl_) {
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) { evaluate(i); });
    return;
  }
  // Reset the counter on rank 0 before anyone takes from it.
  if (impl_->rank == 0) {
    MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, impl_->window);
    *impl_->counter = 0;
    MPI_Win_unlock(0, impl_->window);
  }
  MPI_Barrier(MPI_COMM_WORLD);

  // Each thread takes items one at a time until the generation is used up. MPI is called
  // by one thread at a time (MPI_THREAD_SERIALIZED); with less thread support, only this
  // thread fetches, a batch of `threads` items at a time.
  std::mutex mpi;
  const auto take = [&](std::int64_t count) {
    std::int64_t first = 0;
    const std::lock_guard<std::mutex> lock(mpi);
    MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, impl_->window);
    MPI_Fetch_and_op(&count, &first, MPI_INT64_T, 0, 0, MPI_SUM, impl_->window);
    MPI_Win_unlock(0, impl_->window);
    return first;
  };
  std::vector<std::vector<std::size_t>> done(std::max<std::size_t>(threads, 1));
  if (impl_->serialized) {
    tbb::parallel_for(std::size_t{0}, done.size(), [&](std::size_t t) {
      for (std::int64_t i; (i = take(1)) < static_cast<std::int64_t>(n);) {
        evaluate(static_cast<std::size_t>(i));
        done[t].push_back(static_cast<std::size_t>(i));
      }
    }, tbb::simple_partitioner());
  } else {
    const auto batch = static_cast<std::int64_t>(done.size());
    for (std::int64_t first; (first = take(batch)) < static_cast<std::int64_t>(n);) {
      const auto begin = static_cast<std::size_t>(first);
      const std::size_t end = std::min(n, begin + done.size());
      tbb::parallel_for(begin, end, [&](std::size_t i) { evaluate(i); });
      for (std::size_t i = begin; i < end; ++i) done[0].push_back(i);
    }
  }
  std::vector<double> mine;   // packed: index, then `width` values, per item
  for (const auto& items : done)
    for (const std::size_t i : items) {
      mine.push_back(static_cast<double>(i));
      mine.insert(mine.end(), results.begin() + static_cast<std::ptrdiff_t>(i * width),
                  results.begin() + static_cast<std::ptrdiff_t>((i + 1) * width));
    }

  // Everyone receives everyone's results, bit for bit.
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(impl_->size));
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::vector<int> offsets(counts.size(), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(static_cast<std::size_t>(offsets.back() + counts.back()));
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 MPI_COMM_WORLD);
  for (std::size_t p = 0; p < all.size(); p += width + 1) {
    const auto i = static_cast<std::size_t>(all[p]);
    std::copy_n(all.begin() + static_cast<std::ptrdiff_t>(p + 1), width,
                results.begin() + static_cast<std::ptrdiff_t>(i * width));
  }
}

}  // namespace esc::dist
