// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Ordered parallel loops on oneTBB (issue 28, item 4). The solves run independent pieces of
// work (the chart and placement combinations of a scene, the branches of a solution plan) in
// parallel and merge what they found in the order a sequential run visits them, so that the
// answer is the same, in the same order, with any number of threads. Without oneTBB
// (CGAL_LINKED_WITH_TBB not defined) every loop runs on the calling thread.

#ifndef CGAL_RIGID_INCIDENCE_INTERNAL_PARALLEL_H
#define CGAL_RIGID_INCIDENCE_INTERNAL_PARALLEL_H

#include <CGAL/FPU.h>
#include <cstddef>
#include <exception>
#include <memory>
#include <vector>

#ifdef CGAL_USE_MPFI
#include <CGAL/Gmpfi.h>
#endif
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Rigid_incidence {
namespace internal {

/// true if the package was built with oneTBB (loops may run on several threads)
inline constexpr bool parallel_available()
{
#ifdef CGAL_LINKED_WITH_TBB
  return true;
#else
  return false;
#endif
}

/// The threads a solve asking for `requested` uses: 0 means every core of the machine, and
/// never more than the cores oneTBB may use (its default concurrency: it runs no more workers);
/// 1 without oneTBB.
inline unsigned worker_threads(unsigned requested)
{
#ifdef CGAL_LINKED_WITH_TBB
  const int cores = tbb::info::default_concurrency();
  const unsigned most = cores < 1 ? 1u : unsigned(cores);
  return requested == 0 || requested > most ? most : requested;
#else
  (void)requested;
  return 1;
#endif
}

// The state of the calling thread a piece of work must see on a worker thread: the FPU
// rounding mode (CGAL::Interval_nt needs it upward; a Protector is per thread) and the
// default precision of CGAL::Gmpfi (thread_local in CGAL 5.5: a worker starts at 53 bits).
struct Thread_context
{
  CGAL::FPU_CW_t rounding = CGAL::FPU_get_cw();
#ifdef CGAL_USE_MPFI
  CGAL::Gmpfi::Precision_type gmpfi_precision = CGAL::Gmpfi::get_default_precision();
#endif
};

// Sets a context on the current thread for its lifetime, and restores the thread's own.
class Thread_context_guard
{
 public:
  explicit Thread_context_guard(const Thread_context& c)
      : rounding_(CGAL::FPU_get_and_set_cw(c.rounding))
#ifdef CGAL_USE_MPFI
        , gmpfi_precision_(CGAL::Gmpfi::set_default_precision(c.gmpfi_precision))
#endif
  {
  }
  ~Thread_context_guard()
  {
#ifdef CGAL_USE_MPFI
    CGAL::Gmpfi::set_default_precision(gmpfi_precision_);
#endif
    CGAL::FPU_set_cw(rounding_);
  }
  Thread_context_guard(const Thread_context_guard&) = delete;
  Thread_context_guard& operator=(const Thread_context_guard&) = delete;

 private:
  CGAL::FPU_CW_t rounding_;
#ifdef CGAL_USE_MPFI
  CGAL::Gmpfi::Precision_type gmpfi_precision_;
#endif
};

#ifdef CGAL_LINKED_WITH_TBB
// inside a loop of parallel_for_each_index() or ordered_pipeline() on this thread (a nested
// loop then shares the outer loop's arena, so that the threads never exceed the outer loop's)
inline bool& inside_parallel_loop()
{
  static thread_local bool inside = false;
  return inside;
}
// a piece of a loop on this thread: the caller's context, and nested loops in its arena
class Loop_piece
{
 public:
  explicit Loop_piece(const Thread_context& c) : guard_(c), was_(inside_parallel_loop()) { inside_parallel_loop() = true; }
  ~Loop_piece() { inside_parallel_loop() = was_; }

 private:
  Thread_context_guard guard_;
  bool was_;
};
// runs f in an arena of `threads`, or in the current one inside a loop
template <class F> void in_arena(unsigned threads, const F& f)
{
  if (inside_parallel_loop()) {
    f();
  } else {
    tbb::task_arena arena{static_cast<int>(threads)};
    arena.execute(f);
  }
}
#endif

/*
Calls f(i) for every i in [0, n), on up to `threads` threads (worker_threads() of it), each
call with the caller's Thread_context. f(i) must touch only what belongs to i (its own slot of
a result vector) and const shared data; the caller merges the slots in the order of i. An
exception thrown by f(i) is rethrown once every call has ended: the one of the smallest i
(the one a sequential loop would have met first).
*/
template <class F>
void parallel_for_each_index(std::size_t n, unsigned threads, const F& f)
{
  threads = worker_threads(threads);
  if (n == 0) return;
  if (threads <= 1 || n == 1) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
#ifdef CGAL_LINKED_WITH_TBB
  const Thread_context context;
  std::vector<std::exception_ptr> error(n);
  auto body = [&](const tbb::blocked_range<std::size_t>& range) {
    Loop_piece piece(context);
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      try {
        f(i);
      } catch (...) {
        error[i] = std::current_exception();
      }
    }
  };
  // one index per task: the pieces are coarse (a system built and solved) and uneven
  in_arena(threads, [&] { tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1), body, tbb::simple_partitioner()); });
  for (const auto& e : error)
    if (e) std::rethrow_exception(e);
#else
  for (std::size_t i = 0; i < n; ++i) f(i);
#endif
}

/*
A loop whose pieces come one after the other, work on their own in parallel, and are taken in
their order: `next(item)` fills the next piece (false: there is none, or the loop must stop),
`work(item)` does its work (on any thread, touching only the item and const shared data), and
`take(item)` takes what it found, in the order `next` gave the pieces. `next` and `take` run one
call at a time (on any thread, with the caller's Thread_context). At most `window` pieces are
under way at once (taken as soon as every piece before them is: no batch waits for its slowest
piece). An exception of `work` is rethrown when its piece would be taken; one of `next` or
`take` at once. With one thread: next, work, take, one piece after the other, on this thread.
Item must be default-constructible.
*/
template <class Item, class Next, class Work, class Take>
void ordered_pipeline(unsigned threads, std::size_t window, const Next& next, const Work& work, const Take& take)
{
  threads = worker_threads(threads);
  if (threads <= 1) {
    for (;;) {
      Item item;
      if (!next(item)) return;
      work(item);
      take(item);
    }
  }
#ifdef CGAL_LINKED_WITH_TBB
  struct Slot
  {
    Item item;
    std::exception_ptr error;
  };
  typedef std::shared_ptr<Slot> P;
  const Thread_context context;
  in_arena(threads, [&] {
    tbb::parallel_pipeline(
        window < 1 ? 1 : window,
        tbb::make_filter<void, P>(tbb::filter_mode::serial_in_order,
                                  [&](tbb::flow_control& fc) -> P {
                                    Loop_piece piece(context);
                                    P s = std::make_shared<Slot>();
                                    if (!next(s->item)) {
                                      fc.stop();
                                      return P();
                                    }
                                    return s;
                                  }) &
            tbb::make_filter<P, P>(tbb::filter_mode::parallel,
                                   [&](P s) -> P {
                                     Loop_piece piece(context);
                                     try {
                                       work(s->item);
                                     } catch (...) {
                                       s->error = std::current_exception();
                                     }
                                     return s;
                                   }) &
            tbb::make_filter<P, void>(tbb::filter_mode::serial_in_order, [&](P s) {
              Loop_piece piece(context);
              if (s->error) std::rethrow_exception(s->error);
              take(s->item);
            }));
  });
#endif
}

} // namespace internal
} // namespace Rigid_incidence
} // namespace CGAL

#endif
