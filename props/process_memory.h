#pragma once
/// \file
/// How much memory a fuzzing engine and its jobs hold: the resident pages of
/// every process in its process group, read from /proc. Processes end while
/// they are read, so nothing here throws: a process gone is a process that
/// holds nothing.
#include <optional>
#include <string>

#include <sys/types.h>

namespace mfz::props {

/// Everything left to read on `fd`, or nullopt on a read error (ESRCH once
/// the process behind a /proc file has ended). std::ifstream throws there
/// instead, from inside libstdc++'s filebuf: `manifuzz fuzz` died of it
/// after 768 s of a Bullet campaign.
std::optional<std::string> read_to_end(int fd);

/// Resident memory, in MiB, of the processes whose group is `group`.
double group_resident_mb(pid_t group);

}  // namespace mfz::props
