// The CPU's name, for the headers of benchmark tables and JSON.
#pragma once

#include <string>

namespace hexgait {

// The CPU's model name from /proc/cpuinfo; "unknown CPU" where it names none.
std::string CpuModel();

}  // namespace hexgait
