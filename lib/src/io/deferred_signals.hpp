// Internal to io/: SIGINT, SIGTERM and SIGHUP deferred while a writer has a temporary beside its
// target, so that the writer removes it and the process still ends by the signal.
#pragma once

#include <array>
#include <stdexcept>

#include <signal.h>

namespace stickslip::detail {

// Thrown by DeferredSignals::ThrowIfPending: the writers' cleanup runs as it unwinds.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// While one lives, the three signals are only recorded (a handler may call only async-signal-safe
// functions, and removing a directory tree takes more); the writer asks ThrowIfPending where it may
// stop. The outermost one, when destroyed, restores the dispositions it found and raises a recorded
// signal again: with the default one the process ends by it (exit status 128 + signal), after the
// writer's cleanup. A signal the process ignores (nohup's SIGHUP) stays ignored. Nested ones (a
// trace's branches written inside the trace's temporary) only share the record.
class DeferredSignals {
 public:
  DeferredSignals();
  DeferredSignals(const DeferredSignals&) = delete;
  DeferredSignals& operator=(const DeferredSignals&) = delete;
  ~DeferredSignals();

  bool Outermost() const { return outermost_; }
  static bool Pending();
  // Throws Interrupted naming the signal if one was recorded.
  static void ThrowIfPending();

 private:
  bool outermost_;
  std::array<struct sigaction, 3> previous_{};
};

}  // namespace stickslip::detail
