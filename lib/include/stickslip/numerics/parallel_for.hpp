// A minimal work-sharing loop over independent items, on std::thread.
#pragma once

#include <functional>

namespace stickslip {

// The number of threads ParallelFor uses for `requested` (0: every hardware thread) and `count`
// items: never more threads than items, at least one.
int WorkerCount(int requested, int count);

// Calls body(i) once for every i in [0, count), on WorkerCount(threads, count) threads, which
// take the next index from a shared counter. body must write its result only to a slot of its
// own index, so the outcome does not depend on the number of threads. If a call throws, no new
// item is started and the first exception (in time) is rethrown once every thread has stopped.
// When the system refuses a thread, the threads already running share the work.
void ParallelFor(int count, int threads, const std::function<void(int)>& body);

}  // namespace stickslip
