// Internal to io/: the names of the temporaries a writer makes beside its target (a file's
// ".<name>.tmp.<tag>.<pid>", a directory's ".<name>.tmp.<tag>.<pid>" and ".<name>.old.<tag>.<pid>"),
// which say which process on which host, in which boot, made them: a later run may remove one only
// where it can prove its writer is gone (stale_temporaries.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace stickslip::detail {

// This host in this boot as 16 hexadecimal digits: a 64-bit FNV-1a hash of the host name and the
// boot id (/proc/sys/kernel/random/boot_id). Hashed, not spelt out: a run name of 200 bytes with a
// host name (up to 64) and a boot id (36) would pass the 255 bytes a file name may have.
const std::string& ThisHostTag();

// Whether this system has a boot id: without one a process id may have been reused since a reboot,
// and no temporary can be proven dead.
bool HasBootId();

// ".<target>.<kind>.<tag>.<pid>" for this process ("tmp" or "old").
std::string TemporaryName(std::string_view target, std::string_view kind);

// Who wrote a temporary of `target`: `tag` empty for the name of earlier versions,
// ".<target>.<kind>.<pid>", which does not say the host.
struct TemporaryWriter {
  std::string tag;
  long pid = 0;
};

// The writer named by `name` if it is a temporary of `target` of that kind; nullopt for any other
// name (another output's temporary too: ".a.tmp.b.tmp.<tag>.<pid>" is b's, not a's).
std::optional<TemporaryWriter> WriterOf(std::string_view name, std::string_view target, std::string_view kind);

// Whether `name` is any temporary (of any target or kind) of that writer: what it made inside
// its own temporary directory (a branch's directory, a file not yet renamed).
bool IsTemporaryOf(std::string_view name, const TemporaryWriter& writer);

}  // namespace stickslip::detail
