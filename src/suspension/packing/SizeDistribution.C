#include "packing/SizeDistribution.H"
#include "forces/ParamCheck.H"
#include "search/CellList.H"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

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


SizeDistribution SizeDistribution::discrete
(
    const std::vector<double>& radii,
    const std::vector<double>& fractions,
    Fractions kind
)
{
    const char* const name =
        kind == Fractions::volume ? "volume fraction" : "number fraction";
    if (radii.empty())
    {
        throwOutOfRange(model, "number of radii", 0, "[1, inf)");
    }
    if (fractions.size() != radii.size())
    {
        std::ostringstream msg;
        msg << model << ": " << radii.size() << " radii but "
            << fractions.size() << ' ' << name << "s: give one per radius";
        throw std::invalid_argument(msg.str());
    }
    double sum = 0;
    for (std::size_t k = 0; k < radii.size(); ++k)
    {
        checkPositive(model, "radius", radii[k]);
        checkPositive(model, name, fractions[k]);
        sum += fractions[k];
    }
    if (!(std::abs(sum - 1) <= fractionTolerance))
    {
        std::ostringstream msg;
        msg.precision(10);
        msg << model << ": the " << name << "s sum to " << sum
            << ", not to 1 within " << fractionTolerance;
        throw std::invalid_argument(msg.str());
    }

    // Classes by increasing radius; number fractions n_k to the volume
    // fractions v_k = n_k a_k^3/sum_j n_j a_j^3
    std::vector<std::size_t> order(radii.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort
    (
        order.begin(), order.end(),
        [&](std::size_t i, std::size_t j) { return radii[i] < radii[j]; }
    );
    SizeDistribution d(Type::discrete, 0, 0, 0);
    double total = 0;
    for (std::size_t k : order)
    {
        if (!d.classRadii_.empty() && radii[k] == d.classRadii_.back())
        {
            std::ostringstream msg;
            msg << model << ": radius " << radii[k] << " is given twice;"
                << " the radii of a discrete distribution must be distinct";
            throw std::invalid_argument(msg.str());
        }
        const double a = radii[k];
        const double v =
            kind == Fractions::volume ? fractions[k] : fractions[k]*a*a*a;
        d.classRadii_.push_back(a);
        d.volumeFractions_.push_back(v);
        total += v;
    }
    for (double& v : d.volumeFractions_)
    {
        v /= total;
    }
    return d;
}


SizeDistribution SizeDistribution::list(std::vector<double> radii)
{
    if (radii.empty())
    {
        throwOutOfRange(model, "number of radii", 0, "[1, inf)");
    }
    for (double a : radii)
    {
        checkPositive(model, "radius", a);
    }
    std::sort(radii.begin(), radii.end());
    SizeDistribution d(Type::list, 0, 0, 0);
    d.classRadii_ = std::move(radii);
    return d;
}


std::size_t SizeDistribution::minN() const
{
    switch (type_)
    {
        case Type::bidisperse:
            return 2;
        case Type::discrete:
        case Type::list:
            return classRadii_.size();
        default:
            return 1;
    }
}


std::vector<std::size_t> SizeDistribution::classCounts(std::size_t N) const
{
    const std::size_t K = classRadii_.size();
    std::vector<double> a3(K);
    double perVolume = 0;       // sum_k v_k/a_k^3
    for (std::size_t k = 0; k < K; ++k)
    {
        a3[k] = classRadii_[k]*classRadii_[k]*classRadii_[k];
        perVolume += volumeFractions_[k]/a3[k];
    }

    // sum_k (V_k/V - v_k)^2 of counts c
    const auto misfit = [&](const std::vector<std::size_t>& c)
    {
        double V = 0;
        for (std::size_t k = 0; k < K; ++k)
        {
            V += c[k]*a3[k];
        }
        double e = 0;
        for (std::size_t k = 0; k < K; ++k)
        {
            const double d = c[k]*a3[k]/V - volumeFractions_[k];
            e += d*d;
        }
        return e;
    };

    // Rounded ideal counts, each >= 1
    std::vector<std::size_t> c(K);
    std::size_t sum = 0;
    for (std::size_t k = 0; k < K; ++k)
    {
        const double ideal = N*volumeFractions_[k]/a3[k]/perVolume;
        c[k] = std::max(std::size_t(1), static_cast<std::size_t>(std::llround(ideal)));
        sum += c[k];
    }

    // To sum N: add to (remove from) the class where it fits best
    while (sum != N)
    {
        const bool add = sum < N;
        std::size_t best = K;
        double bestMisfit = 0;
        for (std::size_t k = 0; k < K; ++k)
        {
            if (!add && c[k] == 1)
            {
                continue;
            }
            std::vector<std::size_t> t = c;
            add ? ++t[k] : --t[k];
            const double e = misfit(t);
            if (best == K || e < bestMisfit)
            {
                best = k;
                bestMisfit = e;
            }
        }
        add ? ++c[best] : --c[best];
        add ? ++sum : --sum;
    }

    // Move single particles between classes while the misfit falls
    // (strictly, so this ends)
    double current = misfit(c);
    while (true)
    {
        std::size_t from = K;
        std::size_t to = K;
        for (std::size_t i = 0; i < K; ++i)
        {
            for (std::size_t j = 0; j < K && c[i] > 1; ++j)
            {
                if (j == i)
                {
                    continue;
                }
                std::vector<std::size_t> t = c;
                --t[i];
                ++t[j];
                const double e = misfit(t);
                if (e < current)
                {
                    current = e;
                    from = i;
                    to = j;
                }
            }
        }
        if (from == K)
        {
            return c;
        }
        --c[from];
        ++c[to];
    }
}


std::vector<double> SizeDistribution::radii(std::size_t N) const
{
    const std::size_t nMin = minN();
    if (fixedN() && N != nMin)
    {
        std::ostringstream msg;
        msg << model << ": the list holds " << nMin << " radii, not N = " << N;
        throw std::invalid_argument(msg.str());
    }
    if (N < nMin)
    {
        std::ostringstream range;
        range << '[' << nMin << ", inf) (at least one sphere of each radius)";
        throwOutOfRange(model, "N", static_cast<double>(N), range.str().c_str());
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

        case Type::discrete:
        {
            const std::vector<std::size_t> c = classCounts(N);
            auto it = a.begin();
            for (std::size_t k = 0; k < c.size(); ++k)
            {
                it = std::fill_n(it, c[k], classRadii_[k]);
            }
            break;
        }

        case Type::list:
            a = classRadii_;
            break;
    }
    return a;
}


std::string describeRadii
(
    const std::vector<double>& radii,
    std::size_t maxListed
)
{
    std::vector<double> a = radii;
    std::sort(a.begin(), a.end());
    const double V = solidVolume(a);

    // Distinct radii: runs equal to 1e-12 relative
    std::vector<std::pair<double, std::size_t>> classes;
    for (double r : a)
    {
        if (classes.empty() || r - classes.back().first > 1e-12*r)
        {
            classes.emplace_back(r, 0);
        }
        ++classes.back().second;
    }

    std::ostringstream os;
    if (classes.size() <= maxListed)
    {
        os  << classes.size() << (classes.size() == 1 ? " radius: " : " radii: ");
        for (std::size_t k = 0; k < classes.size(); ++k)
        {
            const auto& [r, n] = classes[k];
            os  << (k ? ", " : "") << r << " (n = " << n
                << ", volume fraction "
                << solidVolume(std::vector<double>(n, r))/V << ')';
        }
    }
    else
    {
        os  << classes.size() << " distinct radii in [" << a.front() << ", "
            << a.back() << "], mean "
            << std::accumulate(a.begin(), a.end(), 0.0)/a.size();
    }
    return os.str();
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



// * * * * * * * * * * * * * * * * * BoxRule * * * * * * * * * * * * * * * //

BoxRule::BoxRule(double reach)
:
    reach_(reach)
{
    checkNonNegative("BoxRule", "reach (largest interaction gap + skin)", reach);
}


bool BoxRule::fits(const Vec3& L, double aMax) const
{
    return CellList::fits(L, range(aMax));
}


std::size_t BoxRule::smallestN
(
    const SizeDistribution& d,
    double phi,
    const Vec3& aspect
) const
{
    const auto fitsAt = [&](std::size_t N)
    {
        const std::vector<double> a = d.radii(N);
        return fits(boxLengths(a, phi, aspect), a.back());
    };

    std::size_t fails = d.minN();
    if (fitsAt(fails))
    {
        return fails;
    }
    if (d.fixedN())
    {
        return 0;
    }

    // Double until it fits, then bisect: the box grows like N^(1/3), faster
    // than a_max
    constexpr std::size_t nLargest = std::size_t(1) << 40;
    std::size_t works = fails;
    do
    {
        fails = works;
        works *= 2;
        if (works > nLargest)
        {
            return 0;
        }
    }
    while (!fitsAt(works));

    while (works - fails > 1)
    {
        const std::size_t mid = fails + (works - fails)/2;
        (fitsAt(mid) ? works : fails) = mid;
    }
    return works;
}


void BoxRule::check(const Vec3& L, double aMax) const
{
    if (fits(L, aMax))
    {
        return;
    }
    const double R = range(aMax);
    std::ostringstream msg;
    msg << "BoxRule: the box (" << L.transpose() << ") is too small for the"
        << " neighbour search: every box length must be at least 3 R = "
        << CellList::smallestLength(R) << ", where R = 2 a_max + reach = 2*"
        << aMax << " + " << reach_ << " = " << R << " is the neighbour-list"
        << " range (reach = largest interaction gap + Verlet skin) and 3 the"
        << " cells of size >= R per direction that give each pair in range a"
        << " single image (minimum image, Lees-Edwards)";
    throw std::invalid_argument(msg.str());
}


void BoxRule::check
(
    const SizeDistribution& d,
    std::size_t N,
    double phi,
    const Vec3& aspect
) const
{
    const std::vector<double> a = d.radii(N);
    const Vec3 L = boxLengths(a, phi, aspect);
    try
    {
        check(L, a.back());
    }
    catch (const std::invalid_argument& err)
    {
        std::ostringstream msg;
        msg << err.what() << ".\n    ";
        const std::size_t nSmallest = smallestN(d, phi, aspect);
        if (nSmallest > 0)
        {
            const std::vector<double> b = d.radii(nSmallest);
            msg << "At volume fraction " << phi << " the smallest number of"
                << " particles that fits is N = " << nSmallest << " (box "
                << boxLengths(b, phi, aspect).transpose() << "; N = " << N
                << " gives the box above)";
        }
        else
        {
            // L scales as phi^(-1/3)
            const double ratio =
                L.minCoeff()/CellList::smallestLength(range(a.back()));
            msg << "These " << N << " radii fit at volume fractions up to "
                << phi*ratio*ratio*ratio << " (not " << phi << ")";
        }
        throw std::invalid_argument(msg.str());
    }
}

} // namespace suspension
