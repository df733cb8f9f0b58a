// Output files appear whole or not at all: written to a temporary name beside the target and
// renamed over it, so a failed run never leaves a half-written or truncated file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

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
  // Closes the temporary file after checking every write; throws std::runtime_error "cannot write
  // '<target>': <the system's reason>" (ENOSPC: "No space left on device") on failure. Commit
  // calls it; a caller that writes several files calls it on each before committing any.
  void Close();
  // Closes, and renames the temporary file over the target; throws std::runtime_error naming the
  // target and the system's reason on failure (the target is then untouched).
  void Commit();
  // The file written: the target, or a link's target.
  const std::filesystem::path& path() const { return path_; }

 private:
  void Flush();

  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::string buffer_;  // pieces not yet written: one system call per 64 KiB, not per piece
  int fd_ = -1;
  int error_ = 0;  // the first write's errno; 0 while every write succeeded
  bool committed_ = false;
};

// Writes `content` to `path` atomically (same directory, then rename). A symbolic link is
// followed: its target is written and the link stays. Throws std::runtime_error naming the
// path if the directory is missing or the write fails; the target is then untouched.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view content);

// Files that belong together (AUTO's b. and s. files): each written whole to its temporary file
// first, then renamed in order; should a rename fail, the files already renamed are removed, so
// that the set appears whole or not at all (a file they replaced is then gone too). Throws as
// AtomicFileWriter, naming the file that failed.
struct FileContent {
  std::filesystem::path path;
  std::string content;
};
void WriteFilesAtomically(const std::vector<FileContent>& files);

// Throws InvalidInput naming `field` if WriteFileAtomically(path, ...) is bound to fail, or
// would replace what is not a file: `path` is empty, its directory does not exist or takes no
// new file, or it exists as something other than a regular file (a directory, a device). Front
// ends call it before the work whose result they write.
void CheckOutputFile(const std::filesystem::path& path, const std::string& field);

// Whether a new file can be created in `directory`: found by creating an empty file of our own
// there and removing it again (permissions alone do not tell, for root or on /proc).
std::error_code CanCreateFileIn(const std::filesystem::path& directory);

}  // namespace stickslip
