#include "stickslip/io/output_marker.hpp"

#include <fstream>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/atomic_file.hpp"

namespace stickslip {

namespace {

// The first line, read up to a bound: a marker is short, and a huge file without a newline (or a
// binary one) must not be read whole only to be refused.
std::string FirstLine(const std::filesystem::path& path) {
  constexpr std::streamsize kLongestMarker = 4096;
  std::ifstream in(path, std::ios::binary);
  std::string line(kLongestMarker, '\0');
  in.read(line.data(), kLongestMarker);
  line.resize(static_cast<std::size_t>(in.gcount()));
  const std::size_t end = line.find('\n');
  return end == std::string::npos ? std::string() : line.substr(0, end);
}

}  // namespace

void CheckReplaceableOutputFile(const std::filesystem::path& path, const std::string& field, const OutputMarker& marker,
                                bool force) {
  CheckOutputFile(path, field);
  std::error_code error;
  if (force || !std::filesystem::exists(path, error)) return;
  if (marker.is_marker(FirstLine(path))) return;
  throw InvalidInput::WithMessage(
      field, fmt::format("{} = '{}' is invalid: it exists and was not written by {} (its first line is not {}'s): valid "
                         "a new file, one {} wrote, or --force to replace it",
                         field, path.string(), marker.writer, marker.writer, marker.writer));
}

}  // namespace stickslip
