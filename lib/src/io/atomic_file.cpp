#include "stickslip/io/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>
#include <fcntl.h>
#include <unistd.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace {

// The name the file is written under first, beside its target (the process id keeps concurrent
// writers of the same target apart).
std::string TemporaryName(const std::filesystem::path& target) {
  return fmt::format(".{}.tmp.{}", target.filename().string(), static_cast<long>(::getpid()));
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
  temporary_ = directory / TemporaryName(path_);
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error(fmt::format("cannot write '{}'", temporary_.string()));
}

AtomicFileWriter::~AtomicFileWriter() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFileWriter::Write(std::string_view piece) {
  out_.write(piece.data(), static_cast<std::streamsize>(piece.size()));
}

void AtomicFileWriter::Commit() {
  namespace fs = std::filesystem;
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || out_.fail()) throw std::runtime_error(fmt::format("cannot write '{}'", temporary_.string()));
  std::error_code error;
  fs::rename(temporary_, path_, error);
  if (error) {
    throw std::runtime_error(
        fmt::format("cannot rename '{}' to '{}': {}", temporary_.string(), path_.string(),
                    error.message()));
  }
  committed_ = true;
}

void WriteFileAtomically(const std::filesystem::path& path, std::string_view content) {
  AtomicFileWriter out(path);
  out.Write(content);
  out.Commit();
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
