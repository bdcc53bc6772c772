#include "common/memory_reuse.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <memory>
#include <sys/resource.h>

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

// page faults taken while a fresh 4 MB block is written and freed
long faultsOfOneBlock() {
    constexpr std::size_t kBytes = 4 << 20;
    const long before = minorFaults();
    {
        std::unique_ptr<char[]> block(new char[kBytes]);
        std::memset(block.get(), 1, kBytes);
        volatile char sink = block[kBytes / 2];
        (void)sink;
    }
    return minorFaults() - before;
}

TEST(MemoryReuse, AFreedBlockIsWrittenAgainWithoutPageFaults) {
#if defined(CHAPLYGIN_OWN_ALLOCATOR) || !defined(__GLIBC__)
    GTEST_SKIP() << "the sanitizer's or this C library's allocator ignores glibc's settings";
#else
    keepFreedMemoryForReuse();
    faultsOfOneBlock(); // the first touch of the pages is a fault each (1,024 of them)
    const long again = faultsOfOneBlock();
    EXPECT_LT(again, 16) << "a block of 1,024 pages faulted again " << again << " times";
#endif
}

} // namespace
} // namespace chaplygin
