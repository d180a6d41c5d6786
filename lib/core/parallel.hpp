#pragma once
// The library's one way of sharing independent items between threads (the C interface's batches,
// the wheelset steps of the Python module): blocks of consecutive indices handed out in order to
// a fixed number of threads, each with its own state (a workspace). No pool is kept between calls.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace mh {

/// Threads for n items in blocks of `block`: `threads` (0: every core), at most one per block.
inline std::size_t parallel_threads(std::size_t n, unsigned threads, std::size_t block) {
  const std::size_t want = threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  return std::max<std::size_t>(1, std::min(want, (n + block - 1) / block));
}

/// body(i, state) for every i in [0, n), on parallel_threads(n, threads, block) threads; each
/// thread makes its state once with make_state() (a workspace: whatever it holds, the results must
/// not depend on which thread ran an item). The calling thread works too. The first exception
/// of any thread is rethrown once every thread has stopped (the others finish their items).
template <class MakeState, class Body>
void parallel_for(std::size_t n, unsigned threads, std::size_t block, MakeState&& make_state, Body&& body) {
  const std::size_t nt = parallel_threads(n, threads, block);
  std::atomic<std::size_t> next{0};
  std::exception_ptr first;
  std::mutex m;
  auto worker = [&]() {
    try {
      auto state = make_state();
      for (;;) {
        const std::size_t b = next.fetch_add(block);
        if (b >= n) break;
        const std::size_t e = std::min(n, b + block);
        for (std::size_t i = b; i < e; ++i) body(i, state);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(m);
      if (!first) first = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(nt - 1);
  for (std::size_t t = 1; t < nt; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& th : pool) th.join();
  if (first) std::rethrow_exception(first);
}

}  // namespace mh
