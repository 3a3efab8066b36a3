// Analytic ambient flow (eq. 17): derivatives against central differences
#include "flow/ShearFlow.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace suspension;

namespace
{
    // Central difference of f along axis i at x
    template<class F>
    Vec3 centralDiff(const F& f, const Vec3& x, int i, double h)
    {
        Vec3 e = Vec3::Zero();
        e[i] = h;
        return (f(x + e) - f(x - e))/(2*h);
    }
}


TEST(ShearFlow, WavyDerivativesMatchFiniteDifferences)
{
    const double Ly = 17.3;
    const ShearFlow flow(1.0, 20.0, 1.0, Ly);
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> pos(0, Ly);
    const double h = 1e-4;

    for (int s = 0; s < 20; ++s)
    {
        const Vec3 x(pos(gen), pos(gen), pos(gen));
        const FlowSample f = flow.sample(x);

        auto U = [&](const Vec3& p) { return Vec3(flow.sample(p).U); };
        auto lapU = [&](const Vec3& p) { return Vec3(flow.sample(p).laplacianU); };

        Vec3 lapFD = Vec3::Zero();
        for (int i = 0; i < 3; ++i)
        {
            const Vec3 dU = centralDiff(U, x, i, h);
            const Vec3 dLap = centralDiff(lapU, x, i, h);
            for (int j = 0; j < 3; ++j)
            {
                EXPECT_NEAR(f.gradU(i, j), dU[j], 1e-5*(1 + std::abs(dU[j])));
                EXPECT_NEAR(f.gradLaplacianU(i, j), dLap[j], 1e-5*(1 + std::abs(dLap[j])));
            }
            Vec3 e = Vec3::Zero();
            e[i] = h;
            lapFD += (U(x + e) - 2*U(x) + U(x - e))/(h*h);
        }
        EXPECT_NEAR((f.laplacianU - lapFD).norm(), 0, 1e-4*(1 + lapFD.norm()));
    }
}


TEST(ShearFlow, StrainAndRotationOfSimpleShear)
{
    const ShearFlow flow(2.0);
    const FlowSample f = flow.sample(Vec3(0.3, 1.7, -0.2));

    // U = (2y, 0, 0): E_xy = E_yx = 1, Omega = curl(U)/2 = (0, 0, -1)
    Mat3 E = Mat3::Zero();
    E(0, 1) = E(1, 0) = 1.0;
    EXPECT_NEAR((f.E() - E).norm(), 0, 1e-14);
    EXPECT_NEAR((f.Omega() - Vec3(0, 0, -1)).norm(), 0, 1e-14);
    EXPECT_NEAR(f.U.x(), 3.4, 1e-14);
}


TEST(ShearFlow, WaveIsPeriodicInY)
{
    const double Ly = 9.0;
    const ShearFlow flow(1.0, 5.0, 2.0, Ly);
    const Vec3 x(1, 2.2, 3);
    const FlowSample a = flow.sample(x);
    const FlowSample b = flow.sample(x + Vec3(0, Ly, 0));
    // Only the mean shear jumps across a period: U_x(y + Ly) = U_x(y) + gammaDot Ly
    EXPECT_NEAR(b.U.x() - a.U.x(), 1.0*Ly, 1e-11);
    EXPECT_NEAR((b.gradU - a.gradU).norm(), 0, 1e-11);
    EXPECT_NEAR((b.laplacianU - a.laplacianU).norm(), 0, 1e-11);
}


TEST(ShearFlow, RejectsNonPositiveHeight)
{
    EXPECT_THROW(ShearFlow(1.0, 1.0, 1.0, 0.0), std::invalid_argument);
}
