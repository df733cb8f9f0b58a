// libFuzzer target: the command line's parsers (tools/number_text.hpp, Signature::Parse) turn any
// text into a value or InvalidInput, never a crash, an abort or another exception; an accepted
// number is what strtod reads from the whole text; an accepted signature reads back from its text
// form as itself. The first byte chooses the parser. tests/cli/command_line_parsing_test.cpp
// checks the same properties on seeded inputs in the unit tests.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "number_text.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/signature.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 3) {
      case 0: {
        const double value = stickslip::cli::ParseNumber("x", text, "a number");
        char* end = nullptr;
        const double expected = std::strtod(text.c_str(), &end);
        if (end != text.c_str() + text.size() || expected != value || !std::isfinite(value)) std::abort();
        break;
      }
      case 1: {
        const int value = stickslip::cli::ParseCount("n", text, 1, 1000000);
        if (value < 1 || value > 1000000 || std::strtod(text.c_str(), nullptr) != value) std::abort();
        break;
      }
      default: {
        const stickslip::Signature signature = stickslip::Signature::Parse(text);
        if (!(stickslip::Signature::Parse(signature.ToString()) == signature)) std::abort();
      }
    }
  } catch (const stickslip::InvalidInput&) {
  }
  return 0;
}
