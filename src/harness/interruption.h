#pragma once
/// \file
/// Ctrl-C and SIGTERM during a long run: the command asks to be told instead
/// of killed, so that it can stop its worker, write what it has and print its
/// summary. A wait for a plugin's answer ends at once when they arrive.

namespace mfz {

/// Installs handlers for SIGINT and SIGTERM (without SA_RESTART, so that a
/// blocking wait returns) and clears the flag.
void catch_interruptions();
/// Restores the default actions.
void release_interruptions();
/// True once SIGINT or SIGTERM arrived after catch_interruptions().
bool interrupted();

}  // namespace mfz
