#include "stickslip/io/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>
#include <fcntl.h>
#include <unistd.h>

#include "deferred_signals.hpp"
#include "stale_temporaries.hpp"
#include "stickslip/invalid_input.hpp"
#include "temporary_name.hpp"
#include "test_fault_points.hpp"

namespace stickslip {

namespace {

// The name the file is written under first, beside its target (the host and process keep
// concurrent writers of the same target apart, and tell a later run whose it is).
std::string TemporaryName(const std::filesystem::path& target) {
  return detail::TemporaryName(target.filename().string(), "tmp");
}

// The user's path and the system's reason, never the temporary name (which the user never sees).
std::runtime_error CannotWrite(const std::filesystem::path& path, int error) {
  return std::runtime_error(
      fmt::format("cannot write '{}': {}", path.string(), std::generic_category().message(error)));
}

}  // namespace

// A symbolic link is followed: its target is written and the link stays.
AtomicFileWriter::AtomicFileWriter(const std::filesystem::path& link_or_path) {
  namespace fs = std::filesystem;
  std::error_code not_a_link;
  path_ = fs::is_symlink(link_or_path, not_a_link) ? fs::weakly_canonical(link_or_path) : link_or_path;
  const fs::path directory = path_.has_parent_path() ? path_.parent_path() : fs::path(".");
  if (!fs::is_directory(directory)) {
    throw std::runtime_error(
        fmt::format("cannot write '{}': directory '{}' does not exist", path_.string(),
                    directory.string()));
  }
  detail::RemoveStaleFileTemporaries(path_);  // a killed writer's, provably dead; the others listed
  temporary_ = directory / TemporaryName(path_);
  // Exclusive and never through a link: a file planted at the (predictable) temporary name is not
  // the run's to truncate or to rename over the output.
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd_ < 0 && (errno == EEXIST || errno == ELOOP)) {
    throw std::runtime_error(fmt::format("cannot write '{}': '{}' is in the way (not this run's: remove it)",
                                         path_.string(), temporary_.filename().string()));
  }
  if (fd_ < 0) throw CannotWrite(path_, errno);
}

AtomicFileWriter::~AtomicFileWriter() {
  if (committed_) return;
  if (fd_ >= 0) ::close(fd_);
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFileWriter::Write(std::string_view piece) {
  constexpr std::size_t kBuffered = 64 * 1024;
  buffer_.append(piece);
  if (buffer_.size() >= kBuffered) Flush();
}

void AtomicFileWriter::Flush() {
  // After a failure the rest is dropped: Close reports the first error.
  std::string_view rest = buffer_;
  while (!rest.empty() && error_ == 0 && fd_ >= 0) {
    const ssize_t written = ::write(fd_, rest.data(), rest.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) {
      error_ = errno;
    } else {
      rest.remove_prefix(static_cast<std::size_t>(written));
    }
  }
  buffer_.clear();
}

void AtomicFileWriter::Close() {
  Flush();
  // A file system may report a full disk only when the file is closed (NFS).
  if (fd_ >= 0 && ::close(fd_) != 0 && error_ == 0) error_ = errno;
  fd_ = -1;
  if (error_ != 0) throw CannotWrite(path_, error_);
}

void AtomicFileWriter::Commit() {
  Close();
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) throw CannotWrite(path_, errno);
  committed_ = true;
}

void WriteFileAtomically(const std::filesystem::path& path, std::string_view content) {
  // Declared first, destroyed last: a signal during the write removes the temporary file, then ends
  // the process (deferred_signals.hpp).
  const detail::DeferredSignals signals;
  AtomicFileWriter out(path);
  out.Write(content);
  out.Close();
  if (signals.Outermost()) detail::PauseBeforeRenameForTests();
  detail::DeferredSignals::ThrowIfPending();
  out.Commit();
}

void WriteFilesAtomically(const std::vector<FileContent>& files) {
  const detail::DeferredSignals signals;  // as in WriteFileAtomically
  std::vector<std::unique_ptr<AtomicFileWriter>> writers;
  for (const FileContent& file : files) {
    writers.push_back(std::make_unique<AtomicFileWriter>(file.path));
    writers.back()->Write(file.content);
    writers.back()->Close();
  }
  if (signals.Outermost()) detail::PauseBeforeRenameForTests();
  detail::DeferredSignals::ThrowIfPending();
  for (std::size_t k = 0; k < writers.size(); ++k) {
    try {
      writers[k]->Commit();
    } catch (const std::runtime_error&) {
      std::error_code ignored;
      for (std::size_t j = 0; j < k; ++j) std::filesystem::remove(writers[j]->path(), ignored);
      throw;
    }
  }
}

void CheckOutputFile(const std::filesystem::path& path, const std::string& field) {
  namespace fs = std::filesystem;
  auto refuse = [&](const std::string& why) {
    return InvalidInput::WithMessage(field, fmt::format("{} = '{}' is invalid: {}: valid a file in an existing directory",
                                                        field, path.string(), why));
  };
  if (path.empty()) throw refuse("it is empty");
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (status.type() == fs::file_type::none) throw refuse(fmt::format("it cannot be examined ({})", error.message()));
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw refuse(fs::is_directory(status) ? "it is a directory" : "it is not a file");
  }
  // The file is written beside its target (a link's target: WriteFileAtomically follows links).
  const fs::path target = fs::is_symlink(path, error) ? fs::weakly_canonical(path) : path;
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(directory, error)) throw refuse(fmt::format("directory '{}' does not exist", directory.string()));
  if (const std::error_code failed = CanCreateFileIn(directory)) {
    throw refuse(fmt::format("no file can be created in directory '{}' ({})", directory.string(), failed.message()));
  }
  // A name the directory takes whose temporary name (longer) it would refuse only after the work.
  const long name_max = ::pathconf(directory.c_str(), _PC_NAME_MAX);
  if (const std::string temporary = TemporaryName(target); name_max > 0 && static_cast<long>(temporary.size()) > name_max) {
    throw refuse(fmt::format("its name is too long to be written as '{}' first ({} bytes, more than the {} the directory "
                             "allows)", temporary, temporary.size(), name_max));
  }
}

std::error_code CanCreateFileIn(const std::filesystem::path& directory) {
  const std::filesystem::path probe = directory / fmt::format(".stickslip.probe.{}", static_cast<long>(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) return {errno, std::generic_category()};
  ::close(fd);
  ::unlink(probe.c_str());
  return {};
}

}  // namespace stickslip
