// A 64-bit FNV-1a hash over whole numbers and the bits of doubles, byte by byte from the least
// significant: the same on every platform, so that the shards of one run, computed anywhere, carry
// one fingerprint (brute-force maps).
#pragma once

#include <bit>
#include <cstdint>
#include <string_view>

namespace stickslip {

class Fingerprint {
 public:
  void Add(std::uint64_t value) {
    for (int byte = 0; byte < 8; ++byte) hash_ = (hash_ ^ ((value >> (8 * byte)) & 0xffu)) * 1099511628211ull;
  }
  void AddNumber(double value) { Add(std::bit_cast<std::uint64_t>(value)); }
  // Its length first, so that ("ab", "c") and ("a", "bc") differ.
  void AddText(std::string_view text) {
    Add(text.size());
    for (const char c : text) Add(static_cast<unsigned char>(c));
  }
  std::uint64_t Value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace stickslip
