// Moduli of an oscillatory test from samples (stress/Oscillation.H)
#include "stress/Oscillation.H"
#include "core/Vector.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace suspension;

namespace
{
    //- Samples of gamma = g0 + gamma0 sin(omega t) and of a stress with
    //  moduli Gp, Gpp, a third harmonic of relative size a3 and a mean
    struct Samples
    {
        std::vector<double> t, gamma, sigma;
    };

    Samples synthetic
    (
        double omega, double gamma0, double Gp, double Gpp, double a3,
        double dt, double tEnd, double t0 = 0
    )
    {
        Samples s;
        for (double t = t0; t <= tEnd; t += dt)
        {
            const double w = omega*t;
            s.t.push_back(t);
            s.gamma.push_back(0.3 + gamma0*std::sin(w));
            const double first = gamma0*(Gp*std::sin(w) + Gpp*std::cos(w));
            s.sigma.push_back
            (
                2.0 + first + a3*gamma0*std::hypot(Gp, Gpp)*std::sin(3*w + 0.4)
            );
        }
        return s;
    }
}


TEST(Oscillation, MomentsOfAKnownResponse)
{
    // G' = 3, G'' = 5 and a third harmonic of a quarter of the first: the
    // moduli, eta', eta'' and I3/I1 to the trapezoid's accuracy, whole
    // cycles only, from samples not aligned with the cycles
    const double omega = 0.7, gamma0 = 0.05;
    const double T = 2*pi/omega;
    const Samples s = synthetic(omega, gamma0, 3, 5, 0.25, T/397, 6.3*T, 0.13);
    const Oscillation osc(s.t, s.gamma, s.sigma, omega, 1);
    ASSERT_EQ(osc.cycles().size(), 5u);         // [T, 2T] ... [5T, 6T]
    EXPECT_EQ(osc.cycles().front().n, 1u);
    EXPECT_EQ(osc.nUsed(), 5u);                 // cycle 0 is the start-up
    for (const Oscillation::Cycle& c : osc.cycles())
    {
        EXPECT_NEAR(c.gamma0, gamma0, 1e-4*gamma0);
        EXPECT_NEAR(c.Gp, 3, 1e-3);
        EXPECT_NEAR(c.Gpp, 5, 1e-3);
        EXPECT_NEAR(c.etaP, 5/omega, 2e-3);
        EXPECT_NEAR(c.etaPP, 3/omega, 2e-3);
        EXPECT_NEAR(c.I3, 0.25, 1e-3);
    }
    EXPECT_NEAR(osc.estimate(&Oscillation::Cycle::Gpp).mean, 5, 1e-3);
    EXPECT_LT(osc.estimate(&Oscillation::Cycle::Gpp).error, 1e-3);
}


TEST(Oscillation, ErrorBarIsTheScatterOfTheCycles)
{
    // Noise on the stress: the cycles scatter, and the error bar is their
    // standard deviation over sqrt(n); the mean is within a few of them
    const double omega = 1.0, gamma0 = 1.0;
    Samples s = synthetic(omega, gamma0, 0, 2, 0, 2*pi/200, 2*pi*21.5);
    std::mt19937 gen(3);
    std::normal_distribution<double> noise(0, 0.5);
    for (double& x : s.sigma)
    {
        x += noise(gen);
    }
    const Oscillation osc(s.t, s.gamma, s.sigma, omega, 1);
    ASSERT_EQ(osc.cycles().size(), 21u);
    ASSERT_EQ(osc.nUsed(), 20u);
    const Oscillation::Estimate e = osc.estimate(&Oscillation::Cycle::Gpp);
    double ss = 0;
    for (std::size_t k = 1; k < osc.cycles().size(); ++k)
    {
        ss += std::pow(osc.cycles()[k].Gpp - e.mean, 2);
    }
    EXPECT_DOUBLE_EQ(e.error, std::sqrt(ss/19/20));
    EXPECT_GT(e.error, 0.005);
    EXPECT_LT(std::abs(e.mean - 2), 4*e.error);
}


TEST(Oscillation, BadInputThrows)
{
    const std::vector<double> t{0, 1}, g{0, 1}, s{0, 1};
    EXPECT_THROW(Oscillation(t, g, s, 0, 0), std::invalid_argument);
    EXPECT_THROW(Oscillation(t, g, {0}, 1, 0), std::invalid_argument);
    EXPECT_EQ(Oscillation(t, g, s, 1, 0).cycles().size(), 0u);
}


TEST(Oscillation, DriftOfTheStrainIsTakenOut)
{
    // A mean rate 0.2 under the oscillation (OpenFOAM's sine with a
    // level): the strain drifts by 0.2 T a cycle, and the moduli are those
    // without the drift
    const double omega = 1.0, gamma0 = 0.3;
    Samples s = synthetic(omega, gamma0, 3, 5, 0, 2*pi/400, 2*pi*4.5);
    for (std::size_t k = 0; k < s.t.size(); ++k)
    {
        s.gamma[k] += 0.2*s.t[k];
    }
    const Oscillation osc(s.t, s.gamma, s.sigma, omega, 1);
    EXPECT_NEAR(osc.estimate(&Oscillation::Cycle::Gp).mean, 3, 1e-3);
    EXPECT_NEAR(osc.estimate(&Oscillation::Cycle::Gpp).mean, 5, 1e-3);
    EXPECT_NEAR(osc.estimate(&Oscillation::Cycle::gamma0).mean, gamma0, 1e-4);
    // no oscillation at all
    std::vector<double> flat(s.t.size(), 1.0);
    EXPECT_THROW(Oscillation(s.t, flat, s.sigma, omega, 0), std::invalid_argument);
}
