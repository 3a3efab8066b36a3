#include "dynamics/ConjugateGradient.H"
#include "core/Parallel.H"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace suspension
{

ConjugateGradient::ConjugateGradient(const Params& params, const Domain* domain)
:
    params_(params),
    domain_(domain)
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
    return dot(a, b, partial);
}


double ConjugateGradient::dot
(
    const Vector& a,
    const Vector& b,
    std::vector<double>& partial
)
{
    partial.resize(nBlocks(a.size()));
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
