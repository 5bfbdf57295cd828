// A small persistent thread pool and parallel-for, shared by the solver's loops.
//
// Natively it uses std::thread; compiled by emscripten with -pthread (the threaded wasm module)
// the same code runs on the module's pthread pool (web workers), which must hold at least
// threadCount() - 1 workers: wasm-build/build.sh sizes it from the module option hsPoolSize.
// Without threads (the single-threaded wasm module) every loop runs serially on the caller.
//
// The thread count is 1 (serial) until setThreadCount() raises it. A loop split with forChunks
// gets contiguous chunks [begin, end) in index order, so a caller that writes per-chunk results
// and joins them in chunk order gets output independent of the thread count. A parallel loop
// started from inside a parallel loop (or while another thread runs one) runs serially.
//
// Adopting it in a loop over n independent items:
//   hairsketch::parallel::forRange(0, n, 4096, [&](size_t b, size_t e) {
//     for (size_t i = b; i < e; ++i) y[i] = f(x[i]);
//   });
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>

#if !defined(__EMSCRIPTEN__) || defined(__EMSCRIPTEN_PTHREADS__)
#define HAIRSKETCH_HAS_THREADS 1
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>
#else
#define HAIRSKETCH_HAS_THREADS 0
#endif

namespace hairsketch {
namespace parallel {

/** The most threads the pool uses (the caller included). */
constexpr int kMaxThreads = 8;

#if HAIRSKETCH_HAS_THREADS

class ThreadPool {
 public:
  static ThreadPool& instance() {
    static ThreadPool pool;
    return pool;
  }

  /** Threads taking part in a loop, the caller included (1 = serial). */
  int size() const { return int(workers_.size()) + 1; }

  /** Sets the number of threads (clamped to [1, kMaxThreads]); returns it. Not from inside a
   *  loop. Workers are started (or stopped) here, never during a loop. */
  int resize(int n) {
    n = std::max(1, std::min(kMaxThreads, n));
    std::lock_guard<std::mutex> run(runMutex_);
    stopWorkers();
    stop_ = false;
    for (int w = 0; w + 1 < n; ++w) workers_.emplace_back([this] { workerLoop(); });
    return size();
  }

  /** Runs task(0) … task(tasks - 1), each once, on the pool and the caller; returns when all
   *  are done. Serial when the pool has one thread, when called from a pool thread or while
   *  another loop runs. */
  void run(int tasks, const std::function<void(int)>& task) {
    if (tasks <= 0) return;
    std::unique_lock<std::mutex> run(runMutex_, std::try_to_lock);
    if (tasks == 1 || workers_.empty() || insideLoop() || !run.owns_lock()) {
      for (int t = 0; t < tasks; ++t) task(t);
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      task_ = &task;
      tasks_ = tasks;
      next_.store(0);
      busy_ = int(workers_.size());
      ++generation_;
    }
    wake_.notify_all();
    insideLoop() = true;
    work();
    insideLoop() = false;
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return busy_ == 0; });
    task_ = nullptr;
  }

  ~ThreadPool() {
    std::lock_guard<std::mutex> run(runMutex_);
    stopWorkers();
  }

 private:
  ThreadPool() = default;

  static bool& insideLoop() {
    static thread_local bool inside = false;
    return inside;
  }

  void work() {
    for (int t = next_.fetch_add(1); t < tasks_; t = next_.fetch_add(1)) (*task_)(t);
  }

  void workerLoop() {
    insideLoop() = true;
    unsigned long long seen = 0;
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
        if (stop_) return;
        seen = generation_;
      }
      work();
      std::lock_guard<std::mutex> lock(mutex_);
      if (--busy_ == 0) done_.notify_one();
    }
  }

  void stopWorkers() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
    workers_.clear();
  }

  std::mutex runMutex_;  // one loop at a time
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
  const std::function<void(int)>* task_ = nullptr;
  int tasks_ = 0;
  std::atomic<int> next_{0};
  int busy_ = 0;
  unsigned long long generation_ = 0;
  bool stop_ = false;
};

inline int threadCount() { return ThreadPool::instance().size(); }
inline int setThreadCount(int n) { return ThreadPool::instance().resize(n); }
inline void runTasks(int tasks, const std::function<void(int)>& task) {
  ThreadPool::instance().run(tasks, task);
}

#else  // single-threaded wasm: everything serial

inline int threadCount() { return 1; }
inline int setThreadCount(int) { return 1; }
inline void runTasks(int tasks, const std::function<void(int)>& task) {
  for (int t = 0; t < tasks; ++t) task(t);
}

#endif

/** Splits [0, n) into `chunks` contiguous ranges of near-equal size and runs
 *  fn(chunk, begin, end) for each (in parallel when the pool has threads). */
template <class F>
void forChunks(size_t n, int chunks, F&& fn) {
  chunks = int(std::max<size_t>(1, std::min<size_t>(size_t(std::max(chunks, 1)), n)));
  runTasks(chunks, [&](int c) {
    const size_t b = n * size_t(c) / size_t(chunks), e = n * size_t(c + 1) / size_t(chunks);
    fn(c, b, e);
  });
}

/** fn(b, e) over [begin, end) in chunks of at least `grain` items, one chunk per thread at
 *  most 4 per thread (balance). Serial (one call) when the range is small or threads are off. */
template <class F>
void forRange(size_t begin, size_t end, size_t grain, F&& fn) {
  if (end <= begin) return;
  const size_t n = end - begin;
  const int threads = threadCount();
  const size_t byGrain = std::max<size_t>(1, n / std::max<size_t>(grain, 1));
  const int chunks = int(std::min<size_t>(byGrain, size_t(threads)));
  if (chunks <= 1) {
    fn(begin, end);
    return;
  }
  forChunks(n, chunks, [&](int, size_t b, size_t e) { fn(begin + b, begin + e); });
}

}  // namespace parallel
}  // namespace hairsketch
