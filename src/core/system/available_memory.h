#pragma once
// How much memory the machine can still give, for estimates made before allocating.

namespace wt {

// MemAvailable from /proc/meminfo (free memory plus what the kernel can reclaim), else the
// machine's physical memory; 0 if neither is known.
double available_memory_bytes();

}  // namespace wt
