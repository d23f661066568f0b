#include "rigiddyn/batch/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace rigiddyn {

int default_thread_count() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(std::min<unsigned>(n, std::numeric_limits<int>::max()));
}

namespace {

// The failure of the lowest task index seen so far (any thread may report one).
class FirstFailure {
 public:
  void keep(std::size_t k, std::exception_ptr error) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!error_ || k < k_) error_ = std::move(error), k_ = k;
  }
  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr error_;
  std::size_t k_ = 0;
};

}  // namespace

void parallel_for(std::size_t n_tasks, int threads, const std::function<void(std::size_t k, int worker)>& task,
                  const std::function<void()>& wait, int wait_interval_ms) {
  if (threads < 1) throw std::invalid_argument("threads: expected an integer >= 1, got " + std::to_string(threads));
  if (n_tasks == 0) return;
  std::atomic<std::size_t> next{0};
  FirstFailure failure;
  auto work = [&](int worker) {
    for (std::size_t k = next.fetch_add(1, std::memory_order_relaxed); k < n_tasks;
         k = next.fetch_add(1, std::memory_order_relaxed)) {
      try {
        task(k, worker);
      } catch (...) {
        failure.keep(k, std::current_exception());
      }
    }
  };

  // workers 1 .. helpers; each says when it is done, so that the calling thread can wait with `wait`
  const int helpers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads) - 1, n_tasks - 1));
  std::mutex done_mutex;
  std::condition_variable done_signal;
  int running = helpers;
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(helpers));
  for (int w = 1; w <= helpers; ++w) {
    try {
      pool.emplace_back([&, w] {
        work(w);
        std::lock_guard<std::mutex> lock(done_mutex);
        --running;
        done_signal.notify_one();
      });
    } catch (const std::system_error&) {  // no more threads to be had: run on those started
      std::lock_guard<std::mutex> lock(done_mutex);
      running -= helpers - w + 1;
      break;
    }
  }
  work(0);
  {
    std::unique_lock<std::mutex> lock(done_mutex);
    while (running > 0) {
      if (!wait) {
        done_signal.wait(lock, [&] { return running == 0; });
        break;
      }
      done_signal.wait_for(lock, std::chrono::milliseconds(wait_interval_ms), [&] { return running == 0; });
      if (running == 0) break;
      lock.unlock();
      try {
        wait();
      } catch (...) {
        failure.keep(0, std::current_exception());
      }
      lock.lock();
    }
  }
  for (std::thread& t : pool) t.join();
  failure.rethrow();
}

}  // namespace rigiddyn
