#include "common/memory_reuse.h"

#include <cstdlib> // any C library header defines __GLIBC__ under glibc
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace chaplygin {

void keepFreedMemoryForReuse() {
#if defined(__GLIBC__)
    // setting either turns off glibc's own adjustment of the other, so both are set
    mallopt(M_MMAP_THRESHOLD, 16 * 1024 * 1024);
    mallopt(M_TRIM_THRESHOLD, 64 * 1024 * 1024);
#endif
}

} // namespace chaplygin
