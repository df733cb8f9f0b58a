// Output files appear whole or not at all: written to a temporary name beside the target and
// renamed over it, so a failed run never leaves a half-written or truncated file.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

namespace stickslip {

// A file written piece by piece and still whole or not at all: the pieces go to a temporary file
// beside the target, which Commit renames over it; a writer destroyed before Commit (an exception,
// an early return) removes the temporary file and leaves the target untouched. For outputs too
// large to hold in memory as one string (a long simulation's time series).
//
//   AtomicFileWriter out("series.csv");   // throws if the directory is missing; follows a link
//   out.Write("t,x1\n");
//   out.Commit();
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(const std::filesystem::path& path);
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;
  ~AtomicFileWriter();

  void Write(std::string_view piece);
  // Flushes, checks every write, and renames the temporary file over the target; throws
  // std::runtime_error naming the path on failure (the target is then untouched).
  void Commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

// Writes `content` to `path` atomically (same directory, then rename). A symbolic link is
// followed: its target is written and the link stays. Throws std::runtime_error naming the
// path if the directory is missing or the write fails; the target is then untouched.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view content);

// Throws InvalidInput naming `field` if WriteFileAtomically(path, ...) is bound to fail, or
// would replace what is not a file: `path` is empty, its directory does not exist or takes no
// new file, or it exists as something other than a regular file (a directory, a device). Front
// ends call it before the work whose result they write.
void CheckOutputFile(const std::filesystem::path& path, const std::string& field);

// Whether a new file can be created in `directory`: found by creating an empty file of our own
// there and removing it again (permissions alone do not tell, for root or on /proc).
std::error_code CanCreateFileIn(const std::filesystem::path& directory);

}  // namespace stickslip
