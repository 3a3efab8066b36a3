#include "packing/SizeDistribution.H"
#include "forces/ParamCheck.H"

#include <algorithm>
#include <cmath>

namespace suspension
{

namespace
{
    const char* const model = "SizeDistribution";

    //- Standard normal distribution function
    double normalCdf(double z)
    {
        return 0.5*std::erfc(-z/std::sqrt(2.0));
    }

    //- Standard normal quantile for p in (0, 1): Newton's method on
    //  normalCdf, safeguarded by bisection of a bracket that always holds
    //  the root (normalCdf(-10) = 8e-24, below any (k + 1/2)/N)
    double normalQuantile(double p)
    {
        double lo = -10;
        double hi = 10;
        double z = 0;
        for (int iter = 0; iter < 100; ++iter)
        {
            const double f = normalCdf(z) - p;
            if (f < 0)
            {
                lo = z;
            }
            else
            {
                hi = z;
            }
            const double density = std::exp(-0.5*z*z)/std::sqrt(2*pi);
            double next = z - f/density;
            if (!(next > lo && next < hi))
            {
                next = 0.5*(lo + hi);
            }
            const bool converged = std::abs(next - z) <= 1e-14*(1 + std::abs(z));
            z = next;
            if (converged)
            {
                break;
            }
        }
        return z;
    }
}


SizeDistribution::SizeDistribution(Type type, double p1, double p2, double p3)
:
    type_(type),
    p1_(p1),
    p2_(p2),
    p3_(p3)
{}


SizeDistribution SizeDistribution::monodisperse(double a)
{
    checkPositive(model, "a", a);
    return SizeDistribution(Type::monodisperse, a, 1, 0);
}


SizeDistribution SizeDistribution::bidisperse
(
    double a1,
    double sizeRatio,
    double volumeRatio
)
{
    checkPositive(model, "a1", a1);
    checkPositive(model, "sizeRatio (a2/a1)", sizeRatio);
    checkPositive(model, "volumeRatio (V2/V1)", volumeRatio);
    return SizeDistribution(Type::bidisperse, a1, sizeRatio, volumeRatio);
}


SizeDistribution SizeDistribution::uniform(double aMin, double aMax)
{
    checkPositive(model, "aMin", aMin);
    checkPositive(model, "aMax", aMax);
    if (!(aMax >= aMin))
    {
        throwOutOfRange(model, "aMax", aMax, "[aMin, inf)");
    }
    return SizeDistribution(Type::uniform, aMin, aMax, 0);
}


SizeDistribution SizeDistribution::logNormal(double mean, double sd)
{
    checkPositive(model, "mean", mean);
    checkPositive(model, "sd", sd);
    return SizeDistribution(Type::logNormal, mean, sd, 0);
}


std::vector<double> SizeDistribution::radii(std::size_t N) const
{
    const std::size_t nMin = type_ == Type::bidisperse ? 2 : 1;
    if (N < nMin)
    {
        throwOutOfRange
        (
            model, "N", static_cast<double>(N),
            type_ == Type::bidisperse ? "[2, inf) (bidisperse)" : "[1, inf)"
        );
    }

    std::vector<double> a(N, p1_);
    switch (type_)
    {
        case Type::monodisperse:
            break;

        case Type::bidisperse:
        {
            const double q = p3_/(p2_*p2_*p2_);     // N2/N1
            const double r = q/(1 + q);             // N2/N
            const double n2 = std::round(static_cast<double>(N)*r);
            const std::size_t N2 = std::clamp
            (
                static_cast<std::size_t>(n2), std::size_t(1), N - 1
            );
            std::fill(a.end() - N2, a.end(), p1_*p2_);
            break;
        }

        case Type::uniform:
            for (std::size_t k = 0; k < N; ++k)
            {
                a[k] = p1_ + (p2_ - p1_)*(k + 0.5)/N;
            }
            break;

        case Type::logNormal:
        {
            const double s2 = std::log1p((p2_/p1_)*(p2_/p1_));
            const double mu = std::log(p1_) - 0.5*s2;
            for (std::size_t k = 0; k < N; ++k)
            {
                a[k] = std::exp(mu + std::sqrt(s2)*normalQuantile((k + 0.5)/N));
            }
            break;
        }
    }
    return a;
}


double solidVolume(const std::vector<double>& radii)
{
    double V = 0;
    for (double a : radii)
    {
        V += 4.0/3.0*pi*a*a*a;
    }
    return V;
}


Vec3 boxLengths
(
    const std::vector<double>& radii,
    double phi,
    const Vec3& aspect
)
{
    if (radii.empty())
    {
        throwOutOfRange("boxLengths", "number of radii", 0, "[1, inf)");
    }
    for (double a : radii)
    {
        checkPositive("boxLengths", "radius", a);
    }
    if (!(phi > 0 && phi < phiMax))
    {
        throwOutOfRange("boxLengths", "phi", phi, "(0, 0.74)");
    }
    checkPositive("boxLengths", "aspect x", aspect.x());
    checkPositive("boxLengths", "aspect y", aspect.y());
    checkPositive("boxLengths", "aspect z", aspect.z());

    return aspect*std::cbrt(solidVolume(radii)/(phi*aspect.prod()));
}

} // namespace suspension
