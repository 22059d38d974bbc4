// SPDX-License-Identifier: Apache-2.0
// SIGINT and SIGTERM. This is the process's one piece of global state, and
// it lives in apps/ only: the libraries never see signals.
//
// The signals are taken by a thread of their own (sigwait), not by a
// handler, so that what they trigger is ordinary code: the first sets a flag
// that long-running commands poll between units of work (batch: between
// structures) to finish what is in flight and leave consistent files; the
// `abandon_at`-th ends the process at once with 128 + the signal's number,
// after removing every temporary file and directory of writes in progress
// (temporaries(): whoever writes registers them there), so that nothing
// half-written or hidden is left. `pockets` abandons at the first signal
// (nothing of a run is worth keeping until its output directory is
// swapped in whole), `batch` at the second.
#pragma once

#include "util/temporary_paths.hpp"

namespace alphapocket {

// Blocks the signals and starts the thread; call once, before any other
// thread is started (threads inherit the blocked signals).
void install_interrupt_handlers(int abandon_at);
// Whether SIGINT or SIGTERM arrived since install_interrupt_handlers().
bool interrupted();
// The signal that arrived first (SIGINT, SIGTERM), 0 if none.
int interrupt_signal();
// The temporary paths that abandoning removes.
molecule::TemporaryPaths& temporaries();

}  // namespace alphapocket
