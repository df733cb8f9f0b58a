// libFuzzer target: the run-file reader must turn any input into a RunFile or a RunFileError,
// never crash, abort or read out of bounds (Debian's toml++ 3.3.0 does on some inputs without
// the reader's guards).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "stickslip/io/run_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    stickslip::ParseRunFile(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml");
  } catch (const stickslip::RunFileError&) {
  }
  return 0;
}
