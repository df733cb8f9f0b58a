#include "stickslip/numerics/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace stickslip {

int WorkerCount(int requested, int count) {
  // hardware_concurrency may report 0 when it cannot tell.
  const int available = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(std::min(available, count), 1, std::max(count, 1));
}

void ParallelFor(int count, int threads, const std::function<void(int)>& body) {
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_failure;
  std::mutex failure_mutex;
  auto work = [&] {
    for (int i = next++; i < count && !failed; i = next++) {
      try {
        body(i);
      } catch (...) {
        const std::lock_guard lock(failure_mutex);
        if (!failed.exchange(true)) first_failure = std::current_exception();
      }
    }
  };
  const int workers = WorkerCount(threads, count);
  {
    std::vector<std::jthread> pool;
    for (int w = 1; w < workers; ++w) {
      try {
        pool.emplace_back(work);
      } catch (const std::system_error&) {
        break;  // no more threads to be had: the ones running do the work, with the same result
      }
    }
    work();  // the calling thread is one of the workers
  }  // jthreads join here
  if (first_failure) std::rethrow_exception(first_failure);
}

}  // namespace stickslip
