// Stokes drag with Faxen corrections (eqs. A.1, 9a): Stokes' law, the
// torque on a spinning sphere, Faxen's laws in a wavy flow, Einstein's
// viscosity and the relaxation times
#include "forces/StokesDrag.H"
#include "flow/ShearFlow.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

using namespace suspension;

namespace
{
    //- Finite-difference Laplacian of a field f at x (second-order stencil)
    template<class T, class F>
    T laplacianFD(const F& f, const Vec3& x, double h)
    {
        T lap = T::Zero();
        for (int k = 0; k < 3; ++k)
        {
            Vec3 e = Vec3::Zero();
            e[k] = h;
            lap += (f(x + e) - 2*f(x) + f(x - e))/(h*h);
        }
        return lap;
    }
}


TEST(Drag, SphereMovingInUniformFlow)
{
    // Stokes' law F = 6 pi eta a (U - u); no torque or stresslet in a
    // uniform flow
    const double eta = 1.3;
    const double a = 0.8;
    const StokesDrag drag(StokesDrag::Params{eta});
    FlowSample flow;
    flow.U = Vec3(1.0, -2.0, 0.5);
    const Vec3 u(0.3, 0.1, -0.4);

    const StokesDrag::Result r = drag.eval(a, u, Vec3::Zero(), flow);

    const Vec3 expected = 6*pi*eta*a*Vec3(0.7, -2.1, 0.9);
    EXPECT_NEAR((r.F - expected).norm(), 0, 1e-13*expected.norm());
    EXPECT_EQ(r.T.norm(), 0);
    EXPECT_EQ(r.S.norm(), 0);
}


TEST(Drag, TorqueOnSpinningSphere)
{
    const double eta = 0.9;
    const double a = 1.7;
    const StokesDrag drag(StokesDrag::Params{eta});

    // Quiescent fluid: T = -8 pi eta a^3 omega (Kirchhoff)
    const Vec3 omega(0.2, -1.1, 0.4);
    const StokesDrag::Result quiescent =
        drag.eval(a, Vec3::Zero(), omega, FlowSample());
    const Vec3 expected = -8*pi*eta*a*a*a*omega;
    EXPECT_NEAR((quiescent.T - expected).norm(), 0, 1e-13*expected.norm());
    EXPECT_EQ(quiescent.F.norm(), 0);

    // Simple shear U = (gammaDot y, 0, 0): a free sphere advected with the
    // flow spins at -gammaDot/2 e_z (Jeffery 1922) and feels nothing
    const double gammaDot = 2.5;
    const ShearFlow shear(gammaDot);
    const Vec3 x(0.3, 1.2, -0.7);
    const StokesDrag::Result free = drag.eval
    (
        a, Vec3(gammaDot*x.y(), 0, 0), Vec3(0, 0, -gammaDot/2), shear.sample(x)
    );
    EXPECT_NEAR(free.F.norm(), 0, 1e-13);
    EXPECT_NEAR(free.T.norm(), 0, 1e-13);
}


TEST(Drag, FaxenForceFreeSphereInWavyFlow)
{
    // Faxen's laws: a sphere moving with u = U + a^2/6 lap U and spinning
    // with curl(U)/2 is force- and torque-free; its stresslet is
    // 20/3 pi eta a^3 (E + a^2/10 lap E). Derivatives by finite differences
    // of the sampled velocity, not from the flow's own derivatives.
    const double Ly = 12.0;
    const ShearFlow flow(1.0, 20.0, 1.0, Ly);     // paper Table 3, YW
    const StokesDrag drag;
    const double h = 1e-3;

    auto U = [&](const Vec3& p) { return Vec3(flow.sample(p).U); };
    auto gradU = [&](const Vec3& p) { return Mat3(flow.sample(p).gradU); };

    for (const double a : {1.0, 3.0})
    {
        for (const double y : {0.4, 2.9, 5.3, 8.8, 11.1})
        {
            const Vec3 x(1.7, y, -0.6);
            const Vec3 lapU = laplacianFD<Vec3>(U, x, h);
            Mat3 G;
            for (int k = 0; k < 3; ++k)
            {
                Vec3 e = Vec3::Zero();
                e[k] = h;
                G.row(k) = ((U(x + e) - U(x - e))/(2*h)).transpose();
            }
            const Vec3 Omega =
                0.5*Vec3(G(1, 2) - G(2, 1), G(2, 0) - G(0, 2), G(0, 1) - G(1, 0));
            const Mat3 E = 0.5*(G + G.transpose());
            const Mat3 lapG = laplacianFD<Mat3>(gradU, x, h);
            const Mat3 lapE = 0.5*(lapG + lapG.transpose());

            const Vec3 u = U(x) + a*a/6*lapU;
            const StokesDrag::Result r = drag.eval(a, u, Omega, flow.sample(x));

            // Scale of the Faxen term: the drag if it were left out
            const double faxenDrag = pi*a*a*a*lapU.norm();
            ASSERT_GT(faxenDrag, 1.0);
            EXPECT_NEAR(r.F.norm(), 0, 1e-6*faxenDrag) << "a " << a << " y " << y;
            EXPECT_NEAR(r.T.norm(), 0, 1e-6*8*pi*a*a*a*Omega.norm());

            const Mat3 S = 20.0/3.0*pi*a*a*a*(E + a*a/10*lapE);
            EXPECT_NEAR((r.S - S).norm(), 0, 1e-6*S.norm());
        }
    }
}


TEST(Drag, EinsteinViscosityFromStressletSum)
{
    // N force- and torque-free spheres in simple shear: eq. (8) gives
    // Sigma_xy/(eta gammaDot) = 1 + 5/2 phi (Einstein 1906)
    const double eta = 1.7;
    const double gammaDot = 0.8;
    const double L = 20.0;
    const ShearFlow flow(gammaDot);
    const StokesDrag drag(StokesDrag::Params{eta});

    std::mt19937 gen(7);
    std::uniform_real_distribution<double> pos(0, L);
    std::uniform_real_distribution<double> radius(0.5, 1.5);

    Mat3 sumS = Mat3::Zero();
    double solidVolume = 0;
    for (int i = 0; i < 50; ++i)
    {
        const Vec3 x(pos(gen), pos(gen), pos(gen));
        const double a = radius(gen);
        const FlowSample s = flow.sample(x);
        const StokesDrag::Result r = drag.eval(a, s.U, s.Omega(), s);
        ASSERT_NEAR(r.F.norm(), 0, 1e-12);
        ASSERT_NEAR(r.T.norm(), 0, 1e-12);
        sumS += r.S;
        solidVolume += 4.0/3.0*pi*a*a*a;
    }
    const double V = L*L*L;
    const double phi = solidVolume/V;

    const double sigmaXY = eta*gammaDot + sumS(0, 1)/V;         // eq. (8)
    EXPECT_NEAR(sigmaXY/(eta*gammaDot), 1 + 2.5*phi, 1e-13);
    // Pure shear: no normal stresses from the drag stresslets
    EXPECT_NEAR(sumS.diagonal().norm(), 0, 1e-12);
}


TEST(Drag, RelaxationTimes)
{
    // m du/dt = F = -6 pi eta a u in a quiescent fluid: tau = m |u|/|F|
    const double eta = 1.3;
    const double a = 2.0;
    const double m = 4.0/3.0*pi*a*a*a*1e-3;
    const double I = 0.4*m*a*a;
    const StokesDrag drag(StokesDrag::Params{eta});
    const Vec3 u(0.5, 0, 0);
    const Vec3 omega(0, 0.3, 0);
    const StokesDrag::Result r = drag.eval(a, u, omega, FlowSample());

    const double tauU = m*u.norm()/r.F.norm();
    const double tauOmega = I*omega.norm()/r.T.norm();
    EXPECT_NEAR(StokesDrag::relaxationTime(m, a, eta), tauU, 1e-13*tauU);
    EXPECT_NEAR
    (
        StokesDrag::rotationalRelaxationTime(I, a, eta), tauOmega, 1e-13*tauOmega
    );
}


TEST(Drag, RejectsBadViscosity)
{
    EXPECT_THROW(StokesDrag(StokesDrag::Params{0}), std::invalid_argument);
    EXPECT_THROW(StokesDrag(StokesDrag::Params{NAN}), std::invalid_argument);
    try
    {
        StokesDrag(StokesDrag::Params{-1});
        FAIL() << "no exception";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("eta = -1"), std::string::npos) << e.what();
    }
}
