#pragma once
// The jobs' one thread pool (the sweep runner, contact tables): persistent workers that run one
// job together, the caller's thread included.
#include <condition_variable>
#include <cstdint>
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

}  // namespace mh
