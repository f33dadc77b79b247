// The parallel loops of the CPU code: tbb::parallel_for, plus, in ThreadSanitizer builds, the
// fork/join edges TBB creates inside libtbb. libtbb is not instrumented, so TSan cannot see that
// the caller's writes happen before every task and every task before parallelFor returns; without
// the edges it reports every buffer a loop writes and the next one reads. With them, what TSan
// still reports between the tasks of one loop is a real race in voxgi (or TBB's own bookkeeping,
// tests/sanitizers/tsan.supp).
#pragma once

#include <tbb/parallel_for.h>

#if defined(__SANITIZE_THREAD__)
extern "C" void __tsan_acquire(void* addr);
extern "C" void __tsan_release(void* addr);
#endif

namespace voxgi {

namespace parallel_detail {

// The happens-before edges of one loop, on the addresses of two locals of the caller: fork()
// just before the loop starts, join when it has returned.
struct ForkJoin {
#if defined(__SANITIZE_THREAD__)
  char forked = 0, joined = 0;
  void fork() {
    __tsan_release(&forked);
  }
  void taskBegins() {
    __tsan_acquire(&forked);
  }
  void taskEnds() {
    __tsan_release(&joined);
  }
  ~ForkJoin() {
    __tsan_acquire(&joined);
  }
#else
  void fork() {}
  void taskBegins() {}
  void taskEnds() {}
#endif
};

}  // namespace parallel_detail

// tbb::parallel_for(range, body) with body(const Range&).
template <class Range, class Body>
void parallelFor(const Range& range, const Body& body) {
  parallel_detail::ForkJoin edges;
  const auto task = [&](const Range& r) {
    edges.taskBegins();
    body(r);
    edges.taskEnds();
  };
  edges.fork();
  tbb::parallel_for(range, task);
}

// tbb::parallel_for(first, last, body) with body(Index) for each index.
template <class Index, class Body>
void parallelFor(Index first, Index last, const Body& body) {
  parallel_detail::ForkJoin edges;
  const auto task = [&](Index i) {
    edges.taskBegins();
    body(i);
    edges.taskEnds();
  };
  edges.fork();
  tbb::parallel_for(first, last, task);
}

}  // namespace voxgi
