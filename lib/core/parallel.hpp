#pragma once
// The library's one thread pool and its one way of sharing independent items between threads.
// Pool: persistent workers that run one job together, the caller's thread included (the sweep
// runner and the contact tables keep one for a whole run). parallel_for: blocks of consecutive
// indices handed out in order to a fixed number of threads, each with its own state (a
// workspace), on a Pool made for the call (the C interface's batches, the wheelset steps of the
// Python module, the geometry sweeps).
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace mh {

// A persistent pool: `n` threads (the caller's included as thread 0) run job(t) together.
class Pool {
 public:
  explicit Pool(unsigned n) : n_(n) {
    for (unsigned t = 1; t < n_; ++t) threads_.emplace_back([this, t] { loop(t); });
  }
  ~Pool() {
    { std::lock_guard<std::mutex> l(m_); stop_ = true; }
    cv_.notify_all();
    for (auto& th : threads_) th.join();
  }
  unsigned size() const { return n_; }
  void run(const std::function<void(unsigned)>& job) {
    {
      std::lock_guard<std::mutex> l(m_);
      job_ = &job;
      pending_ = n_ - 1;
      ++gen_;
    }
    cv_.notify_all();
    job(0);
    std::unique_lock<std::mutex> l(m_);
    done_.wait(l, [this] { return pending_ == 0; });
    job_ = nullptr;
  }

 private:
  void loop(unsigned t) {
    std::uint64_t seen = 0;
    for (;;) {
      const std::function<void(unsigned)>* job;
      {
        std::unique_lock<std::mutex> l(m_);
        cv_.wait(l, [&] { return stop_ || gen_ != seen; });
        if (stop_) return;
        seen = gen_;
        job = job_;
      }
      (*job)(t);
      std::lock_guard<std::mutex> l(m_);
      if (--pending_ == 0) done_.notify_one();
    }
  }
  unsigned n_;
  std::vector<std::thread> threads_;
  std::mutex m_;
  std::condition_variable cv_, done_;
  const std::function<void(unsigned)>* job_ = nullptr;
  std::uint64_t gen_ = 0;
  unsigned pending_ = 0;
  bool stop_ = false;
};

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
  if (nt == 1) {
    worker();
  } else {
    Pool pool(static_cast<unsigned>(nt));
    pool.run([&](unsigned) { worker(); });
  }
  if (first) std::rethrow_exception(first);
}

}  // namespace mh
