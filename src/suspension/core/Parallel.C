#include "core/Parallel.H"

#include <atomic>

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

} // namespace suspension
