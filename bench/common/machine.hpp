// What the benchmarks record about the machine they measured on.
#pragma once

#include <string>

namespace projtrack::bench {

// The CPU's model name from /proc/cpuinfo ("unknown" elsewhere).
std::string cpu_model();
// Now, as "YYYY-MM-DD HH:MM UTC": when the data was measured.
std::string utc_now();

}  // namespace projtrack::bench
