#include "deferred_signals.hpp"

#include <atomic>
#include <csignal>
#include <cstring>

#include <fmt/format.h>

namespace stickslip::detail {

namespace {

constexpr std::array<int, 3> kDeferred = {SIGINT, SIGTERM, SIGHUP};

volatile std::sig_atomic_t received = 0;
std::atomic<int> depth{0};

extern "C" void RecordSignal(int signal) { received = signal; }

}  // namespace

DeferredSignals::DeferredSignals() : outermost_(depth.fetch_add(1) == 0) {
  if (!outermost_) return;
  received = 0;
  struct sigaction record {};
  record.sa_handler = RecordSignal;
  sigemptyset(&record.sa_mask);
  record.sa_flags = SA_RESTART;  // the writes go on; the writer stops where it checks
  for (std::size_t k = 0; k < kDeferred.size(); ++k) {
    ::sigaction(kDeferred[k], &record, &previous_[k]);
    if (!(previous_[k].sa_flags & SA_SIGINFO) && previous_[k].sa_handler == SIG_IGN) {
      ::sigaction(kDeferred[k], &previous_[k], nullptr);
    }
  }
}

DeferredSignals::~DeferredSignals() {
  depth.fetch_sub(1);
  if (!outermost_) return;
  for (std::size_t k = 0; k < kDeferred.size(); ++k) ::sigaction(kDeferred[k], &previous_[k], nullptr);
  if (const int signal = received; signal != 0) {
    received = 0;
    std::raise(signal);
  }
}

bool DeferredSignals::Pending() { return received != 0; }

void DeferredSignals::ThrowIfPending() {
  if (const int signal = received; signal != 0) {
    throw Interrupted(fmt::format("interrupted by signal {} ({})", signal, ::strsignal(signal)));
  }
}

}  // namespace stickslip::detail
