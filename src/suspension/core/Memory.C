#include "core/Memory.H"

#include <cstdlib>      // includes <features.h>, which defines __GLIBC__

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace suspension
{

void useSystemForLargeArrays()
{
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, static_cast<int>(largeArrayBytes));
#endif
}


void returnFreedMemory()
{
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

} // namespace suspension
