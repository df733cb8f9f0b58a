#include "stale_temporaries.hpp"

#include <algorithm>
#include <cerrno>
#include <limits>
#include <optional>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <signal.h>

#include "temporary_name.hpp"

namespace stickslip::detail {

namespace fs = std::filesystem;

namespace {

// Why the temporary cannot be proven dead, or nullopt where it can.
std::optional<std::string> WhyAlive(const TemporaryWriter& writer) {
  if (writer.tag.empty()) return "its name does not say its host (an earlier version of stickslip wrote it)";
  if (writer.tag != ThisHostTag()) return "written on another host or before this host's last boot";
  if (!HasBootId()) return "this system has no boot id to tell a reused process id";
  // kill() takes a pid_t: 4294967296 would ask about process 0 (this process group).
  if (writer.pid <= 0 || writer.pid > std::numeric_limits<pid_t>::max()) {
    return fmt::format("{} is no process id of this system: no stickslip process wrote it", writer.pid);
  }
  if (::kill(static_cast<pid_t>(writer.pid), 0) == 0 || errno != ESRCH) {
    return fmt::format("its process {} is running", writer.pid);
  }
  return std::nullopt;
}

// Removes below root/relative what the dead writer made: the entries of ours, and its own
// temporaries (which never receive the user's files); the user's stay.
void RemoveWritten(const fs::path& root, const fs::path& relative, const OwnedEntry& ours, const TemporaryWriter& writer) {
  std::error_code ignored;
  fs::directory_iterator listing(root / relative, ignored);
  const std::vector<fs::directory_entry> entries(begin(listing), end(listing));
  for (const fs::directory_entry& entry : entries) {
    const fs::path name = relative / entry.path().filename();
    if (IsTemporaryOf(entry.path().filename().string(), writer)) {
      fs::remove_all(entry.path(), ignored);
    } else if (ours(name)) {
      if (entry.is_directory(ignored) && !entry.is_symlink(ignored)) RemoveWritten(root, name, ours, writer);
      fs::remove(entry.path(), ignored);  // a directory that holds the user's files stays
    }
  }
}

// The line that says what became of one temporary.
std::string Clean(const fs::path& temporary, const TemporaryWriter& writer, const OwnedEntry& ours) {
  if (const std::optional<std::string> why = WhyAlive(writer)) {
    return fmt::format("note: left '{}': {}", temporary.string(), *why);
  }
  RemoveWritten(temporary, {}, ours, writer);
  std::error_code ignored;
  fs::remove(temporary, ignored);
  if (fs::exists(fs::symlink_status(temporary, ignored))) {
    return fmt::format("note: left '{}': its process {} has ended, but it holds files stickslip did not write",
                       temporary.string(), writer.pid);
  }
  return fmt::format("note: removed '{}': a temporary of process {} on this host, which has ended", temporary.string(),
                     writer.pid);
}

}  // namespace

void RemoveStaleTemporaries(const fs::path& results_root, const std::string& output, const OwnedEntry& ours) {
  std::error_code ignored;
  std::vector<std::pair<fs::path, TemporaryWriter>> found;
  for (const fs::directory_entry& entry : fs::directory_iterator(results_root, ignored)) {
    const std::optional<TemporaryWriter> writer = WriterOf(entry.path().filename().string(), output, "tmp");
    if (writer && entry.is_directory(ignored) && !entry.is_symlink(ignored)) found.emplace_back(entry.path(), *writer);
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [temporary, writer] : found) fmt::print(stderr, "{}\n", Clean(temporary, writer, ours));
}

void RemoveStaleFileTemporaries(const fs::path& target) {
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ignored;
  std::vector<std::pair<fs::path, TemporaryWriter>> found;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, ignored)) {
    const std::optional<TemporaryWriter> writer = WriterOf(entry.path().filename().string(), target.filename().string(), "tmp");
    if (writer && entry.is_regular_file(ignored) && !entry.is_symlink(ignored)) found.emplace_back(entry.path(), *writer);
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [temporary, writer] : found) {
    if (const std::optional<std::string> why = WhyAlive(writer)) {
      fmt::print(stderr, "note: left '{}': {}\n", temporary.string(), *why);
    } else if (fs::remove(temporary, ignored)) {
      fmt::print(stderr, "note: removed '{}': a temporary of process {} on this host, which has ended\n",
                 temporary.string(), writer.pid);
    }
  }
}

}  // namespace stickslip::detail
