#include "core/Parallel.H"

#include <algorithm>
#include <atomic>
#include <mutex>

#include <fenv.h>

namespace suspension
{

namespace
{
    std::atomic<std::size_t> minParticles{defaultParallelMinParticles};
}


std::size_t parallelMinParticles()
{
    return minParticles.load(std::memory_order_relaxed);
}


std::size_t setParallelMinParticles(std::size_t n)
{
    return minParticles.exchange(n);
}


NonStopArithmetic::NonStopArithmetic()
:
    traps_(fegetexcept())
{
    if (traps_)
    {
        fedisableexcept(FE_ALL_EXCEPT);

        // The threads of the pool once, for good: they run only engine
        // code, and threads started later copy this thread's environment
        static std::once_flag pool;
        std::call_once(pool, []
        {
            const int n = std::max(omp_get_max_threads(), omp_get_num_procs());
            #pragma omp parallel num_threads(n)
            {
                fedisableexcept(FE_ALL_EXCEPT);
            }
        });
    }
}


NonStopArithmetic::~NonStopArithmetic()
{
    if (traps_)
    {
        feclearexcept(FE_ALL_EXCEPT);
        feenableexcept(traps_);
    }
}

} // namespace suspension
