#include "common/memory_reuse.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <memory>
#include <sys/resource.h>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define CHAPLYGIN_OWN_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CHAPLYGIN_OWN_ALLOCATOR 1
#endif
#endif

namespace chaplygin {
namespace {

long minorFaults() {
    rusage r{};
    getrusage(RUSAGE_SELF, &r);
    return r.ru_minflt;
}

// page faults taken while 1 MB in 256 blocks of 4 KB (below any mmap threshold, as a table's
// vectors) is written and freed; glibc's default hands the freed top of the heap back at 128 KB
long faultsOfManyBlocks() {
    constexpr std::size_t kBlocks = 256, kBytes = 4096;
    const long before = minorFaults();
    {
        std::vector<std::unique_ptr<char[]>> blocks;
        blocks.reserve(kBlocks);
        for (std::size_t i = 0; i < kBlocks; ++i) {
            blocks.emplace_back(new char[kBytes]);
            std::memset(blocks.back().get(), 1, kBytes);
        }
    }
    return minorFaults() - before;
}

TEST(MemoryReuse, FreedBlocksAreWrittenAgainWithoutPageFaults) {
#if defined(CHAPLYGIN_OWN_ALLOCATOR) || !defined(__GLIBC__)
    GTEST_SKIP() << "the sanitizer's or this C library's allocator ignores glibc's settings";
#else
    keepFreedMemoryForReuse();
    faultsOfManyBlocks(); // the first touch of the pages is a fault each (about 256)
    const long again = faultsOfManyBlocks();
    EXPECT_LT(again, 16) << "256 freed pages faulted again " << again << " times";
#endif
}

} // namespace
} // namespace chaplygin
