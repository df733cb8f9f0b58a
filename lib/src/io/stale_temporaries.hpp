// Internal to io/: the temporaries earlier writers of an output left beside it (a process killed,
// a machine that stopped), removed only where this run can prove them its own kind and dead.
#pragma once

#include <filesystem>
#include <string>

#include "result_directory.hpp"

namespace stickslip::detail {

// Before a writer makes its temporary directory beside results_root/<output>: each temporary
// directory of that output (temporary_name.hpp) written on this host in this boot by a process
// that no longer exists loses what its writer made (the entries `ours` names, and that writer's
// own temporaries inside it), and goes once empty; one that still holds the user's files (moved
// into it before its writer ended) stays. Every other temporary of the output stays: on a shared
// file system a process that is gone here may be running on another host. One line on stderr per
// temporary, removed or left, saying why.
void RemoveStaleTemporaries(const std::filesystem::path& results_root, const std::string& output, const OwnedEntry& ours);

// Before a file is written beside `target` (io/atomic_file.hpp): each temporary file of that target
// (a regular file, not a link, named exactly as temporary_name.hpp names them) written on this host
// in this boot by a process that no longer exists is removed; every other stays, for the reasons
// above. One line on stderr per temporary, removed or left, saying why.
void RemoveStaleFileTemporaries(const std::filesystem::path& target);

}  // namespace stickslip::detail
