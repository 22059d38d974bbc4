// SIGINT and SIGTERM as a request to stop: the handlers set one atomic
// flag that long-running commands poll between units of work (batch: between
// structures), so that they finish what is in flight and leave consistent
// files. This is the process's one piece of global state, and it lives in
// apps/ only: the libraries never see signals.
//
// A second signal abandons the work in flight: the process exits at once
// with 128 + the signal's number (files being written are temporary files
// that are never renamed into place, so nothing is left half-written).
#pragma once

namespace alphapocket {

// Installs the handlers (once, before any thread is started).
void install_interrupt_handlers();
// Whether SIGINT or SIGTERM arrived since install_interrupt_handlers().
bool interrupted();
// The signal that arrived first (SIGINT, SIGTERM), 0 if none.
int interrupt_signal();

}  // namespace alphapocket
