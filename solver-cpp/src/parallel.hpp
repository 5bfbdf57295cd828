// A small persistent thread pool and parallel-for, shared by the solver's loops.
//
// Natively it uses std::thread; compiled by emscripten with -pthread (the threaded wasm module)
// the same code runs on the module's pthread pool (web workers), which must hold at least
// threadCount() - 1 workers: wasm-build/build.sh sizes it from the module option hsPoolSize.
// Without threads (the single-threaded wasm module) every loop runs serially on the caller.
//
// The thread count is 1 (serial) until setThreadCount() raises it. A loop split with forChunks
// gets contiguous chunks [begin, end) in index order, so a caller that writes per-chunk results
// and joins them in chunk order gets output independent of the thread count; sumBlocks does that
// for sums (fixed blocks, added in block order). A parallel loop started from inside a parallel
// loop (or while another thread runs one) runs serially. The caller takes part in its loop and
// never waits for a worker that has not started a task (on a loaded machine it does them all).
//
// Adopting it in a loop over n independent items:
//   hairsketch::parallel::forRange(0, n, 4096, [&](size_t b, size_t e) {
//     for (size_t i = b; i < e; ++i) y[i] = f(x[i]);
//   });
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#if !defined(__EMSCRIPTEN__) || defined(__EMSCRIPTEN_PTHREADS__)
#define HAIRSKETCH_HAS_THREADS 1
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#else
#define HAIRSKETCH_HAS_THREADS 0
#endif

namespace hairsketch {
namespace parallel {

/** The most threads the pool uses (the caller included). */
constexpr int kMaxThreads = 8;

#if HAIRSKETCH_HAS_THREADS

class ThreadPool {
  using Clock = std::chrono::steady_clock;

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
   *  another loop runs. Tasks are claimed one at a time, so the caller does them all itself
   *  when the workers are slow to wake (a loaded machine) and then waits only for tasks a
   *  worker has started, never for a worker that has not woken yet. */
  void run(int tasks, const std::function<void(int)>& task) {
    if (tasks <= 0) return;
    std::unique_lock<std::mutex> run(runMutex_, std::try_to_lock);
    const bool serial = tasks == 1 || workers_.empty() || insideLoop() || !run.owns_lock();
    if (serial || (adaptive_ && serialLoops_ > 0)) {
      if (!serial) --serialLoops_;
      for (int t = 0; t < tasks; ++t) task(t);
      return;
    }
    dispatched_.fetch_add(1, std::memory_order_relaxed);
    const auto t0 = Clock::now();
    // Close first: a late worker of the previous loop may have read the new task count while
    // the state still named the previous loop; its claim must fail (it did not, once: a fourth
    // task of a 3-task loop ran with the old function and the counts never matched).
    const uint64_t gen = ++generation_;
    state_.store((gen << 32) | kClosed);
    task_.store(&task);
    tasks_.store(tasks);
    done_.store(0);
    state_.store(gen << 32);  // open: task 0 is next
    bool sleeping;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      wakeGen_ = gen;
      sleeping = sleepers_ > 0;
    }
    if (sleeping) wake_.notify_all();
    insideLoop() = true;
    double mine = 0;  // seconds the caller spent in its own tasks
    int mineCount = 0;
    work(gen, &mine, &mineCount);
    insideLoop() = false;
    // Tasks still running on workers end soon (chunks are alike): spin for them a while
    // rather than sleep (a sleeping caller is woken tens of microseconds late, more in wasm).
    auto finished = [&] { return done_.load() == tasks; };
    if (!spinUntil(finished, kCallerSpinMicros)) {
      std::unique_lock<std::mutex> lock(mutex_);
      finished_.wait(lock, finished);
    }
    judge(std::chrono::duration<double>(Clock::now() - t0).count(), mine, mineCount, tasks);
  }

  /** Adaptive (default): loops run serially for a while when threads did not pay lately. */
  void setAdaptive(bool on) {
    std::lock_guard<std::mutex> run(runMutex_);
    adaptive_ = on;
    serialLoops_ = 0;
  }

  /** Loops handed to the workers so far (tests: did a loop really run in parallel?). */
  unsigned long long dispatched() const { return dispatched_.load(std::memory_order_relaxed); }

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

  // Claims and runs tasks of loop `gen` until none is left. state_ holds the loop's generation
  // (high 32 bits) and its next unclaimed task (low 32): a claim is a compare-and-swap on both,
  // so a late worker can never take a task of a newer loop with the older loop's function.
  // (All of state_, task_, tasks_ and done_ use sequentially consistent operations: a worker
  // that sees the next loop's task count sees its closed state too.)
  // The caller passes busy/count: the time it spent in its own tasks, and how many it ran.
  void work(uint64_t gen, double* busy = nullptr, int* count = nullptr) {
    uint64_t s = state_.load();
    for (;;) {
      if ((s >> 32) != gen) return;
      const int tasks = tasks_.load();
      const uint32_t t = uint32_t(s);
      if (t >= uint32_t(tasks)) return;                       // all claimed, or closed
      if (!state_.compare_exchange_weak(s, s + 1)) continue;  // s reloaded
      if (busy) {
        const auto t0 = Clock::now();
        (*task_.load())(int(t));
        *busy += std::chrono::duration<double>(Clock::now() - t0).count();
        ++*count;
      } else {
        (*task_.load())(int(t));
      }
      if (done_.fetch_add(1) + 1 == tasks) {
        std::lock_guard<std::mutex> lock(mutex_);
        finished_.notify_all();
      }
      s = state_.load();
    }
  }

  // Did threads pay? A loop's serial time is estimated as its task count times the caller's
  // mean task time (chunks are alike); over a window of kWindow dispatched loops, when the loops
  // took more than 1 / kMinGain of their serial estimate, the next kSerialLoops loops run
  // serially, then threads are tried again. On a machine whose other cores are busy (here: a
  // shared 2-core machine under a load of 3-5, or a page drawing on a software rasteriser) a
  // worker that wakes late or shares a core made the 250K solve 15-20 % slower than serial;
  // when the cores are free the loops run 1.5-1.9x faster and stay parallel. Serial or
  // parallel, every loop gives the same bits.
  void judge(double loop, double mine, int mineCount, int tasks) {
    if (!adaptive_ || mineCount == 0) return;
    windowSerial_ += mine / mineCount * tasks;
    windowLoop_ += loop;
    if (++windowLoops_ < kWindow) return;
    if (windowSerial_ < kMinGain * windowLoop_) serialLoops_ = kSerialLoops;
    windowSerial_ = windowLoop_ = 0;
    windowLoops_ = 0;
  }

  // Busy-waits until pred() or `micros` have passed; returns pred().
  template <class P>
  static bool spinUntil(P&& pred, double micros) {
    const auto t0 = std::chrono::steady_clock::now();
    for (unsigned k = 1;; ++k) {
      if (pred()) return true;
      if (k % 64 == 0 &&
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() >
              micros)
        return pred();
    }
  }

  // A worker sleeps on wake_ between loops. (Spinning a while first, as OpenMP runtimes do, gained
  // little here at low load and, on this shared 2-core machine under a load of 5-6, made the 50K
  // solve 10-60 % slower with 2 threads: the spinning worker takes the core the caller needs.)
  void workerLoop() {
    insideLoop() = true;
    uint64_t seen = 0;
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(mutex_);
        ++sleepers_;
        wake_.wait(lock, [&] { return stop_ || wakeGen_ != seen; });
        --sleepers_;
        if (stop_) return;
        seen = wakeGen_;
      }
      work(seen);
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
  std::condition_variable wake_, finished_;
  std::vector<std::thread> workers_;
  std::atomic<const std::function<void(int)>*> task_{nullptr};
  std::atomic<int> tasks_{0};
  std::atomic<int> done_{0};
  std::atomic<uint64_t> state_{0};  // generation << 32 | next task (kClosed: being set up)
  static constexpr uint64_t kClosed = 0xffffffffu;
  std::atomic<unsigned long long> dispatched_{0};
  uint64_t generation_ = 0;  // the caller's (under runMutex_)
  uint64_t wakeGen_ = 0;     // the newest loop, for sleeping workers (under mutex_)
  int sleepers_ = 0;         // workers waiting on wake_ (under mutex_)
  bool stop_ = false;
  // How long the caller spins for the workers' last tasks before it sleeps: at low load a loop's
  // end comes sooner than a sleep and wake-up would take (the solves of npm run bench:threads);
  // under heavy load it costs nothing measurable.
  static constexpr double kCallerSpinMicros = 1000;
  // The adaptive switch (judge), all under runMutex_.
  static constexpr int kWindow = 64, kSerialLoops = 1024;
  static constexpr double kMinGain = 1.1;
  bool adaptive_ = true;
  int serialLoops_ = 0, windowLoops_ = 0;
  double windowSerial_ = 0, windowLoop_ = 0;
};

inline int threadCount() { return ThreadPool::instance().size(); }
inline int setThreadCount(int n) { return ThreadPool::instance().resize(n); }
inline void runTasks(int tasks, const std::function<void(int)>& task) {
  ThreadPool::instance().run(tasks, task);
}
/** Loops that ran on the pool's workers so far (not those run serially). */
inline unsigned long long dispatchedLoops() { return ThreadPool::instance().dispatched(); }
/** Adaptive (default): loops run serially for a while when threads have not paid lately (tests
 *  turn it off to know that their loops are handed to the workers). */
inline void setAdaptive(bool on) { ThreadPool::instance().setAdaptive(on); }

#else  // single-threaded wasm: everything serial

inline int threadCount() { return 1; }
inline int setThreadCount(int) { return 1; }
inline void runTasks(int tasks, const std::function<void(int)>& task) {
  for (int t = 0; t < tasks; ++t) task(t);
}
inline unsigned long long dispatchedLoops() { return 0; }
inline void setAdaptive(bool) {}

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

/** fn(b, e) over [begin, end) in chunks of at least `grain` items, at most one chunk per
 *  thread. Serial (one call) when the range is small or threads are off. */
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

/** Ordered reduction: fn(b, e) returns K partial sums over items [b, e); [0, n) is cut into
 *  fixed blocks of `block` items (independent of the thread count), the blocks are summed in
 *  parallel (groups of at least `grainBlocks` blocks per thread) and their sums added in block
 *  order, so the result has the same bits with any thread count. */
template <size_t K, class F>
std::array<double, K> sumBlocks(size_t n, size_t block, size_t grainBlocks, F&& fn) {
  std::array<double, K> total{};
  if (n == 0) return total;
  block = std::max<size_t>(block, 1);
  const size_t blocks = (n + block - 1) / block;
  std::vector<std::array<double, K>> part(blocks);
  forRange(0, blocks, grainBlocks, [&](size_t b, size_t e) {
    for (size_t k = b; k < e; ++k) part[k] = fn(k * block, std::min(n, (k + 1) * block));
  });
  for (const std::array<double, K>& p : part)
    for (size_t c = 0; c < K; ++c) total[c] += p[c];
  return total;
}

}  // namespace parallel
}  // namespace hairsketch
