// Resource guards: what a command will need (memory, frames, CSV rows and bytes), checked
// before any work against fixed limits and against what this machine has.
//
// Design note: a hostile or mistyped scene (beads = 1000000000, --speed 1e-300) used to be
// found out by the kernel's OOM killer after minutes, or to overflow a count. Every command
// now adds up its big allocations here first and stops with status 2 and a message that
// gives the estimate, the limit and the fix. Estimates are in double: 2^31 beads squared
// does not overflow it. Machine limits come from MemAvailable in /proc/meminfo, or the
// cgroup (v2 memory.max, v1 memory.limit_in_bytes) when that is lower, as in a container.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cb {

// A user error (status 2): the request would not fit.
struct ResourceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Fixed limits, whatever the machine.
inline constexpr double kMaxFrames = 1e6;  // 9.3 hours of video at 30 fps
// (A table drive's file has its own limit, kMaxDriveTableBytes in drive/drive.h.)
inline constexpr int kMaxSweepValues = 1000000;
// Share of the available memory one command may plan to use: the rest is for the system
// and for what the estimate leaves out.
inline constexpr double kMemoryShare = 0.8;

// One big allocation of a command.
struct MemoryNeed {
  std::string what;  // "RK4 state (2 arrays of N + 11 work arrays)"
  double bytes = 0;
};

struct MemoryEstimate {
  std::vector<MemoryNeed> needs;
  double total() const;
  std::string json() const;  // {"total_bytes":...,"parts":{"what":bytes,...}}
};

// How much memory the machine can give, and which source said so.
struct MachineMemory {
  double available_bytes = 0;
  std::string source;  // "MemAvailable", "cgroup v2 memory.max", "cgroup v1 memory.limit_in_bytes"
};
MachineMemory machine_memory();
// The same from the files' texts (tests): meminfo is /proc/meminfo; a cgroup text is empty
// when the file is absent. v2: memory.max ("max" or bytes) minus memory.current; v1:
// memory.limit_in_bytes minus memory.usage_in_bytes (huge values mean no limit).
MachineMemory machine_memory_from(const std::string& meminfo, const std::string& v2_max,
                                  const std::string& v2_current, const std::string& v1_limit,
                                  const std::string& v1_usage);

// "24.0 GB" (decimal units, 3 digits).
std::string format_bytes(double bytes);

// Throws ResourceError "<command>: needs about X (<biggest parts>), but <limit>; <fix>" when
// the estimate is above kMemoryShare of what the machine has.
void require_memory(const MemoryEstimate& estimate, const MachineMemory& machine,
                    const std::string& command, const std::string& fix);

// The big allocations of the physics, per bead (bytes), for estimates.
double rk4_bytes(double beads);          // state and the integrator's work arrays
double exact_table_bytes(double beads);  // the exact solver's N x N modal tables
// A CSV row of `values` numbers written by append_number: at most 24 characters each
// ("-1.2345678901234567e-300"), a separator or newline after each.
double csv_row_bytes(double values);

}  // namespace cb
