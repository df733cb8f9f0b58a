// Output files appear whole or not at all: written to a temporary name beside the target and
// renamed over it, so a failed run never leaves a half-written or truncated file.
#pragma once

#include <filesystem>
#include <string_view>

namespace stickslip {

// Writes `content` to `path` atomically (same directory, then rename). Throws
// std::runtime_error naming the path if the directory is missing or the write fails; the
// target is then untouched.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view content);

}  // namespace stickslip
