// ParallelFor under ThreadSanitizer (built apart, with -fsanitize=thread, from parallel_for.cpp
// alone): the pattern the sweep uses (each item writes its own slot, the caller reads them all
// after the loop) and the failure path (an item throws while others run) must be free of races.
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "stickslip/numerics/parallel_for.hpp"

int main() {
  using stickslip::ParallelFor;
  for (int round = 0; round < 50; ++round) {
    std::vector<std::vector<double>> slots(64);
    ParallelFor(64, 4, [&](int i) { slots[i].assign(100, i * 0.5); });
    for (int i = 0; i < 64; ++i) {
      if (slots[i].size() != 100 || slots[i].back() != i * 0.5) {
        std::fprintf(stderr, "slot %d wrong\n", i);
        return 1;
      }
    }
    std::vector<int> written(64, 0);
    try {
      ParallelFor(64, 4, [&](int i) {
        written[i] = 1;
        if (i == 20) throw std::runtime_error("item 20");
      });
      std::fprintf(stderr, "no exception\n");
      return 1;
    } catch (const std::runtime_error&) {
    }
  }
  std::puts("parallel_for: no race reported");
  return 0;
}
