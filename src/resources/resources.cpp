#include "resources/resources.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace cb {

namespace {

std::string slurp(const char* path) {
  std::ifstream in(path);
  if (!in) return {};
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A cgroup number: bytes, or nullopt for "max", an empty text, or no limit at all (v1 shows
// "no limit" as a number near 2^63).
std::optional<double> cgroup_bytes(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || v <= 0 || v >= 1e18) return std::nullopt;
  return v;
}

std::string json_text(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

}  // namespace

double MemoryEstimate::total() const {
  double sum = 0;
  for (const MemoryNeed& n : needs) sum += n.bytes;
  return sum;
}

std::string MemoryEstimate::json() const {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.0f", total());
  std::string j = std::string("{\"total_bytes\":") + buf + ",\"parts\":{";
  for (std::size_t i = 0; i < needs.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.0f", needs[i].bytes);
    j += (i ? "," : "") + json_text(needs[i].what) + ":" + buf;
  }
  return j + "}}";
}

MachineMemory machine_memory_from(const std::string& meminfo, const std::string& v2_max,
                                  const std::string& v2_current, const std::string& v1_limit,
                                  const std::string& v1_usage) {
  MachineMemory m;
  m.available_bytes = 0;
  m.source = "MemAvailable";
  std::istringstream lines(meminfo);
  for (std::string line; std::getline(lines, line);) {
    double kib = 0;
    if (std::sscanf(line.c_str(), "MemAvailable: %lf kB", &kib) == 1)
      m.available_bytes = kib * 1024;
  }
  auto lower = [&](std::optional<double> limit, std::optional<double> used, const char* source) {
    if (!limit) return;
    const double free = std::max(0.0, *limit - used.value_or(0.0));
    if (m.available_bytes <= 0 || free < m.available_bytes) {
      m.available_bytes = free;
      m.source = source;
    }
  };
  lower(cgroup_bytes(v2_max), cgroup_bytes(v2_current), "cgroup v2 memory.max");
  lower(cgroup_bytes(v1_limit), cgroup_bytes(v1_usage), "cgroup v1 memory.limit_in_bytes");
  return m;
}

MachineMemory machine_memory() {
  return machine_memory_from(slurp("/proc/meminfo"), slurp("/sys/fs/cgroup/memory.max"),
                             slurp("/sys/fs/cgroup/memory.current"),
                             slurp("/sys/fs/cgroup/memory/memory.limit_in_bytes"),
                             slurp("/sys/fs/cgroup/memory/memory.usage_in_bytes"));
}

std::string format_bytes(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000 && u < 6) bytes /= 1000, ++u;
  char buf[48];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return buf;
}

void require_memory(const MemoryEstimate& estimate, const MachineMemory& machine,
                    const std::string& command, const std::string& fix) {
  const double limit = kMemoryShare * machine.available_bytes;
  const double need = estimate.total();
  if (machine.available_bytes <= 0 || need <= limit) return;
  // The parts, biggest first: what to shrink.
  std::vector<MemoryNeed> parts = estimate.needs;
  std::sort(parts.begin(), parts.end(),
            [](const MemoryNeed& a, const MemoryNeed& b) { return a.bytes > b.bytes; });
  std::string list;
  for (std::size_t i = 0; i < parts.size() && i < 3; ++i)
    if (parts[i].bytes > 0)
      list += (list.empty() ? "" : ", ") + parts[i].what + " " + format_bytes(parts[i].bytes);
  throw ResourceError(command + ": needs about " + format_bytes(need) + " of memory (" + list +
                      "), more than the limit of " + format_bytes(limit) + " (" +
                      std::to_string(static_cast<int>(kMemoryShare * 100)) + " % of the " +
                      format_bytes(machine.available_bytes) + " available, " + machine.source +
                      "); " + fix);
}

double rk4_bytes(double beads) {
  // psi and velocity of the state, the step's new state, and the row of phi a run samples.
  return 5 * 8 * beads;
}

double exact_table_bytes(double beads) {
  // psi_w and phi_w: N x N each (exact_chain.h), plus the O(N) modes.
  return 2 * 8 * beads * beads + 64 * beads;
}

double csv_row_bytes(double values) {
  return 25 * values;
}

}  // namespace cb
