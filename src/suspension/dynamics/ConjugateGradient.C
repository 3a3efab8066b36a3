#include "dynamics/ConjugateGradient.H"
#include "core/Parallel.H"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace suspension
{

namespace
{
    //- Entries per block of the ordered reductions (6 per particle,
    //  core/Parallel.H); vectors of fewer than parallelMinParticles()
    //  particles are done on one thread
    constexpr Eigen::Index blockSize = 6*reductionBlock;

    Eigen::Index nBlocks(Eigen::Index n)
    {
        return (n + blockSize - 1)/blockSize;
    }

    //- f(start, length) for every block, in parallel
    template<class F>
    void forBlocks(Eigen::Index n, F f)
    {
        const Eigen::Index nb = nBlocks(n);
        const bool parallel = threaded(std::size_t(n/6)) && nb > 1;
        #pragma omp parallel for schedule(static) if(parallel)
        for (Eigen::Index k = 0; k < nb; ++k)
        {
            const Eigen::Index start = k*blockSize;
            f(start, std::min(blockSize, n - start));
        }
    }
}


ConjugateGradient::ConjugateGradient(const Params& params)
:
    params_(params)
{
    if (!(params.tolerance > 0 && params.tolerance < 1) || params.maxIterations == 0)
    {
        throw std::invalid_argument
        (
            "ConjugateGradient: need 0 < tolerance < 1 and maxIterations > 0;"
            " got tolerance " + std::to_string(params.tolerance)
          + ", maxIterations " + std::to_string(params.maxIterations)
        );
    }
}


double ConjugateGradient::dot(const Vector& a, const Vector& b)
{
    std::vector<double> partial(nBlocks(a.size()));
    forBlocks(a.size(), [&](Eigen::Index start, Eigen::Index n)
    {
        partial[start/blockSize] = a.segment(start, n).dot(b.segment(start, n));
    });
    double sum = 0;
    for (const double s : partial)
    {
        sum += s;
    }
    return sum;
}


void ConjugateGradient::residualDots
(
    const Vector& r,
    const Vector& z,
    double& rz,
    double& rr
)
{
    std::vector<double> partial(2*nBlocks(r.size()));
    forBlocks(r.size(), [&](Eigen::Index start, Eigen::Index n)
    {
        const Eigen::Index k = 2*(start/blockSize);
        partial[k] = r.segment(start, n).dot(z.segment(start, n));
        partial[k + 1] = r.segment(start, n).squaredNorm();
    });
    rz = 0;
    rr = 0;
    for (std::size_t k = 0; k < partial.size(); k += 2)
    {
        rz += partial[k];
        rr += partial[k + 1];
    }
}


void ConjugateGradient::update
(
    double alpha,
    const Vector& p,
    const Vector& q,
    Vector& x,
    Vector& r
)
{
    forBlocks(x.size(), [&](Eigen::Index start, Eigen::Index n)
    {
        x.segment(start, n) += alpha*p.segment(start, n);
        r.segment(start, n) -= alpha*q.segment(start, n);
    });
}


void ConjugateGradient::direction(const Vector& z, double beta, Vector& p)
{
    forBlocks(p.size(), [&](Eigen::Index start, Eigen::Index n)
    {
        p.segment(start, n) = z.segment(start, n) + beta*p.segment(start, n);
    });
}

} // namespace suspension
