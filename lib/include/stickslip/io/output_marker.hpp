// Which existing file a command's file output may replace: one that this command wrote, known by
// the marker its format already carries on its first line (the exact header of its CSV format,
// the first-line comment of the run file find writes), or one the user names with --force. Any
// other file (a committed run file, the user's data) is refused before the work: nothing is
// written, and no marker line is added to any format.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace stickslip {

struct OutputMarker {
  std::string writer;                                      // "stickslip sweep", as messages name it
  std::function<bool(std::string_view line)> is_marker;   // the file's first line, without '\n'
};

// CheckOutputFile(path, field), and then, where `path` exists and `force` is false, InvalidInput
// "<field> = '<path>' is invalid: it exists and was not written by <writer> (...): valid a new
// file, one <writer> wrote, or --force to replace it" unless its first line is the marker.
void CheckReplaceableOutputFile(const std::filesystem::path& path, const std::string& field, const OutputMarker& marker,
                                bool force);

}  // namespace stickslip
