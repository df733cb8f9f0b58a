#include "test_fault_points.hpp"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>

#include "deferred_signals.hpp"

namespace stickslip::detail {

void PauseBeforeRenameForTests() {
  const char* marker = std::getenv("STICKSLIP_TEST_PAUSE_BEFORE_RENAME");
  if (marker == nullptr || *marker == '\0') return;
  std::ofstream(marker).put('\n');
  using namespace std::chrono_literals;
  const auto until = std::chrono::steady_clock::now() + 60s;
  while (!DeferredSignals::Pending() && std::chrono::steady_clock::now() < until) std::this_thread::sleep_for(10ms);
}

}  // namespace stickslip::detail
