#pragma once
// Process-wide allocator settings of the riemesh tool (never of the library).

namespace riemesh::cli {

/// With glibc: its malloc's thresholds set to their steady-state values from the start, and the
/// first 32 MiB of the heap backed by transparent huge pages where the system allows them
/// (madvise mode). Nothing elsewhere, and nothing in sanitized builds.
void tune_memory();

}  // namespace riemesh::cli
