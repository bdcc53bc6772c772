#pragma once
// The allocator settings the program and the benchmarks start with (keepFreedMemoryForReuse).

namespace chaplygin {

/// Asks the C library to keep freed memory for the program's next allocations instead of
/// returning it to the kernel at once. A path table of a drawn stroke is about 0.5 MB; with the
/// C library's defaults every new table is fresh memory whose first touch costs a page fault per
/// 4 KB (a quarter of a 500-point stroke's tabulation, docs/numerics.md §7). With glibc: freed
/// memory is kept up to 64 MB, and blocks below 16 MB come from the heap, not from mmap. Does
/// nothing with other C libraries. Called once at start-up by the program and the benchmarks.
void keepFreedMemoryForReuse();

} // namespace chaplygin
