// Heap allocations counted process-wide (alloc_count.cpp interposes malloc and its relatives).
#pragma once

#include <atomic>

namespace projtrack::bench {

extern std::atomic<long> allocations;

}  // namespace projtrack::bench
