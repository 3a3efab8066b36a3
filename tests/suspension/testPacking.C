// Initial configurations: the particle population (counts, volumes, box)
// and random packings free of overlaps (paper section 3, tables 1 and 3)
#include "core/Parallel.H"
#include "packing/RandomPacking.H"
#include "packing/SizeDistribution.H"
#include "search/CellList.H"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

using namespace suspension;

namespace
{
    double sphereVolume(double a)
    {
        return 4.0/3.0*pi*a*a*a;
    }

    //- Number of radii equal to a
    std::size_t count(const std::vector<double>& radii, double a)
    {
        return static_cast<std::size_t>(std::count(radii.begin(), radii.end(), a));
    }

    //- Expect `f` to throw E with `what` in its message
    template<class E>
    void expectThrow(const std::function<void()>& f, const std::string& what)
    {
        try
        {
            f();
            ADD_FAILURE() << "no exception for " << what;
        }
        catch (const E& e)
        {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    }

    //- Smallest surface gap r - a_i - a_j over all pairs (minimum image)
    double smallestGap(const Particles& p, const LeesEdwardsBox& box)
    {
        double h = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            for (std::size_t j = i + 1; j < p.size(); ++j)
            {
                Vec3 r = p.x[j] - p.x[i];
                box.minimumImage(r);
                h = std::min(h, r.norm() - p.a[i] - p.a[j]);
            }
        }
        return h;
    }

    //- The packing holds the requested spheres at rest, in the box, at the
    //  volume fraction phi, and no pair is closer than minGap
    void expectValidPacking
    (
        const RandomPacking::Result& r,
        const std::vector<double>& radii,
        double phi,
        double rho,
        double minGap
    )
    {
        const Particles& p = r.particles;
        ASSERT_EQ(p.size(), radii.size());
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            EXPECT_EQ(p.id[i], static_cast<std::int64_t>(i));
            EXPECT_EQ(p.a[i], radii[i]);
            EXPECT_DOUBLE_EQ(p.m[i], sphereVolume(radii[i])*rho);
            EXPECT_EQ(p.u[i], Vec3::Zero());
            EXPECT_EQ(p.omega[i], Vec3::Zero());
            for (int d = 0; d < 3; ++d)
            {
                EXPECT_GE(p.x[i][d], 0);
                EXPECT_LT(p.x[i][d], r.box.L()[d]);
            }
        }
        EXPECT_EQ(r.box.shearRate(), 0);
        EXPECT_NEAR(p.solidVolume()/r.box.volume(), phi, 1e-12);

        // the acceptance test of the brief: no pair with |r| < a_i + a_j + minGap
        PairList close;
        bruteForcePairs(p, r.box, minGap, close);
        EXPECT_EQ(close.nPairs(), 0u);
        EXPECT_GE(smallestGap(p, r.box), minGap);
    }
}


// * * * * * * * * * * * * * * * Size distribution  * * * * * * * * * * * * //

TEST(SizeDistribution, MonodisperseRadiiAndCubicBox)
{
    const std::vector<double> radii = SizeDistribution::monodisperse(0.5).radii(100);
    ASSERT_EQ(radii.size(), 100u);
    EXPECT_EQ(count(radii, 0.5), 100u);

    // L^3 phi = N 4/3 pi a^3
    const Vec3 L = boxLengths(radii, 0.3);
    EXPECT_DOUBLE_EQ(L.x(), L.y());
    EXPECT_DOUBLE_EQ(L.x(), L.z());
    EXPECT_NEAR(L.prod()*0.3, 100*sphereVolume(0.5), 1e-12*L.prod());
}


TEST(SizeDistribution, BidisperseCountsOfTables1And3)
{
    // Table 1: a2/a1 = 1.4, V2/V1 = 1. N2/N1 = 1/1.4^3 = 0.364431,
    // N2 = 200 x 0.364431/1.364431 = 53.42 -> 53; 1000 -> 267.09 -> 267
    // Table 3: a2/a1 = 3, V2/V1 = 0.25. N2/N1 = 0.25/27 = 0.00925926,
    // N2 = 4096 x 0.00917431 = 37.58 -> 38; 65536 -> 601.25 -> 601
    struct Case { double sizeRatio, volumeRatio; std::size_t N, N2; };
    for (const Case& c : {Case{1.4, 1, 200, 53}, Case{1.4, 1, 1000, 267},
                          Case{3, 0.25, 4096, 38}, Case{3, 0.25, 65536, 601}})
    {
        const double a1 = 1;
        const double a2 = c.sizeRatio*a1;
        const std::vector<double> radii =
            SizeDistribution::bidisperse(a1, c.sizeRatio, c.volumeRatio).radii(c.N);
        ASSERT_EQ(radii.size(), c.N);
        EXPECT_EQ(count(radii, a2), c.N2) << "N = " << c.N;
        EXPECT_EQ(count(radii, a1), c.N - c.N2) << "N = " << c.N;
        EXPECT_TRUE(std::is_sorted(radii.begin(), radii.end()));

        // N2 rounds the exact count n* = N (V2/V1)/((a2/a1)^3 + V2/V1), so
        // the realised V2/V1 lies between its values at n* -+ 1/2
        const double nStar =
            c.N*c.volumeRatio/(std::pow(c.sizeRatio, 3) + c.volumeRatio);
        EXPECT_LE(std::abs(c.N2 - nStar), 0.5) << "N = " << c.N;
        const double V1 = (c.N - c.N2)*sphereVolume(a1);
        const double V2 = c.N2*sphereVolume(a2);
        auto ratio = [&](double n)
        {
            return n*sphereVolume(a2)/((c.N - n)*sphereVolume(a1));
        };
        EXPECT_GE(V2/V1, ratio(nStar - 0.5)) << "N = " << c.N;
        EXPECT_LE(V2/V1, ratio(nStar + 0.5)) << "N = " << c.N;
        EXPECT_GT(ratio(nStar + 0.5), c.volumeRatio);
        EXPECT_LT(ratio(nStar - 0.5), c.volumeRatio);

        // the box holds the solid volume at phi
        const double phi = 0.55;
        const Vec3 L = boxLengths(radii, phi);
        EXPECT_NEAR(phi*L.prod(), V1 + V2, 1e-12*(V1 + V2)) << "N = " << c.N;
    }
}


TEST(SizeDistribution, BidisperseKeepsOneOfEachSpecies)
{
    // N2 = round(10 x 1e-6/27/(1 + ...)) = 0 would lose species 2
    const std::vector<double> few = SizeDistribution::bidisperse(1, 3, 1e-6).radii(10);
    EXPECT_EQ(count(few, 3.0), 1u);
    EXPECT_EQ(count(few, 1.0), 9u);

    // N1 = round(10/(1 + 1e6/8)) = 0 would lose species 1
    const std::vector<double> many = SizeDistribution::bidisperse(1, 2, 1e6).radii(10);
    EXPECT_EQ(count(many, 1.0), 1u);
    EXPECT_EQ(count(many, 2.0), 9u);

    const std::vector<double> two = SizeDistribution::bidisperse(1, 1.4, 1).radii(2);
    EXPECT_EQ(count(two, 1.0), 1u);
    EXPECT_EQ(count(two, 1.4), 1u);
}


TEST(SizeDistribution, UniformRadiiAtQuantiles)
{
    const std::size_t N = 1000;
    const std::vector<double> radii = SizeDistribution::uniform(0.8, 1.2).radii(N);
    ASSERT_EQ(radii.size(), N);
    double mean = 0;
    double var = 0;
    for (double a : radii)
    {
        EXPECT_GT(a, 0.8);
        EXPECT_LT(a, 1.2);
        mean += a/N;
    }
    for (double a : radii)
    {
        var += (a - mean)*(a - mean)/N;
    }
    // midpoints of N equal bins: mean 1, variance 0.4^2/12 (1 - 1/N^2)
    EXPECT_NEAR(mean, 1.0, 1e-12);
    EXPECT_NEAR(var, 0.16/12*(1 - 1.0/(N*N)), 1e-12);
    EXPECT_TRUE(std::is_sorted(radii.begin(), radii.end()));
}


TEST(SizeDistribution, LogNormalMeanAndSd)
{
    const std::size_t N = 20000;
    const double mean = 1.5;
    const double sd = 0.3;
    const std::vector<double> radii = SizeDistribution::logNormal(mean, sd).radii(N);
    ASSERT_EQ(radii.size(), N);
    double m = 0;
    double var = 0;
    for (double a : radii)
    {
        m += a/N;
    }
    for (double a : radii)
    {
        var += (a - m)*(a - m)/N;
    }
    EXPECT_TRUE(std::is_sorted(radii.begin(), radii.end()));
    EXPECT_NEAR(m, mean, 1e-4*mean);
    EXPECT_NEAR(std::sqrt(var), sd, 1e-2*sd);

    // the median quantile (k + 1/2)/N = 1/2 of an odd sample is exp(mu)
    const std::vector<double> odd = SizeDistribution::logNormal(mean, sd).radii(101);
    const double s2 = std::log(1 + (sd/mean)*(sd/mean));
    EXPECT_NEAR(odd[50], mean*std::exp(-0.5*s2), 1e-12);
}


TEST(SizeDistribution, BoxAspect)
{
    const std::vector<double> radii = SizeDistribution::monodisperse(1).radii(50);
    const Vec3 L = boxLengths(radii, 0.4, Vec3(2, 1, 0.5));
    EXPECT_NEAR(L.x()/L.y(), 2, 1e-14);
    EXPECT_NEAR(L.z()/L.y(), 0.5, 1e-14);
    EXPECT_NEAR(0.4*L.prod(), 50*sphereVolume(1), 1e-12*L.prod());
}


TEST(SizeDistribution, RejectsBadInput)
{
    using E = std::invalid_argument;
    expectThrow<E>([]{ SizeDistribution::monodisperse(0); }, "a = 0");
    expectThrow<E>([]{ SizeDistribution::monodisperse(NAN); }, "a = nan");
    expectThrow<E>([]{ SizeDistribution::bidisperse(-1, 1.4, 1); }, "a1 = -1");
    expectThrow<E>([]{ SizeDistribution::bidisperse(1, 0, 1); }, "sizeRatio (a2/a1) = 0");
    expectThrow<E>([]{ SizeDistribution::bidisperse(1, 3, -0.25); }, "volumeRatio (V2/V1) = -0.25");
    expectThrow<E>([]{ SizeDistribution::uniform(0, 1); }, "aMin = 0");
    expectThrow<E>([]{ SizeDistribution::uniform(1, 0.5); }, "aMax = 0.5");
    expectThrow<E>([]{ SizeDistribution::logNormal(1, 0); }, "sd = 0");
    expectThrow<E>([]{ SizeDistribution::monodisperse(1).radii(0); }, "N = 0");
    expectThrow<E>([]{ SizeDistribution::bidisperse(1, 1.4, 1).radii(1); }, "N = 1");

    const std::vector<double> radii(10, 1.0);
    expectThrow<E>([&]{ boxLengths(radii, 0); }, "phi = 0");
    expectThrow<E>([&]{ boxLengths(radii, 0.74); }, "phi = 0.74");
    expectThrow<E>([&]{ boxLengths(radii, -0.1); }, "(0, 0.74)");
    expectThrow<E>([&]{ boxLengths(radii, 0.5, Vec3(1, 0, 1)); }, "aspect y = 0");
    expectThrow<E>([]{ boxLengths({}, 0.5); }, "number of radii = 0");
    expectThrow<E>([]{ boxLengths({1, -2}, 0.5); }, "radius = -2");
}


namespace
{
    //- Realised volume fraction of the spheres of radius a
    double volumeShare(const std::vector<double>& radii, double a)
    {
        return count(radii, a)*sphereVolume(a)/solidVolume(radii);
    }

    //- sum_k (V_k/V - v_k)^2 of counts c of radii a
    double misfit
    (
        const std::vector<std::size_t>& c,
        const std::vector<double>& a,
        const std::vector<double>& v
    )
    {
        double V = 0;
        for (std::size_t k = 0; k < c.size(); ++k)
        {
            V += c[k]*sphereVolume(a[k]);
        }
        double e = 0;
        for (std::size_t k = 0; k < c.size(); ++k)
        {
            e += std::pow(c[k]*sphereVolume(a[k])/V - v[k], 2);
        }
        return e;
    }
}


TEST(SizeDistribution, DiscreteTrimodalAtEqualVolumes)
{
    const std::vector<double> a{1, 1.5, 2};
    const std::vector<double> v{0.3333333, 0.3333333, 0.3333334};
    const SizeDistribution d =
        SizeDistribution::discrete({2, 1, 1.5}, {v[2], v[0], v[1]}, SizeDistribution::Fractions::volume);
    EXPECT_EQ(d.minN(), 3u);
    EXPECT_FALSE(d.fixedN());

    for (std::size_t N : {3u, 10u, 200u, 2000u, 2001u})
    {
        const std::vector<double> r = d.radii(N);
        ASSERT_EQ(r.size(), N);
        EXPECT_TRUE(std::is_sorted(r.begin(), r.end()));
        std::vector<std::size_t> c;
        for (double ak : a)
        {
            c.push_back(count(r, ak));
            EXPECT_GE(c.back(), 1u) << "N = " << N << ", a = " << ak;
        }
        EXPECT_EQ(c[0] + c[1] + c[2], N);

        // No single particle moved between classes brings the volume
        // fractions closer
        const double e = misfit(c, a, v);
        for (std::size_t i = 0; i < 3; ++i)
        {
            for (std::size_t j = 0; j < 3; ++j)
            {
                if (i == j || c[i] == 1)
                {
                    continue;
                }
                std::vector<std::size_t> t = c;
                --t[i];
                ++t[j];
                EXPECT_GE(misfit(t, a, v), e) << "N = " << N;
            }
        }
    }

    // N = 2000 and 300: within one particle of the largest radius (the
    // coarsest step); n ~ 1 : 1.5^-3 : 2^-3
    for (std::size_t N : {300u, 2000u})
    {
        const std::vector<double> r = d.radii(N);
        for (std::size_t k = 0; k < 3; ++k)
        {
            EXPECT_NEAR(volumeShare(r, a[k]), v[k], sphereVolume(2)/solidVolume(r))
                << "N = " << N << ", a = " << a[k];
        }
    }
    const std::vector<double> r = d.radii(2000);
    for (std::size_t k = 0; k < 3; ++k)
    {
        EXPECT_NEAR(volumeShare(r, a[k]), v[k], sphereVolume(a[k])/solidVolume(r))
            << "a = " << a[k];
    }
    const double n1 = 2000/(1 + std::pow(1.5, -3) + std::pow(2, -3));
    EXPECT_NEAR(static_cast<double>(count(r, 1)), n1, 1.0);
}


TEST(SizeDistribution, DiscreteNumberFractions)
{
    // Half the spheres of each radius: 50 and 50, volume fractions 1:8
    const std::vector<double> r = SizeDistribution::discrete
    (
        {1, 2}, {0.5, 0.5}, SizeDistribution::Fractions::number
    ).radii(100);
    EXPECT_EQ(count(r, 1), 50u);
    EXPECT_EQ(count(r, 2), 50u);
    EXPECT_NEAR(volumeShare(r, 2), 8.0/9.0, 1e-14);
}


TEST(SizeDistribution, ListIsTheGivenRadiiSorted)
{
    const SizeDistribution d = SizeDistribution::list({1.2, 0.8, 1});
    EXPECT_TRUE(d.fixedN());
    EXPECT_EQ(d.minN(), 3u);
    EXPECT_EQ(d.radii(3), (std::vector<double>{0.8, 1, 1.2}));
    expectThrow<std::invalid_argument>([&]{ d.radii(4); }, "holds 3 radii, not N = 4");
}


TEST(SizeDistribution, DiscreteAndListRejectBadInput)
{
    using E = std::invalid_argument;
    using F = SizeDistribution::Fractions;
    expectThrow<E>([]{ SizeDistribution::discrete({1, 2}, {-0.1, 1.1}, F::volume); }, "volume fraction = -0.1");
    expectThrow<E>([]{ SizeDistribution::discrete({1, 2}, {0, 1}, F::number); }, "number fraction = 0");
    expectThrow<E>([]{ SizeDistribution::discrete({1, 2}, {0.5, 0.4}, F::volume); }, "sum to 0.9, not to 1");
    expectThrow<E>([]{ SizeDistribution::discrete({1, 0}, {0.5, 0.5}, F::volume); }, "radius = 0");
    expectThrow<E>([]{ SizeDistribution::discrete({1, 1}, {0.5, 0.5}, F::volume); }, "radius 1 is given twice");
    expectThrow<E>([]{ SizeDistribution::discrete({1, 2}, {1}, F::volume); }, "2 radii but 1 volume fraction");
    expectThrow<E>([]{ SizeDistribution::discrete({}, {}, F::volume); }, "number of radii = 0");
    expectThrow<E>([]{ SizeDistribution::discrete({1, 2, 3}, {0.2, 0.3, 0.5}, F::volume).radii(2); }, "N = 2");
    expectThrow<E>([]{ SizeDistribution::list({}); }, "number of radii = 0");
    expectThrow<E>([]{ SizeDistribution::list({1, -1}); }, "radius = -1");
}


TEST(SizeDistribution, DescribeRadiiInUse)
{
    const std::vector<double> r = SizeDistribution::discrete
    (
        {1, 2}, {0.5, 0.5}, SizeDistribution::Fractions::number
    ).radii(4);
    EXPECT_EQ(describeRadii(r), "2 radii: 1 (n = 2, volume fraction 0.111111), 2 (n = 2, volume fraction 0.888889)");
    EXPECT_EQ(describeRadii({1.28, 1.28}), "1 radius: 1.28 (n = 2, volume fraction 1)");
    EXPECT_EQ(describeRadii({1, 2, 3}, 2), "3 distinct radii in [1, 3], mean 2");
}


// * * * * * * * * * * * * * * * * * BoxRule  * * * * * * * * * * * * * * * //

TEST(BoxRule, SmallestNOfTheSolverIsThatOfThePacking)
{
    // a2/a1 = 5, V2/V1 = 1, phi = 0.5, reach 0.15 (lubrication + skin):
    // R = 2 x 5 + 0.15 = 10.15, so every box length must be >= 30.45
    const BoxRule rule(0.15);
    EXPECT_DOUBLE_EQ(rule.range(5), 10.15);
    const SizeDistribution d = SizeDistribution::bidisperse(1, 5, 1);
    const std::size_t N = rule.smallestN(d, 0.5, Vec3::Ones());
    ASSERT_GT(N, 2u);

    // Independently: the cube side (V_s/phi)^(1/3) against 3 R
    const auto side = [&](std::size_t n)
    {
        return std::cbrt(solidVolume(d.radii(n))/0.5);
    };
    EXPECT_GE(side(N), 3*10.15);
    EXPECT_LT(side(N - 1), 3*10.15*(1 + 1e-9));
    EXPECT_TRUE(rule.fits(Vec3::Constant(side(N)), 5));
    EXPECT_FALSE(rule.fits(Vec3::Constant(side(N - 1)), 5));

    // The error at N - 1 names N, and why
    try
    {
        rule.check(d, N - 1, 0.5, Vec3::Ones());
        ADD_FAILURE() << "no exception at N = " << N - 1;
    }
    catch (const std::invalid_argument& e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("smallest number of particles that fits is N = " + std::to_string(N) + " "), std::string::npos) << what;
        EXPECT_NE(what.find("3 R = 30.45"), std::string::npos) << what;
        EXPECT_NE(what.find("R = 2 a_max + reach = 2*5 + 0.15 = 10.15"), std::string::npos) << what;
        EXPECT_NE(what.find("Lees-Edwards"), std::string::npos) << what;
    }
    EXPECT_NO_THROW(rule.check(d, N, 0.5, Vec3::Ones()));

    // The packing with the same reach refuses N - 1 by the same rule and
    // takes N (it then stops at its step limit, not at the box)
    RandomPacking::Params p;
    p.phi = 0.5;
    p.reach = 0.15;
    p.maxIterations = 1;
    expectThrow<std::invalid_argument>
    (
        [&]{ RandomPacking(p).pack(d.radii(N - 1), 1); },
        "BoxRule: the box"
    );
    EXPECT_THROW(RandomPacking(p).pack(d.radii(N), 1), PackingError);
}


TEST(BoxRule, ListGivesTheLargestVolumeFraction)
{
    // 10 unit spheres at phi = 0.5: side 4.37 < 3 (2 + 0.1) = 6.3
    const BoxRule rule(0.1);
    const SizeDistribution d = SizeDistribution::list(std::vector<double>(10, 1));
    EXPECT_EQ(rule.smallestN(d, 0.5, Vec3::Ones()), 0u);
    const double phiFits = 10*sphereVolume(1)/std::pow(6.3, 3);
    try
    {
        rule.check(d, 10, 0.5, Vec3::Ones());
        ADD_FAILURE() << "no exception";
    }
    catch (const std::invalid_argument& e)
    {
        const std::string what = e.what();
        const std::size_t at = what.find("fit at volume fractions up to ");
        ASSERT_NE(at, std::string::npos) << what;
        EXPECT_NEAR(std::stod(what.substr(at + 30)), phiFits, 1e-5) << what;
    }
    expectThrow<std::invalid_argument>([]{ BoxRule(-1); }, "reach (largest interaction gap + skin) = -1");
}


// * * * * * * * * * * * * * * * * * Packing  * * * * * * * * * * * * * * * //

namespace
{
    RandomPacking::Params params(double phi, std::uint64_t seed = 1)
    {
        RandomPacking::Params p;
        p.phi = phi;
        p.seed = seed;
        p.reach = 0.3;      // lubrication and skin of a typical run
        return p;
    }
}


TEST(Packing, Table1BidisperseAtPhi060)
{
    // a2/a1 = 1.4, V2/V1 = 1, N = 200, phi = 0.6 (paper, table 1)
    const std::vector<double> radii =
        SizeDistribution::bidisperse(1, 1.4, 1).radii(200);
    const RandomPacking packing(params(0.6));
    const RandomPacking::Result r = packing.pack(radii, 2.5);
    expectValidPacking(r, radii, 0.6, 2.5, 1e-6);
    EXPECT_GE(r.statistics.stages, 7u);     // 0.3, 0.35, ..., 0.6
    EXPECT_GT(r.statistics.iterations, 0u);
}


TEST(Packing, RemovesTheOverlapsOfACarelessStart)
{
    // A packing at phi = 0.60 with every radius then made 2% larger
    // (phi = 0.637, overlaps up to 2% of a_i + a_j): the relaxation keeps
    // ids, radii and masses, moves the centres by less than a diameter
    // (measured 1.3 a_1) and leaves no gap below minGap; 10% larger (phi = 0.80) cannot be freed
    const std::vector<double> radii =
        SizeDistribution::bidisperse(1, 1.4, 1).radii(200);
    const RandomPacking packing(params(0.6));
    const RandomPacking::Result r = packing.pack(radii, 2.5);
    for (const double inflate : {1.02, 1.1})
    {
        Particles p = r.particles;
        for (double& a : p.a)
        {
            a *= inflate;
        }
        ASSERT_LT(smallestGap(p, r.box), -0.01);
        const Particles before = p;
        if (inflate > 1.05)
        {
            expectThrow<PackingError>
            (
                [&]() { packing.removeOverlaps(p, r.box.L()); }, "jam"
            );
            continue;
        }
        const double moved = packing.removeOverlaps(p, r.box.L());
        EXPECT_GE(smallestGap(p, r.box), 1e-6);
        EXPECT_GT(moved, 0);
        EXPECT_LT(moved, 2.0);
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            EXPECT_EQ(p.id[i], before.id[i]);
            EXPECT_EQ(p.a[i], before.a[i]);
            EXPECT_EQ(p.m[i], before.m[i]);
        }
    }
}


TEST(Packing, Table3BidisperseAtPhi055)
{
    // a2/a1 = 3, V2/V1 = 0.25 (paper, table 3) at N = 1000, phi = 0.55
    const std::vector<double> radii =
        SizeDistribution::bidisperse(1, 3, 0.25).radii(1000);
    const RandomPacking::Result r = RandomPacking(params(0.55)).pack(radii, 1);
    expectValidPacking(r, radii, 0.55, 1, 1e-6);
}


TEST(Packing, ReproducibleWithSeed)
{
    const std::vector<double> radii =
        SizeDistribution::bidisperse(1, 1.4, 1).radii(200);
    const RandomPacking::Result a = RandomPacking(params(0.5, 7)).pack(radii, 1);
    const RandomPacking::Result b = RandomPacking(params(0.5, 7)).pack(radii, 1);
    const RandomPacking::Result c = RandomPacking(params(0.5, 8)).pack(radii, 1);
    EXPECT_EQ(a.particles.x, b.particles.x);
    EXPECT_EQ(a.statistics.iterations, b.statistics.iterations);
    std::size_t moved = 0;
    for (std::size_t i = 0; i < radii.size(); ++i)
    {
        moved += (a.particles.x[i] - c.particles.x[i]).norm() > 1;
    }
    EXPECT_GT(moved, radii.size()/2);

    // Threads share the work (core/Parallel.H): the packing is bitwise the
    // same on one and on two threads
    const std::vector<double> many = SizeDistribution::monodisperse(1).radii(1000);
    const std::size_t threshold = setParallelMinParticles(0);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const RandomPacking::Result d = RandomPacking(params(0.3, 3)).pack(many, 1);
    omp_set_num_threads(2);
    const RandomPacking::Result e = RandomPacking(params(0.3, 3)).pack(many, 1);
    omp_set_num_threads(threads);
    setParallelMinParticles(threshold);
    EXPECT_EQ(d.particles.x, e.particles.x);
}


TEST(Packing, PolydisperseAspectAndLargeGap)
{
    // uniform radii in a 2:1:1 box, gaps of at least 0.05 a_min
    const std::vector<double> radii = SizeDistribution::uniform(0.8, 1.2).radii(300);
    RandomPacking::Params p = params(0.5);
    p.aspect = Vec3(2, 1, 1);
    p.minGap = 0.05;
    const RandomPacking::Result r = RandomPacking(p).pack(radii, 1);
    expectValidPacking(r, radii, 0.5, 1, 0.05*0.8);
    EXPECT_NEAR(r.box.L().x()/r.box.L().y(), 2, 1e-14);

    // log-normal radii
    const std::vector<double> logNormal = SizeDistribution::logNormal(1, 0.15).radii(300);
    const RandomPacking::Result q = RandomPacking(params(0.55)).pack(logNormal, 1);
    expectValidPacking(q, logNormal, 0.55, 1, 1e-6*logNormal.front());
}


TEST(Packing, JammedTargetReportsPhiReached)
{
    // the 1.4 mixture jams near phi = 0.64; 0.70 is out of reach
    const std::vector<double> radii =
        SizeDistribution::bidisperse(1, 1.4, 1).radii(200);
    try
    {
        RandomPacking(params(0.70)).pack(radii, 1);
        FAIL() << "no exception";
    }
    catch (const PackingError& e)
    {
        EXPECT_GT(e.phiReached(), 0.6);
        EXPECT_LT(e.phiReached(), 0.70);
        const std::string what = e.what();
        EXPECT_NE(what.find("could not pack 200 spheres at phi = 0.7"), std::string::npos) << what;
        EXPECT_NE(what.find("densest overlap-free stage reached phi = "), std::string::npos) << what;
    }
}


TEST(Packing, StepLimitReportsPhiReached)
{
    const std::vector<double> radii = SizeDistribution::monodisperse(1).radii(200);
    RandomPacking::Params p = params(0.5);
    p.maxIterations = 5;
    try
    {
        RandomPacking(p).pack(radii, 1);
        FAIL() << "no exception";
    }
    catch (const PackingError& e)
    {
        EXPECT_EQ(e.phiReached(), 0);
        EXPECT_NE(std::string(e.what()).find("FIRE step limit"), std::string::npos) << e.what();
    }
}


TEST(Packing, RejectsBadInput)
{
    using E = std::invalid_argument;
    expectThrow<E>([]{ RandomPacking(params(0)); }, "phi = 0");
    expectThrow<E>([]{ RandomPacking(params(0.8)); }, "phi = 0.8");
    expectThrow<E>([]{ RandomPacking(RandomPacking::Params()); }, "phi = nan");
    RandomPacking::Params p = params(0.5);
    p.minGap = -1;
    expectThrow<E>([&]{ RandomPacking{p}; }, "minGap = -1");
    p = params(0.5);
    p.aspect = Vec3(1, 1, -1);
    expectThrow<E>([&]{ RandomPacking{p}; }, "aspect z = -1");
    p = params(0.5);
    p.maxStageIterations = 0;
    expectThrow<E>([&]{ RandomPacking{p}; }, "maxStageIterations = 0");

    const RandomPacking packing(params(0.5));
    const std::vector<double> radii = SizeDistribution::monodisperse(1).radii(200);
    expectThrow<E>([&]{ packing.pack(radii, 0); }, "rho = 0");
    expectThrow<E>([&]{ packing.pack({}, 1); }, "number of radii = 0");

    // 20 spheres with a2/a1 = 3: the box is shorter than 3 cut-offs
    const std::vector<double> few = SizeDistribution::bidisperse(1, 3, 0.25).radii(20);
    expectThrow<E>([&]{ packing.pack(few, 1); }, "too small");
}
