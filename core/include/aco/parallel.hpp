#pragma once
// tbb::parallel_for, with its fork and join made visible to ThreadSanitizer (the preset tsan).
// Debian's libtbb is not built with ThreadSanitizer, so TSan cannot see how the library hands a
// task to a worker and reports the completion back: every write before a loop would look racy
// with the body's reads on a worker, and every body's writes with the caller's reads after the
// loop. Under TSan the loop therefore states the two orderings parallel_for guarantees, and no
// more: the caller's work before the call happens before every body invocation, and every body
// invocation before the call returns (or throws). Invocations stay unordered among themselves,
// so a race between two of them is still reported. Without TSan this is tbb::parallel_for.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#if defined(__SANITIZE_THREAD__)
#define ACO_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define ACO_THREAD_SANITIZER 1
#endif
#endif

#ifdef ACO_THREAD_SANITIZER
#include <sanitizer/tsan_interface.h>

#include <memory>

// ThreadSanitizer's dynamic annotations (libtsan defines them; no header declares them).
extern "C" void AnnotateIgnoreReadsBegin(const char* file, int line);
extern "C" void AnnotateIgnoreReadsEnd(const char* file, int line);
#endif

namespace aco {

// Calls body(part) for parts of `range` in parallel, like tbb::parallel_for(range, body).
template <class Range, class Body>
void parallel_for(const Range& range, const Body& body) {
#ifdef ACO_THREAD_SANITIZER
  // The tokens are two heap bytes, not locals: TSan forgets what was released at an address
  // when the heap block is freed, never for a stack address, which a later loop would reuse.
  const auto tokens = std::make_unique<char[]>(2);
  struct Release {
    char* token;
    ~Release() { __tsan_release(token); }
  };
  struct Acquire {
    char* token;
    ~Acquire() { __tsan_acquire(token); }
  };
  const auto annotated = [fork = &tokens[0], join = &tokens[1], run = &body](const Range& part) {
    // A worker runs TBB's copy of this closure, in TBB's task memory, written by whichever
    // thread split the work (unseen by TSan, and that memory's earlier use with it). Its three
    // pointers are constants of the loop, so reading them is not checked; the first is needed
    // for the acquire that orders everything else.
    AnnotateIgnoreReadsBegin(__FILE__, __LINE__);
    char* const forked = fork;
    const Release done{join};
    const Body& loop_body = *run;
    AnnotateIgnoreReadsEnd(__FILE__, __LINE__);
    __tsan_acquire(forked);
    loop_body(part);
  };
  // The body must be complete before the release: the empty asm hands the compiler its
  // address, which forbids moving its construction past the (opaque) release call.
  asm volatile("" : : "r"(&body) : "memory");
  __tsan_release(&tokens[0]);
  const Acquire joined{&tokens[1]};
  tbb::parallel_for(range, annotated);
#else
  tbb::parallel_for(range, body);
#endif
}

// Calls function(i) for i in [first, last) in parallel, like tbb::parallel_for(first, last,
// function) (which splits the same range the same way), through the loop above: TBB's own
// index loop would not copy the annotated closure into its tasks but refer to this frame's.
template <class Index, class Function>
void parallel_for(Index first, Index last, const Function& function) {
  aco::parallel_for(tbb::blocked_range<Index>(first, last), [&function](const tbb::blocked_range<Index>& part) {
    for (Index i = part.begin(); i != part.end(); ++i) function(i);
  });
}

}  // namespace aco
