// Electro-chemical forces: screened repulsion (eq. 6), regularised van der
// Waals attraction (eq. 7), their stresslets (9d) and their scales from the
// paper's groups (eq. 14)
#include "forces/ElectroChemicalScales.H"
#include "forces/ElectrostaticRepulsion.H"
#include "forces/VanDerWaalsAttraction.H"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace suspension;

namespace
{
    const double ai = 1.0;
    const double aj = 1.4;
    const double abar = 2*ai*aj/(ai + aj);
    const Vec3 n = Vec3(0.6, -0.48, 0.64);      // unit

    //- Pair at surface gap h along n
    PairGeometry atGap(double h)
    {
        return PairGeometry::make((ai + aj + h)*n, ai, aj);
    }

    //- Central difference of U at h
    template<class F>
    double derivative(const F& U, double h, double dh)
    {
        return (U(h + dh) - U(h - dh))/(2*dh);
    }

    //- Swapping i and j reverses the force and keeps the stresslet; the
    //  stresslet is -r_ij (x) F_ij with r_ij = x_i - x_j
    template<class Kernel>
    void expectPairSymmetryAndVirial(const Kernel& kernel, double h)
    {
        const PairGeometry g = atGap(h);
        const PairForce fij = kernel.eval(g);
        const PairForce fji = kernel.eval(PairGeometry::make(-g.r, aj, ai));
        const double scale = fij.F.norm();
        EXPECT_NEAR((fji.F + fij.F).norm(), 0, 1e-14*scale);
        EXPECT_NEAR((fji.S - fij.S).norm(), 0, 1e-14*scale);
        const Vec3 rij = -g.r;
        EXPECT_NEAR((fij.S + rij*fij.F.transpose()).norm(), 0, 1e-14*scale);
        EXPECT_EQ(fij.Ti.norm() + fij.Tj.norm(), 0);
    }

    //- The exception message of make() names the text `what`
    template<class Make>
    void expectThrowNaming(const Make& make, const std::string& what)
    {
        try
        {
            make();
            ADD_FAILURE() << "no exception for " << what;
        }
        catch (const std::invalid_argument& e)
        {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    }
}


// * * * * * * * * * * * * * * * Repulsion  * * * * * * * * * * * * * * * * //

namespace
{
    ElectrostaticRepulsion::Params repulsionParams(double FER, double lambdaD)
    {
        ElectrostaticRepulsion::Params p;
        p.FER = FER;
        p.lambdaD = lambdaD;
        return p;
    }
}


TEST(Repulsion, MatchesEq6AtSeveralGaps)
{
    const double FER = 0.7;
    const double lambdaD = 0.02;
    const ElectrostaticRepulsion rep(repulsionParams(FER, lambdaD));

    // Reference at the gap the geometry holds (|r| - a_i - a_j rounds h)
    for (const double h : {-0.05, -1e-3, 0.0, 1e-3, 0.02, 0.1, 0.3})
    {
        const PairGeometry g = atGap(h);
        const double expected = FER*abar*std::exp(-std::max(g.h, 0.0)/lambdaD);
        const Vec3 F = rep.eval(g).F;
        EXPECT_NEAR((F + expected*n).norm(), 0, 1e-14*expected) << "h = " << h;
    }

    // Cut at 20 lambda_D (paper Fig. 3): the pair loop calls the kernel
    // for h < gap() only
    EXPECT_DOUBLE_EQ(rep.gap(), 20*lambdaD);
    EXPECT_GT(rep.eval(atGap(20*lambdaD*(1 - 1e-9))).F.norm(), 0);
}


TEST(Repulsion, ForceIsMinusGradientOfPotential)
{
    // U(h) = F_ER abar lambda_D exp(-h/lambda_D); the force on i along n is
    // dU/dh (a repulsion pushes i away from j)
    const double FER = 1.3;
    const double lambdaD = 0.045;
    const ElectrostaticRepulsion rep(repulsionParams(FER, lambdaD));
    auto U = [&](double h) { return FER*abar*lambdaD*std::exp(-h/lambdaD); };

    for (const double h : {0.001, 0.01, 0.05, 0.2})
    {
        const double dUdh = derivative(U, h, 1e-5*lambdaD);
        EXPECT_NEAR(n.dot(rep.eval(atGap(h)).F), dUdh, 1e-7*std::abs(dUdh)) << "h = " << h;
    }

    // Largest |dF/dh| is at contact
    const double dh = 1e-6*lambdaD;
    const double slope = (rep.eval(atGap(0)).F - rep.eval(atGap(dh)).F).norm()/dh;
    EXPECT_NEAR(FER*abar/lambdaD, slope, 1e-5*slope);
}


TEST(Repulsion, PairSymmetryVirialAndPressure)
{
    const ElectrostaticRepulsion rep(repulsionParams(1.0, 0.02));
    for (const double h : {-0.01, 0.0, 0.03})
    {
        expectPairSymmetryAndVirial(rep, h);
    }
    // A repulsive pair carries a positive pressure -tr(S)/3
    EXPECT_GT(-rep.eval(atGap(0.01)).S.trace(), 0);
}


TEST(Repulsion, RejectsBadParams)
{
    EXPECT_NO_THROW(ElectrostaticRepulsion(repulsionParams(1, 0.02)));
    expectThrowNaming([] { ElectrostaticRepulsion(repulsionParams(0, 0.02)); }, "FER = 0");
    expectThrowNaming([] { ElectrostaticRepulsion(repulsionParams(1, -0.02)); }, "lambdaD = -0.02");
    expectThrowNaming
    (
        [] { ElectrostaticRepulsion(ElectrostaticRepulsion::Params()); }, "FER = nan"
    );
    expectThrowNaming
    (
        []
        {
            ElectrostaticRepulsion::Params p = repulsionParams(1, 0.02);
            p.cutoffDebyeLengths = 0;
            ElectrostaticRepulsion{p};
        },
        "cutoffDebyeLengths = 0"
    );
}


// * * * * * * * * * * * * * * * Attraction * * * * * * * * * * * * * * * * //

namespace
{
    VanDerWaalsAttraction::Params attractionParams(double A)
    {
        VanDerWaalsAttraction::Params p;
        p.A = A;
        return p;
    }
}


TEST(VanDerWaals, MatchesEq7AtSeveralGaps)
{
    const double A = 3e-4;
    const VanDerWaalsAttraction vdw(attractionParams(A));
    const double eps = 0.01*abar;

    // Reference at the gap the geometry holds (|r| - a_i - a_j rounds h)
    for (const double h : {-0.05, -1e-3, 0.0, 1e-3, 0.01, 0.5, 3.9})
    {
        const PairGeometry g = atGap(h);
        const double hp = std::max(g.h, 0.0);
        const double expected = A*abar/(12*(hp*hp + eps*eps));
        const Vec3 F = vdw.eval(g).F;
        EXPECT_NEAR((F - expected*n).norm(), 0, 1e-14*expected) << "h = " << h;
    }

    // Cut at a surface gap of 4 a0 (paper Fig. 3): the pair loop calls the
    // kernel for h < gap() only
    EXPECT_DOUBLE_EQ(vdw.gap(), 4);
    EXPECT_GT(vdw.eval(atGap(4 - 1e-9)).F.norm(), 0);
}


TEST(VanDerWaals, ForceIsMinusGradientOfPotential)
{
    // U(h) = A abar/(12 eps) (atan(h/eps) - pi/2); the force on i along n is
    // dU/dh (an attraction pulls i towards j)
    const double A = 2e-4;
    VanDerWaalsAttraction::Params p = attractionParams(A);
    p.epsilonFraction = 0.02;
    const VanDerWaalsAttraction vdw(p);
    const double eps = p.epsilonFraction*abar;
    auto U = [&](double h) { return A*abar/(12*eps)*(std::atan(h/eps) - pi/2); };

    for (const double h : {0.001, 0.01, 0.05, 0.2, 1.0})
    {
        const double dUdh = derivative(U, h, 1e-5*eps);
        EXPECT_NEAR(n.dot(vdw.eval(atGap(h)).F), dUdh, 1e-7*std::abs(dUdh)) << "h = " << h;
    }
}


TEST(VanDerWaals, PairSymmetryVirialAndPressure)
{
    const VanDerWaalsAttraction vdw(attractionParams(1e-4));
    for (const double h : {-0.01, 0.0, 0.5})
    {
        expectPairSymmetryAndVirial(vdw, h);
    }
    // An attractive pair carries a negative pressure
    EXPECT_LT(-vdw.eval(atGap(0.01)).S.trace(), 0);
}


TEST(VanDerWaals, RejectsBadParams)
{
    EXPECT_NO_THROW(VanDerWaalsAttraction(attractionParams(1e-4)));
    expectThrowNaming([] { VanDerWaalsAttraction(attractionParams(-1)); }, "A = -1");
    expectThrowNaming
    (
        [] { VanDerWaalsAttraction(VanDerWaalsAttraction::Params()); }, "A = nan"
    );
    expectThrowNaming
    (
        []
        {
            VanDerWaalsAttraction::Params p = attractionParams(1e-4);
            p.epsilonFraction = 0;
            VanDerWaalsAttraction{p};
        },
        "epsilonFraction = 0"
    );
    expectThrowNaming
    (
        []
        {
            VanDerWaalsAttraction::Params p = attractionParams(1e-4);
            p.cutoffGap = -1;
            VanDerWaalsAttraction{p};
        },
        "cutoffGap = -1"
    );
}


// * * * * * * * * * * * * * * * * Scales * * * * * * * * * * * * * * * * * //

namespace
{
    ElectroChemicalScales::Params scalesParams(double shearRateRatio, double forceRatio)
    {
        ElectroChemicalScales::Params p;
        p.shearRateRatio = shearRateRatio;
        p.forceRatio = forceRatio;
        return p;
    }
}


TEST(ElectroChemicalScales, ContactForcesFollowThePaperGroups)
{
    // Equal spheres a = a0 = 1 at contact: the repulsion is
    // eta0 a0^2 gammaDot0 = gammaDot0/gammaDot (eq. 14, reduced units) and
    // F^R/F^A is the tabulated ratio (Table 3: 1 and 19; Table 2 extremes)
    for (const double shearRateRatio : {1.0, 1e-5, 10.0})
    {
        for (const double forceRatio : {19.0, 1.0})
        {
            const ElectroChemicalScales scales(scalesParams(shearRateRatio, forceRatio));
            const ElectrostaticRepulsion rep(scales.repulsion(0.02));
            const VanDerWaalsAttraction vdw(scales.attraction());
            const PairGeometry contact = PairGeometry::make(Vec3(2, 0, 0), 1, 1);

            const double FR = rep.eval(contact).F.norm();
            const double FA = vdw.eval(contact).F.norm();
            EXPECT_NEAR(FR, 1/shearRateRatio, 1e-14/shearRateRatio);
            EXPECT_NEAR(FR/FA, forceRatio, 1e-12*forceRatio);
        }
    }

    // Table 3 by hand: A = 12 (0.01)^2 F_ER/19
    const ElectroChemicalScales table3(scalesParams(1, 19));
    EXPECT_DOUBLE_EQ(table3.FER(), 1.0);
    EXPECT_NEAR(table3.hamaker(), 12e-4/19, 1e-18);
    EXPECT_EQ(table3.repulsion(0.02).lambdaD, 0.02);
    EXPECT_EQ(table3.attraction().epsilonFraction, 0.01);
}


TEST(ElectroChemicalScales, RejectsBadParams)
{
    expectThrowNaming
    (
        [] { ElectroChemicalScales(scalesParams(0, 19)); }, "shearRateRatio = 0"
    );
    expectThrowNaming
    (
        [] { ElectroChemicalScales(scalesParams(INFINITY, 19)); }, "shearRateRatio = inf"
    );
    expectThrowNaming
    (
        [] { ElectroChemicalScales(scalesParams(1, -19)); }, "forceRatio = -19"
    );
    expectThrowNaming
    (
        [] { ElectroChemicalScales(ElectroChemicalScales::Params()); }, "shearRateRatio = nan"
    );
}
