// Internal to io/: the one place a test may stop a writer at a known point, so that signals are
// sent there rather than timed. Test-only: no user sets these variables.
#pragma once

namespace stickslip::detail {

// Where STICKSLIP_TEST_PAUSE_BEFORE_RENAME names a file: creates it, then waits (at most a minute)
// for a deferred signal (deferred_signals.hpp). ReplaceDirectory, WriteFileAtomically and
// WriteFilesAtomically call it once their temporary is written, just before it moves into place
// (only the outermost writer: a directory's files do not pause).
void PauseBeforeRenameForTests();

}  // namespace stickslip::detail
