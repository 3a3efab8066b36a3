#include "stress/SteadyState.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace suspension
{

std::size_t SteadyState::mserTruncation
(
    const std::vector<double>& x,
    const std::size_t m
)
{
    const std::size_t k = x.size()/m;
    if (k < 2)
    {
        return 0;
    }
    // Batch means z_j and, from the end, their running sums
    std::vector<double> z(k);
    for (std::size_t j = 0; j < k; ++j)
    {
        double s = 0;
        for (std::size_t i = 0; i < m; ++i)
        {
            s += x[j*m + i];
        }
        z[j] = s/m;
    }
    std::vector<double> sum(k + 1, 0), sum2(k + 1, 0);
    for (std::size_t j = k; j-- > 0;)
    {
        sum[j] = sum[j + 1] + z[j];
        sum2[j] = sum2[j + 1] + z[j]*z[j];
    }
    std::size_t best = 0;
    double bestValue = std::numeric_limits<double>::infinity();
    for (std::size_t d = 0; d <= k/2; ++d)
    {
        const double n = double(k - d);
        const double mean = sum[d]/n;
        // sum (z - zbar)^2 = sum z^2 - n zbar^2, never below 0
        const double ss = std::max(0.0, sum2[d] - n*mean*mean);
        const double value = ss/(n*n);
        if (value < bestValue)
        {
            bestValue = value;
            best = d;
        }
    }
    return best*m;
}


double SteadyState::integratedCorrelation
(
    const std::vector<double>& x,
    const double c,
    bool& found
)
{
    const std::size_t n = x.size();
    found = false;
    if (n < 4)
    {
        return 0.5;
    }
    // Shifted by the first value, so that a constant series (the Stokes
    // part, 2.5 phi) has deviations of exactly zero, not rounding noise
    // that correlates perfectly
    double mean = 0;
    for (double v : x) mean += v - x[0];
    mean = x[0] + mean/n;
    double c0 = 0;
    for (double v : x) c0 += (v - mean)*(v - mean);
    c0 /= n;
    if (c0 <= 0)
    {
        found = true;               // a constant series: no correlation
        return 0.5;
    }
    double tau = 0.5;
    for (std::size_t t = 1; t < n/2; ++t)
    {
        double ct = 0;
        for (std::size_t i = 0; i + t < n; ++i)
        {
            ct += (x[i] - mean)*(x[i + t] - mean);
        }
        tau += ct/(n*c0);
        if (double(t) >= c*tau)
        {
            found = true;
            // The mean taken from the series itself biases the sum low by
            // the factor 1 - (2W + 1)/n (Madras & Sokal 1988)
            tau /= std::max(1 - double(2*t + 1)/n, 0.5);
            break;
        }
    }
    return std::max(tau, 0.5);
}


SteadyState::SteadyState
(
    const std::vector<double>& strain,
    const std::vector<double>& values,
    const Options& opt
)
:
    minBlocks_(opt.minBlocks),
    minStrain_(opt.minStrain)
{
    if (strain.size() != values.size())
    {
        throw std::invalid_argument("SteadyState: strain and values differ in length");
    }
    const std::size_t n = values.size();
    if (n < 2)
    {
        return;
    }
    h_ = (strain.back() - strain.front())/double(n - 1);

    if (opt.discardStrain >= 0)
    {
        nDiscarded_ = std::size_t
        (
            std::lower_bound(strain.begin(), strain.end(), strain.front() + opt.discardStrain)
          - strain.begin()
        );
    }
    else
    {
        nDiscarded_ = mserTruncation(values, std::max<std::size_t>(opt.batch, 1));
    }
    const std::vector<double> y(values.begin() + nDiscarded_, values.end());
    if (y.empty())
    {
        return;
    }

    tau_ = integratedCorrelation(y, opt.window, windowFound_);
    blockLength_ = std::max<std::size_t>(1, std::size_t(std::ceil(4*tau_)));
    nBlocks_ = y.size()/blockLength_;
    if (nBlocks_ == 0)
    {
        // Shorter than one block: the mean of all, no error bar
        blockLength_ = y.size();
        nBlocks_ = 1;
    }
    nUsed_ = nBlocks_*blockLength_;
    // The oldest samples that do not fill a block join the discarded part
    const std::size_t first = y.size() - nUsed_;
    nDiscarded_ += first;

    // Sums shifted by the first value (exact for a constant series)
    const double y0 = y[first];
    std::vector<double> blockMean(nBlocks_, 0);
    for (std::size_t b = 0; b < nBlocks_; ++b)
    {
        double s = 0;
        for (std::size_t i = 0; i < blockLength_; ++i)
        {
            s += y[first + b*blockLength_ + i] - y0;
        }
        blockMean[b] = y0 + s/blockLength_;
        mean_ += s/blockLength_;
    }
    mean_ = y0 + mean_/nBlocks_;
    if (nBlocks_ > 1)
    {
        double var = 0;
        for (double m : blockMean) var += (m - mean_)*(m - mean_);
        var /= (nBlocks_ - 1);
        standardError_ = std::sqrt(var/nBlocks_);
    }
    else
    {
        standardError_ = std::numeric_limits<double>::quiet_NaN();
    }
}


double SteadyState::strainNeeded(const double p) const
{
    const double enoughBlocks = std::max
    (
        minBlocks_*std::max(blockStrain(), correlationStrain()),
        minStrain_
    );
    // (no ordered comparison with a NaN: OpenFOAM traps the FE_INVALID)
    if (nBlocks_ < 2 || std::isnan(standardError_) || mean_ == 0)
    {
        return std::max(enoughBlocks, 2*strainUsed());
    }
    const double r = standardError_/(p*std::abs(mean_));
    return std::max(strainUsed()*r*r, enoughBlocks);
}

} // namespace suspension
