#include "core/Parallel.H"

#include <atomic>

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
        #pragma omp parallel
        {
            fedisableexcept(FE_ALL_EXCEPT);
        }
    }
}


NonStopArithmetic::~NonStopArithmetic()
{
    if (traps_)
    {
        #pragma omp parallel
        {
            feclearexcept(FE_ALL_EXCEPT);
            feenableexcept(traps_);
        }
        feclearexcept(FE_ALL_EXCEPT);
        feenableexcept(traps_);
    }
}

} // namespace suspension
