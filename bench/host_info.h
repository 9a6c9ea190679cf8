// Facts about the machine and the invocation that every benchmark number is recorded with:
// the command line, the CPU, and the load average (other processes share the cores, so a
// number measured under load says so).
#pragma once

#include <array>
#include <string>

namespace tp::bench {

// The command line of this process as a shell would accept it, argv[0] shortened to its file
// name (read from /proc/self/cmdline).
std::string command_line();

// The 1-, 5- and 15-minute load averages (/proc/loadavg); -1 where unavailable.
std::array<double, 3> load_average();

// "model name" of /proc/cpuinfo, or "unknown CPU".
std::string cpu_model();

// Logical cores the process may use.
unsigned cpu_cores();

// The current UTC time as 2024-01-31T12:00:00Z.
std::string utc_timestamp();

} // namespace tp::bench
