#include "temporary_name.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>

#include <fmt/format.h>
#include <unistd.h>

namespace stickslip::detail {

namespace {

constexpr std::size_t kTagDigits = 16;

std::string BootId() {
  std::ifstream in("/proc/sys/kernel/random/boot_id");
  std::string id;
  std::getline(in, id);
  return id;
}

std::string HostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return {};
  return name;
}

bool IsDigits(std::string_view text, std::size_t max) {
  return !text.empty() && text.size() <= max && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool IsTag(std::string_view text) {
  return text.size() == kTagDigits &&
         std::all_of(text.begin(), text.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

}  // namespace

const std::string& ThisHostTag() {
  static const std::string tag = [] {
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (const unsigned char c : HostName() + '\n' + BootId()) {
      hash ^= c;
      hash *= 0x100000001b3ULL;
    }
    return fmt::format("{:016x}", hash);
  }();
  return tag;
}

bool HasBootId() {
  static const bool has = !BootId().empty();
  return has;
}

std::string TemporaryName(std::string_view target, std::string_view kind) {
  return fmt::format(".{}.{}.{}.{}", target, kind, ThisHostTag(), static_cast<long>(::getpid()));
}

std::optional<TemporaryWriter> WriterOf(std::string_view name, std::string_view target, std::string_view kind) {
  const std::string prefix = fmt::format(".{}.{}.", target, kind);
  if (!name.starts_with(prefix)) return std::nullopt;
  const std::string_view rest = name.substr(prefix.size());
  constexpr std::size_t kPidDigits = 18;
  if (IsDigits(rest, kPidDigits)) return TemporaryWriter{"", std::stol(std::string(rest))};
  if (rest.size() < kTagDigits + 2 || rest[kTagDigits] != '.') return std::nullopt;
  const std::string_view tag = rest.substr(0, kTagDigits), pid = rest.substr(kTagDigits + 1);
  if (!IsTag(tag) || !IsDigits(pid, kPidDigits)) return std::nullopt;
  return TemporaryWriter{std::string(tag), std::stol(std::string(pid))};
}

bool IsTemporaryOf(std::string_view name, const TemporaryWriter& writer) {
  return name.starts_with('.') && !writer.tag.empty() && name.ends_with(fmt::format(".tmp.{}.{}", writer.tag, writer.pid));
}

}  // namespace stickslip::detail
