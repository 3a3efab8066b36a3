// Pairwise lubrication (eq. 3, Appendix A): resistance scalars against
// values of Jeffrey & Onishi (1984) and Jeffrey (1992) evaluated
// independently (forces/LubricationCoefficients.H), the Reynolds squeeze
// limit, worked forces of a pair, and the exact identities (force balance,
// rigid-body motion, affine strain, relabelling).
#include "forces/Lubrication.H"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

using namespace suspension;

namespace
{
    using Gap = LubricationCoefficients::Gap;
    using Entries = LubricationCoefficients::Entries;
    using PairVector = Lubrication::PairVector;
    using PairMatrix = Lubrication::PairMatrix;

    const double sizeRatios[] = {0.1, 0.5, 1, 1.4, 3, 10};

    constexpr LubricationTerms leading = LubricationTerms::leading;
    constexpr LubricationTerms extended = LubricationTerms::extended;
    constexpr LubricationTerms bothModes[] = {leading, extended};

    // Gap functions selecting one order of the expansions
    const Gap orderInv{1, 0, 0, 0};     // coefficient of 1/xi
    const Gap orderLog{0, 1, 1, 0};     // coefficient of L (X and Y)
    const Gap orderXiLog{0, 0, 0, 1};   // coefficient of xi L

    Lubrication makeLubrication
    (
        double epsilon,
        LubricationTerms terms = leading,
        double eta = 1
    )
    {
        Lubrication::Params p;
        p.eta = eta;
        p.epsilon = epsilon;
        p.terms = terms;
        return Lubrication(p);
    }

    // Pair with surface gap h along the unit vector n (i at the origin)
    PairGeometry pairAt(double ai, double aj, double h, const Vec3& n)
    {
        return PairGeometry::make((ai + aj + h)*n.normalized(), ai, aj);
    }

    PairKinematics still()
    {
        return PairKinematics
        {
            Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero(),
            Vec3::Zero(), Vec3::Zero(), Vec3::Zero(),
            Mat3::Zero(), Mat3::Zero()
        };
    }

    Vec3 randomVec(std::mt19937& gen)
    {
        std::uniform_real_distribution<double> u(-1, 1);
        return Vec3(u(gen), u(gen), u(gen));
    }

    Vec3 randomUnit(std::mt19937& gen)
    {
        return randomVec(gen).normalized();
    }

    // Symmetric, traceless
    Mat3 randomStrain(std::mt19937& gen)
    {
        Mat3 E;
        std::uniform_real_distribution<double> u(-1, 1);
        for (int i = 0; i < 3; ++i)
        {
            for (int j = i; j < 3; ++j)
            {
                E(i, j) = E(j, i) = u(gen);
            }
        }
        return E - E.trace()/3*Mat3::Identity();
    }

    PairKinematics randomKinematics(std::mt19937& gen)
    {
        PairKinematics k = still();
        k.ui = randomVec(gen);
        k.uj = randomVec(gen);
        k.wi = randomVec(gen);
        k.wj = randomVec(gen);
        k.Ei = randomStrain(gen);
        k.Ej = randomStrain(gen);
        return k;
    }

    PairVector velocities(const PairKinematics& k)
    {
        PairVector v;
        v << k.ui, k.uj, k.wi, k.wj;
        return v;
    }

    // (F_i, F_j, T_i, T_j) from the matrix form of eq. (3)
    PairVector matrixForces
    (
        const Lubrication& lub,
        const PairGeometry& g,
        const PairKinematics& k
    )
    {
        return -lub.resistanceMatrix(g)*velocities(k)
             + lub.strainForces(g, k.Ei, k.Ej);
    }

    // Size of the largest single term of the forces, for relative tolerances
    double forceScale
    (
        const Lubrication& lub,
        const PairGeometry& g,
        const PairKinematics& k
    )
    {
        return lub.resistanceMatrix(g).cwiseAbs().maxCoeff()
              *velocities(k).cwiseAbs().maxCoeff()
             + lub.strainForces(g, k.Ei, k.Ej).cwiseAbs().maxCoeff();
    }

    // Reynolds squeeze: 6 pi eta (a1 a2/(a1 + a2))^2 v/h
    double reynolds(double eta, double a1, double a2, double v, double h)
    {
        const double aRed = a1*a2/(a1 + a2);
        return 6*pi*eta*aRed*aRed*v/h;
    }

    void expectEntries
    (
        const Entries& e,
        double ii, double ij, double ji, double jj,
        double tol,
        const std::string& what
    )
    {
        EXPECT_NEAR(e.ii, ii, tol) << what << " ii";
        EXPECT_NEAR(e.ij, ij, tol) << what << " ij";
        EXPECT_NEAR(e.ji, ji, tol) << what << " ji";
        EXPECT_NEAR(e.jj, jj, tol) << what << " jj";
    }

    // Entries in units of pi (eta = 1)
    Entries perPi(const Entries& e)
    {
        return Entries{e.ii/pi, e.ij/pi, e.ji/pi, e.jj/pi};
    }
}


// ---------------------------------------------------------------------------
// Coefficients


TEST(LubricationCoefficients, TableValuesOfJeffreyOnishi)
{
    // The dimensional singular coefficients of pi eta (1/xi) and pi eta L at a_1 = 1,
    // printed to 6 decimals
    const double tol = 5e-7;
    const double eta = 1;

    {
        const LubricationCoefficients inv(1, 1, orderInv, eta);
        const LubricationCoefficients log(1, 1, orderLog, eta);
        expectEntries(perPi(inv.XA), 1.5, -1.5, -1.5, 1.5, tol, "XA 1/xi");
        expectEntries(perPi(log.XA), 1.35, -1.35, -1.35, 1.35, tol, "XA L");
        expectEntries(perPi(log.YA), 1, -1, -1, 1, tol, "YA, a2=1");
        expectEntries(perPi(log.YB), -1, 1, -1, 1, tol, "YB, a2=1");
        expectEntries(perPi(log.YC), 1.6, 0.4, 0.4, 1.6, tol, "YC, a2=1");
        expectEntries(perPi(inv.XG), 1.5, -1.5, 1.5, -1.5, tol, "XG 1/xi");
        expectEntries(perPi(log.XG), 1.35, -1.35, 1.35, -1.35, tol, "XG L");
        expectEntries(perPi(log.YG), 0.5, -0.5, 0.5, -0.5, tol, "YG, a2=1");
        expectEntries(perPi(log.YH), 0.2, 0.8, 0.8, 0.2, tol, "YH, a2=1");
    }
    {
        const LubricationCoefficients inv(1, 1.4, orderInv, eta);
        const LubricationCoefficients log(1, 1.4, orderLog, eta);
        expectEntries
        (
            perPi(inv.XA),
            1.701389, -1.701389, -1.701389, 1.701389, tol, "XA 1/xi, a2=1.4"
        );
        expectEntries
        (
            perPi(log.XA),
            1.550694, -1.550694, -1.550694, 1.550694, tol, "XA L, a2=1.4"
        );
        expectEntries
        (
            perPi(log.YA),
            1.186111, -1.186111, -1.186111, 1.186111, tol, "YA, a2=1.4"
        );
        expectEntries
        (
            perPi(log.YB),
            -1.05, 1.05, -1.796667, 1.796667, tol, "YB, a2=1.4"
        );
        expectEntries
        (
            perPi(log.YC),
            1.866667, 0.653333, 0.653333, 3.658667, tol, "YC, a2=1.4"
        );
        expectEntries
        (
            perPi(inv.XG),
            1.701389, -1.701389, 2.381944, -2.381944, tol, "XG 1/xi, a2=1.4"
        );
        expectEntries
        (
            perPi(log.XG),
            1.210417, -1.210417, 2.51125, -2.51125, tol, "XG L, a2=1.4"
        );
        expectEntries
        (
            perPi(log.YG),
            0.661111, -0.661111, 0.762222, -0.762222, tol, "YG, a2=1.4"
        );
        expectEntries
        (
            perPi(log.YH),
            0.116667, 1.47, 1.143333, 0.686, tol, "YH, a2=1.4"
        );
    }
}


TEST(LubricationCoefficients, ClosedForms)
{
    // The dimensional closed forms in (a1, a2), against the
    // code's lambda-series, for any radii and viscosity
    const double eta = 1.7;
    for (const double a1 : {1.0, 0.37})
    {
        for (const double ratio : sizeRatios)
        {
            const double a2 = ratio*a1;
            const double s = a1 + a2;
            const double u = pi*eta;
            const LubricationCoefficients inv(a1, a2, orderInv, eta);
            const LubricationCoefficients log(a1, a2, orderLog, eta);
            const std::string what = "a1=" + std::to_string(a1)
                                   + " a2=" + std::to_string(a2) + " ";

            auto check = [&]
            (
                const Entries& e,
                double ii, double ij, double ji, double jj,
                const char* name
            )
            {
                const double scale = std::max
                (
                    std::max(std::abs(ii), std::abs(ij)),
                    std::max(std::abs(ji), std::abs(jj))
                );
                expectEntries(e, ii, ij, ji, jj, 1e-13*scale, what + name);
            };

            const double xa = u*12*a1*a1*a2*a2/(s*s*s);
            check(inv.XA, xa, -xa, -xa, xa, "XA 1/xi");
            const double xaL = u*6*a1*a2*(a1*a1 + 7*a1*a2 + a2*a2)/(5*s*s*s);
            check(log.XA, xaL, -xaL, -xaL, xaL, "XA L");
            const double ya = u*8*a1*a2*(2*a1*a1 + a1*a2 + 2*a2*a2)/(5*s*s*s);
            check(log.YA, ya, -ya, -ya, ya, "YA");
            const double yb1 = u*4*a1*a1*a2*(4*a1 + a2)/(5*s*s);
            const double yb2 = u*4*a1*a2*a2*(a1 + 4*a2)/(5*s*s);
            check(log.YB, -yb1, yb1, -yb2, yb2, "YB");
            check
            (
                log.YC,
                u*16*a1*a1*a1*a2/(5*s),
                u*4*a1*a1*a2*a2/(5*s),
                u*4*a1*a1*a2*a2/(5*s),
                u*16*a1*a2*a2*a2/(5*s),
                "YC"
            );
            const double xg1 = u*12*a1*a1*a1*a2*a2/(s*s*s);
            const double xg2 = u*12*a1*a1*a2*a2*a2/(s*s*s);
            check(inv.XG, xg1, -xg1, xg2, -xg2, "XG 1/xi");
            const double xg1L =
                u*6*a1*a1*a2*(a1*a1 + 12*a1*a2 - 4*a2*a2)/(5*s*s*s);
            const double xg2L =
                u*6*a1*a2*a2*(a2*a2 + 12*a1*a2 - 4*a1*a1)/(5*s*s*s);
            check(log.XG, xg1L, -xg1L, xg2L, -xg2L, "XG L");
            const double yg1 =
                u*2*a1*a1*a2*(4*a1*a1 - a1*a2 + 7*a2*a2)/(5*s*s*s);
            const double yg2 =
                u*2*a1*a2*a2*(7*a1*a1 - a1*a2 + 4*a2*a2)/(5*s*s*s);
            check(log.YG, yg1, -yg1, yg2, -yg2, "YG");
            check
            (
                log.YH,
                u*4*a1*a1*a1*a2*(2*a1 - a2)/(5*s*s),
                u*2*a1*a1*a2*a2*(a1 + 7*a2)/(5*s*s),
                u*2*a1*a1*a2*a2*(7*a1 + a2)/(5*s*s),
                u*4*a1*a2*a2*a2*(2*a2 - a1)/(5*s*s),
                "YH"
            );

            // xi L order of X^A
            const LubricationCoefficients xiLog(a1, a2, orderXiLog, eta);
            const double xa3 = u/7*
            (
                a1*a1*a1*a1 + 18*a1*a1*a1*a2 - 29*a1*a1*a2*a2
              + 18*a1*a2*a2*a2 + a2*a2*a2*a2
            )/(s*s*s);
            check(xiLog.XA, xa3, -xa3, -xa3, xa3, "XA xi L");
        }
    }
}


TEST(LubricationCoefficients, LogTermsOfTheGap)
{
    // Coefficients of pi eta xi L (extended mode) at a_1 = 1: the g3 (g5, g6)
    // of JO 1984 (A) and J92 (G, H) with the JO/J92 prefactors pi eta (a_a + a_b)^k and
    // the JO rule f_22(lambda) = p f_11(1/lambda), evaluated independently
    // in exact rational arithmetic
    const double tol = 1e-11;
    {
        const LubricationCoefficients c(1, 1, orderXiLog, 1);
        const double xa = 9.0/56, xg = 117.0/140;
        expectEntries(perPi(c.XA), xa, -xa, -xa, xa, tol, "XA, a2=1");
        expectEntries(perPi(c.YA), 0, 0, 0, 0, tol, "YA, a2=1");
        expectEntries(perPi(c.YB), -0.5, 0.5, -0.5, 0.5, tol, "YB, a2=1");
        expectEntries(perPi(c.YC), 1.504, 0.496, 0.496, 1.504, tol, "YC, a2=1");
        expectEntries(perPi(c.XG), xg, -xg, xg, -xg, tol, "XG, a2=1");
        expectEntries(perPi(c.YG), 0.25, -0.25, 0.25, -0.25, tol, "YG, a2=1");
        expectEntries(perPi(c.YH), 0.548, 0.452, 0.452, 0.548, tol, "YH, a2=1");
    }
    {
        const LubricationCoefficients c(1, 1.4, orderXiLog, 1);
        expectEntries
        (
            perPi(c.XA),
            0.233482142857, -0.233482142857, -0.233482142857, 0.233482142857,
            tol, "XA, a2=1.4"
        );
        expectEntries
        (
            perPi(c.YA), 0.0108, -0.0108, -0.0108, 0.0108, tol, "YA, a2=1.4"
        );
        expectEntries
        (
            perPi(c.YB),
            -0.7402, 0.7402, -0.709053333333, 0.709053333333, tol, "YB, a2=1.4"
        );
        expectEntries
        (
            perPi(c.YC),
            2.16213333333, 0.874346666667, 0.874346666667, 2.98338133333,
            tol, "YC, a2=1.4"
        );
        expectEntries
        (
            perPi(c.XG),
            1.39285714286, -1.39285714286, 1.02833333333, -1.02833333333,
            tol, "XG, a2=1.4"
        );
        expectEntries
        (
            perPi(c.YG),
            0.402922222222, -0.402922222222, 0.321704444444, -0.321704444444,
            tol, "YG, a2=1.4"
        );
        expectEntries
        (
            perPi(c.YH),
            0.802466666667, 0.95788, 0.715773333333, 0.970984, tol, "YH, a2=1.4"
        );
    }
}


TEST(LubricationCoefficients, Identities)
{
    // Exact identities of the singular (1/xi and L) orders, for all lambda
    for (const double ratio : sizeRatios)
    {
        for (const Gap& order : {orderInv, orderLog})
        {
            const double a1 = 0.8;
            const double a2 = ratio*a1;
            const double s = a1 + a2;
            const LubricationCoefficients c(a1, a2, order, 1);
            const double tol = 1e-13*std::max
            (
                {std::abs(c.XA.ii)*s, std::abs(c.YA.ii)*s,
                 std::abs(c.YB.ii), std::abs(c.YB.jj),
                 std::abs(c.XG.ii), std::abs(c.XG.jj),
                 std::abs(c.YC.jj), std::abs(c.YC.ii)}
            );
            SCOPED_TRACE("ratio " + std::to_string(ratio));

            // Relative-velocity dependence and matrix symmetry
            EXPECT_NEAR(c.XA.ii + c.XA.ij, 0, tol);
            EXPECT_NEAR(c.XA.jj - c.XA.ii, 0, tol);
            EXPECT_NEAR(c.XA.ji - c.XA.ij, 0, tol);
            EXPECT_NEAR(c.YA.ii + c.YA.ij, 0, tol);
            EXPECT_NEAR(c.YA.jj - c.YA.ii, 0, tol);
            EXPECT_NEAR(c.YA.ji - c.YA.ij, 0, tol);
            EXPECT_NEAR(c.YB.ii + c.YB.ij, 0, tol);
            EXPECT_NEAR(c.YB.ji + c.YB.jj, 0, tol);
            EXPECT_NEAR(c.YC.ji - c.YC.ij, 0, tol);

            // Rigid rotation of the pair: no singular force or torque
            EXPECT_NEAR(c.YC.ii + c.YC.ij - s*c.YB.ij, 0, tol);
            EXPECT_NEAR(c.YC.ji + c.YC.jj + s*c.YB.ji, 0, tol);
            EXPECT_NEAR(s*c.YA.ij - (c.YB.ii + c.YB.ji), 0, tol);
            EXPECT_NEAR(s*c.YA.jj - (c.YB.ij + c.YB.jj), 0, tol);

            // Affine motion in strain = relative translation (a1 + a2) E.n
            EXPECT_NEAR(c.XG.ii + c.XG.ji + s*c.XA.ij, 0, tol);
            EXPECT_NEAR(c.XG.ij + c.XG.jj - s*c.XA.ji, 0, tol);
            EXPECT_NEAR(2*(c.YG.ii + c.YG.ji) + s*c.YA.ij, 0, tol);
            EXPECT_NEAR(2*(c.YG.ij + c.YG.jj) - s*c.YA.ji, 0, tol);
            EXPECT_NEAR(2*(c.YH.ii + c.YH.ji) - s*c.YB.ij, 0, tol);
            EXPECT_NEAR(2*(c.YH.ij + c.YH.jj) + s*c.YB.ji, 0, tol);
        }
    }
}


TEST(LubricationCoefficients, ForceBalanceHoldsAtOrderXiLog)
{
    // Section 6: the relative-velocity identities also hold at order xi L,
    // so F_j = -F_i in the extended mode as well
    for (const double ratio : sizeRatios)
    {
        const LubricationCoefficients c(1, ratio, orderXiLog, 1);
        const double tol = 1e-13*std::max
        (
            {std::abs(c.XA.ii), std::abs(c.YA.ii), std::abs(c.YB.ii),
             std::abs(c.YB.jj), std::abs(c.XG.ii), std::abs(c.XG.ji),
             std::abs(c.YG.ii), std::abs(c.YG.ji), std::abs(c.YC.ij)}
        );
        SCOPED_TRACE("ratio " + std::to_string(ratio));
        EXPECT_NEAR(c.XA.ii + c.XA.ij, 0, tol);
        EXPECT_NEAR(c.XA.jj - c.XA.ii, 0, tol);
        EXPECT_NEAR(c.XA.ji - c.XA.ij, 0, tol);
        EXPECT_NEAR(c.YA.ii + c.YA.ij, 0, tol);
        EXPECT_NEAR(c.YA.jj - c.YA.ii, 0, tol);
        EXPECT_NEAR(c.YA.ji - c.YA.ij, 0, tol);
        EXPECT_NEAR(c.YB.ii + c.YB.ij, 0, tol);
        EXPECT_NEAR(c.YB.ji + c.YB.jj, 0, tol);
        EXPECT_NEAR(c.YC.ji - c.YC.ij, 0, tol);
        EXPECT_NEAR(c.XG.ii + c.XG.ij, 0, tol);
        EXPECT_NEAR(c.XG.ji + c.XG.jj, 0, tol);
        EXPECT_NEAR(c.YG.ii + c.YG.ij, 0, tol);
        EXPECT_NEAR(c.YG.ji + c.YG.jj, 0, tol);
    }
}


TEST(LubricationCoefficients, RegularisedGap)
{
    const double eps = 1e-3;

    // (A.6): xi_e = xi + epsilon
    const Gap g = Gap::make(0.01, eps, extended);
    EXPECT_DOUBLE_EQ(g.inv, 1/0.011);
    EXPECT_DOUBLE_EQ(g.log, std::log(1/0.011));
    EXPECT_DOUBLE_EQ(g.logX, std::log(1/0.011));
    EXPECT_DOUBLE_EQ(g.xiLog, 0.011*std::log(1/0.011));

    // Leading: no L in X, no xi L
    const Gap lead = Gap::make(0.01, eps, leading);
    EXPECT_DOUBLE_EQ(lead.inv, 1/0.011);
    EXPECT_DOUBLE_EQ(lead.log, std::log(1/0.011));
    EXPECT_EQ(lead.logX, 0);
    EXPECT_EQ(lead.xiLog, 0);

    // Overlap: xi = 0
    const Gap overlap = Gap::make(-0.2, eps, extended);
    EXPECT_DOUBLE_EQ(overlap.inv, 1/eps);
    EXPECT_DOUBLE_EQ(overlap.log, std::log(1/eps));

    // Log terms vanish when 1/xi_e <= 1
    const Gap wide = Gap::make(1.0, eps, extended);
    EXPECT_DOUBLE_EQ(wide.inv, 1/(1 + eps));
    EXPECT_EQ(wide.log, 0);
    EXPECT_EQ(wide.logX, 0);
    EXPECT_EQ(wide.xiLog, 0);
}


// ---------------------------------------------------------------------------
// Kernel: analytic limits


TEST(Lubrication, ReynoldsSqueezeEqualSpheres)
{
    // F = 3 pi eta a^2 v/(2h); i is pushed away from an approaching j
    const double a = 1;
    const double v = 0.7;
    const double eta = 2.5;
    const Vec3 n = Vec3(1, -2, 0.5).normalized();
    const Lubrication lead = makeLubrication(1e-9, leading, eta);
    const Lubrication ext = makeLubrication(1e-9, extended, eta);

    for (const double h : {1e-3, 2e-3, 5e-3, 1e-2})
    {
        const PairGeometry g = pairAt(a, a, h, n);
        PairKinematics k = still();
        k.uj = -v*n;
        const double exact = 3*pi*eta*a*a*v/(2*h);

        // Leading order is the Reynolds result up to epsilon/xi = 1e-9 a/h
        const PairForce f = lead.eval(g, k);
        EXPECT_NEAR(-f.F.dot(n), exact, 2e-6*exact) << "h = " << h;
        EXPECT_NEAR((f.F - f.F.dot(n)*n).norm(), 0, 1e-14*exact);
        EXPECT_NEAR(f.Ti.norm(), 0, 1e-14*exact);
        EXPECT_NEAR(f.Tj.norm(), 0, 1e-14*exact);

        // Extended: the O(L) correction is below 1% at h = 1e-3 a
        if (h == 1e-3)
        {
            const PairForce fe = ext.eval(g, k);
            EXPECT_NEAR(-fe.F.dot(n), exact, 1e-2*exact);
            EXPECT_GT(-fe.F.dot(n), exact);
        }
    }
}


TEST(Lubrication, ReynoldsSqueezeUnequalSpheres)
{
    // F = 6 pi eta (a1 a2/(a1 + a2))^2 v/h, exact at order 1/xi
    const double v = 1.3;
    const Lubrication lub = makeLubrication(1e-14);
    std::mt19937 gen(7);

    for (const double a1 : {1.0, 0.45})
    {
        for (const double ratio : sizeRatios)
        {
            const double a2 = ratio*a1;
            const double h = 1e-3*std::min(a1, a2);
            const Vec3 n = randomUnit(gen);
            PairKinematics k = still();
            k.ui = v*n;         // i approaches j
            const PairForce f = lub.eval(pairAt(a1, a2, h, n), k);
            const double exact = reynolds(1, a1, a2, v, h);
            EXPECT_NEAR(-f.F.dot(n), exact, 1e-9*exact)
                << "a1 = " << a1 << ", a2 = " << a2;
        }
    }
}


TEST(Lubrication, WorkedNumbers)
{
    // |F_i| for a unit approach speed of j, eta = a_1 = 1:
    // 1/xi term only; 1/xi + g2 L; 1/xi + g2 L + g3 xi L
    struct Case
    {
        double a2, h, lead, withLog, withXiLog;
    };
    const Case cases[] =
    {
        {1.0, 0.01, 471.238898, 490.770116, 490.793367},
        {1.4, 0.012, 534.507083, 556.941862, 556.975641},
        {1.4, 0.01, 641.408500, 664.731486, 664.760749}
    };
    const double tol = 1e-6;
    const double eps = 1e-14;
    const Lubrication lead = makeLubrication(eps, leading);
    const Lubrication ext = makeLubrication(eps, extended);
    const Vec3 n = Vec3(0.3, 0.1, -1).normalized();

    for (const Case& c : cases)
    {
        const PairGeometry g = pairAt(1, c.a2, c.h, n);
        PairKinematics k = still();
        k.uj = -n;

        const PairForce fLead = lead.eval(g, k);
        EXPECT_NEAR(fLead.F.dot(n), -c.lead, tol) << "a2 = " << c.a2;
        EXPECT_NEAR(c.lead, reynolds(1, 1, c.a2, 1, c.h), tol);

        // 1/xi + g2 L, no xi L: from the scalars directly
        const double xi = 2*c.h/(1 + c.a2);
        const double L = std::log(1/xi);
        const LubricationCoefficients s(1, c.a2, Gap{1/xi, L, L, 0}, 1);
        EXPECT_NEAR(-s.XA.ij, c.withLog, tol) << "a2 = " << c.a2;

        const PairForce fExt = ext.eval(g, k);
        EXPECT_NEAR(fExt.F.dot(n), -c.withXiLog, tol) << "a2 = " << c.a2;
    }
}


TEST(Lubrication, OverlapIsRegularised)
{
    // Overlapping pairs see the contact value xi = 0: finite, and equal to
    // 6 pi eta a_1 g1/epsilon for the squeeze (g1 = 1/4 for equal spheres)
    const double eps = 1e-3;
    const Lubrication lub = makeLubrication(eps, extended);
    const Vec3 n = Vec3(0, 1, 1).normalized();
    std::mt19937 gen(11);
    const PairKinematics k = randomKinematics(gen);

    const PairForce contact = lub.eval(pairAt(1, 1, 0, n), k);
    for (const double h : {-1e-4, -0.01, -0.3})
    {
        const PairForce f = lub.eval(pairAt(1, 1, h, n), k);
        ASSERT_TRUE(f.F.allFinite() && f.Ti.allFinite() && f.Tj.allFinite());
        const double scale = contact.F.norm() + contact.Ti.norm();
        EXPECT_NEAR((f.F - contact.F).norm(), 0, 1e-13*scale) << "h = " << h;
        EXPECT_NEAR((f.Ti - contact.Ti).norm(), 0, 1e-13*scale);
        EXPECT_NEAR((f.Tj - contact.Tj).norm(), 0, 1e-13*scale);
    }

    const Lubrication lead = makeLubrication(eps);
    PairKinematics squeeze = still();
    squeeze.uj = -n;
    const PairForce f = lead.eval(pairAt(1, 1, -0.05, n), squeeze);
    EXPECT_NEAR(f.F.dot(n), -6*pi*0.25/eps, 1e-12*6*pi*0.25/eps);
}


TEST(Lubrication, RangeIsTheGapCutOff)
{
    Lubrication::Params p;
    p.deltaLub = 0.07;
    const Lubrication lub(p);
    EXPECT_DOUBLE_EQ(lub.gap(), 0.07);
}


TEST(Lubrication, InvalidParametersThrow)
{
    auto expectThrow = []
    (
        const Lubrication::Params& p,
        const std::string& name,
        const std::string& value
    )
    {
        try
        {
            const Lubrication lub(p);
            ADD_FAILURE() << name << " = " << value << " accepted";
        }
        catch (const std::invalid_argument& e)
        {
            const std::string msg = e.what();
            EXPECT_NE(msg.find(name), std::string::npos) << msg;
            EXPECT_NE(msg.find(value), std::string::npos) << msg;
        }
    };

    Lubrication::Params p;
    p.eta = 0;
    expectThrow(p, "eta", "0");
    p.eta = -2;
    expectThrow(p, "eta", "-2");
    p.eta = std::numeric_limits<double>::quiet_NaN();
    expectThrow(p, "eta", "nan");

    p = Lubrication::Params();
    p.epsilon = -1e-9;
    expectThrow(p, "epsilon", "-1e-09");
    p.epsilon = 0;
    expectThrow(p, "epsilon", "0");

    p = Lubrication::Params();
    p.deltaLub = -0.1;
    expectThrow(p, "deltaLub", "-0.1");
    p.deltaLub = std::numeric_limits<double>::infinity();
    expectThrow(p, "deltaLub", "inf");

    EXPECT_NO_THROW(Lubrication(Lubrication::Params()));
}


// ---------------------------------------------------------------------------
// Kernel: structure


TEST(Lubrication, ResistanceMatrixSymmetricPositiveSemiDefinite)
{
    // R_Lub is symmetric (reciprocal theorem) in both modes. It is positive
    // semi-definite with the singular orders 1/xi and L, i.e. in the leading
    // mode and with g2 L added to X^A, X^G; the xi L terms of the extended
    // mode alone are indefinite (see LubricationCoefficients.H)
    std::mt19937 gen(5);
    const double eps = 1e-3;
    const Lubrication lead = makeLubrication(eps, leading);
    const Lubrication ext = makeLubrication(eps, extended);

    auto expectSymmetric = [](const PairMatrix& R, const std::string& what)
    {
        const double scale = R.cwiseAbs().maxCoeff();
        EXPECT_NEAR((R - R.transpose()).cwiseAbs().maxCoeff(), 0, 1e-15*scale)
            << what;
    };
    auto expectPSD = [](const PairMatrix& R, const std::string& what)
    {
        const Eigen::SelfAdjointEigenSolver<PairMatrix> eig(R);
        const double largest = eig.eigenvalues().maxCoeff();
        EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-13*largest) << what;
    };

    for (const double ratio : sizeRatios)
    {
        for (const double h : {1e-5, 1e-3, 1e-2, 0.049})
        {
            const std::string what =
                "ratio " + std::to_string(ratio) + ", h " + std::to_string(h);
            const PairGeometry g = pairAt(1, ratio, h, randomUnit(gen));

            const PairMatrix R = lead.resistanceMatrix(g);
            expectSymmetric(R, what + " leading");
            expectPSD(R, what + " leading");

            expectSymmetric(ext.resistanceMatrix(g), what + " extended");

            const Gap gap = Gap::make(2*h/(1 + ratio), eps, extended);
            const PairMatrix RLog = Lubrication::resistanceMatrix
            (
                LubricationCoefficients
                (
                    1, ratio, Gap{gap.inv, gap.log, gap.logX, 0}, 1
                ),
                g.n
            );
            expectSymmetric(RLog, what + " 1/xi + L");
            expectPSD(RLog, what + " 1/xi + L");
        }
    }
}


TEST(Lubrication, ForceBalanceAndMatrixForm)
{
    // F_j = -F_i for any velocities and strains (E_i != E_j), and eval()
    // equals the matrix form -R_Lub v + R'_Lub E of eq. (3)
    std::mt19937 gen(1);
    std::uniform_real_distribution<double> gap(0, 0.05);
    for (const LubricationTerms terms : bothModes)
    {
        const Lubrication lub = makeLubrication(1e-3, terms);
        for (const double ratio : sizeRatios)
        {
            for (int trial = 0; trial < 20; ++trial)
            {
                const double ai = 0.5 + 0.5*gap(gen)/0.05;
                const PairGeometry g =
                    pairAt(ai, ratio*ai, gap(gen), randomUnit(gen));
                const PairKinematics k = randomKinematics(gen);
                const PairForce f = lub.eval(g, k);
                const PairVector m = matrixForces(lub, g, k);
                const double tol = 1e-13*forceScale(lub, g, k);

                EXPECT_NEAR((m.segment<3>(0) + m.segment<3>(3)).norm(), 0, tol)
                    << "ratio " << ratio;
                EXPECT_NEAR((f.F - m.segment<3>(0)).norm(), 0, tol);
                EXPECT_NEAR((f.Ti - m.segment<3>(6)).norm(), 0, tol);
                EXPECT_NEAR((f.Tj - m.segment<3>(9)).norm(), 0, tol);
            }
        }
    }
}


TEST(Lubrication, IsotropicStrainGivesNoForce)
{
    // P = n.E.n - tr(E)/3 (A.4), Q.n and n_perp all vanish for E = I
    const Lubrication lub = makeLubrication(1e-3);
    const PairGeometry g = pairAt(1, 1.4, 0.01, Vec3(1, 2, 3));
    const Mat3 I = Mat3::Identity();
    const PairVector fE = lub.strainForces(g, I, 2*I);
    const double scale = lub.strainForces(g, Mat3::Ones(), I).norm();
    EXPECT_NEAR(fE.norm(), 0, 1e-14*scale);
}


TEST(Lubrication, StressletIsSymmetricPartOfRF)
{
    // eq. (9b); a squeezed (repulsive) pair has a positive pressure -tr/3
    std::mt19937 gen(2);
    const Lubrication lub = makeLubrication(1e-3);
    const PairGeometry g = pairAt(1, 1.4, 0.01, randomUnit(gen));
    const PairKinematics k = randomKinematics(gen);
    const PairForce f = lub.eval(g, k);
    const Mat3 S = 0.5*(g.r*f.F.transpose() + f.F*g.r.transpose());
    const double scale = S.cwiseAbs().maxCoeff();
    EXPECT_NEAR((f.S - S).cwiseAbs().maxCoeff(), 0, 1e-14*scale);

    PairKinematics squeeze = still();
    squeeze.uj = -g.n;
    EXPECT_LT(lub.eval(g, squeeze).S.trace(), 0);
}


TEST(Lubrication, RelabellingMirrorsForces)
{
    // Swapping i and j (r -> -r, radii, velocities, strains) gives the force
    // -F on the new i, swaps the torques and keeps the stresslet
    std::mt19937 gen(3);
    for (const LubricationTerms terms : bothModes)
    {
        const Lubrication lub = makeLubrication(1e-3, terms);
        for (const double ratio : sizeRatios)
        {
            const PairGeometry g =
                pairAt(0.9, 0.9*ratio, 0.013, randomUnit(gen));
            const PairGeometry gs = PairGeometry::make(-g.r, g.aj, g.ai);
            const PairKinematics k = randomKinematics(gen);
            PairKinematics ks = still();
            ks.ui = k.uj;
            ks.uj = k.ui;
            ks.wi = k.wj;
            ks.wj = k.wi;
            ks.Ei = k.Ej;
            ks.Ej = k.Ei;

            const PairForce f = lub.eval(g, k);
            const PairForce fs = lub.eval(gs, ks);
            const double tol = 1e-13*forceScale(lub, g, k);
            EXPECT_NEAR((fs.F + f.F).norm(), 0, tol) << "ratio " << ratio;
            EXPECT_NEAR((fs.Ti - f.Tj).norm(), 0, tol) << "ratio " << ratio;
            EXPECT_NEAR((fs.Tj - f.Ti).norm(), 0, tol) << "ratio " << ratio;
            EXPECT_NEAR((fs.S - f.S).cwiseAbs().maxCoeff(), 0, tol*g.dist);
        }
    }
}


// ---------------------------------------------------------------------------
// Kernel: frame invariance (G/H terms against A/B)


TEST(Lubrication, RigidBodyMotionInLinearFlowGivesNoForce)
{
    // In a linear ambient flow U_inf = Omega_inf x x + E.x, a pair moving as
    // one rigid body (u_a = U0 + w x x_a, omega_a = w) has no relative surface
    // motion, so no singular force or torque - although U'_a, Omega'_a and
    // the strain terms are all nonzero. Particles held at rest in a pure
    // strain (U0 = w = Omega_inf = 0) are a special case.
    // The rigid-body and affine-strain identities cancel the singular terms exactly for
    // the contact lever arm a_i + a_j, so the velocity fields are sampled at
    // x_j = x_i + (a_i + a_j) n; with the true centre distance a_i + a_j + h
    // a non-singular O(1) residual remains (the order the model drops).
    std::mt19937 gen(4);
    std::uniform_real_distribution<double> gap(1e-4, 0.05);
    const Lubrication lub = makeLubrication(1e-3);

    for (const double ratio : sizeRatios)
    {
        for (int trial = 0; trial < 10; ++trial)
        {
            const bool atRest = trial == 0;
            const Mat3 E = randomStrain(gen);
            const Vec3 OmegaInf = atRest ? Vec3::Zero() : randomVec(gen);
            const Vec3 U0 = atRest ? Vec3::Zero() : randomVec(gen);
            const Vec3 w = atRest ? Vec3::Zero() : randomVec(gen);

            const double ai = 1.1;
            const Vec3 xi = 3*randomVec(gen);
            const PairGeometry g =
                pairAt(ai, ratio*ai, gap(gen), randomUnit(gen));
            const Vec3 xj = xi + (g.ai + g.aj)*g.n;

            auto Uinf = [&](const Vec3& x)
            {
                return Vec3(OmegaInf.cross(x) + E*x);
            };
            PairKinematics k = still();
            k.ui = U0 + w.cross(xi) - Uinf(xi);
            k.uj = U0 + w.cross(xj) - Uinf(xj);
            k.wi = w - OmegaInf;
            k.wj = w - OmegaInf;
            k.Ei = E;
            k.Ej = E;

            const PairForce f = lub.eval(g, k);
            const double tol = 1e-12*forceScale(lub, g, k);
            SCOPED_TRACE("ratio " + std::to_string(ratio));
            SCOPED_TRACE("trial " + std::to_string(trial));
            EXPECT_NEAR(f.F.norm(), 0, tol);
            EXPECT_NEAR(f.Ti.norm(), 0, tol);
            EXPECT_NEAR(f.Tj.norm(), 0, tol);
        }
    }
}


TEST(Lubrication, AffineMotionEqualsRelativeTranslation)
{
    // Spheres moving and spinning with the ambient flow (U' = Omega' = 0)
    // feel the strain terms only, and these equal the force of j translating
    // past i at V = (a_i + a_j) E.n in a fluid at rest (affine-strain identity); the
    // normal part is the Reynolds squeeze at the normal speed n.V.
    std::mt19937 gen(6);
    const double eta = 0.8;
    const Lubrication lub = makeLubrication(1e-14, leading, eta);

    for (const double ratio : sizeRatios)
    {
        const double ai = 1, aj = ratio;
        const double h = 1e-3*std::min(ai, aj);
        const PairGeometry g = pairAt(ai, aj, h, randomUnit(gen));
        const Mat3 E = randomStrain(gen);

        PairKinematics affine = still();
        affine.Ei = E;
        affine.Ej = E;
        const PairForce fa = lub.eval(g, affine);

        PairKinematics relative = still();
        relative.uj = (ai + aj)*E*g.n;
        const PairForce fr = lub.eval(g, relative);

        const double tol = 1e-13*forceScale(lub, g, relative);
        EXPECT_NEAR((fa.F - fr.F).norm(), 0, tol) << "ratio " << ratio;
        EXPECT_NEAR((fa.Ti - fr.Ti).norm(), 0, tol) << "ratio " << ratio;
        EXPECT_NEAR((fa.Tj - fr.Tj).norm(), 0, tol) << "ratio " << ratio;

        // Reynolds: i is pulled towards a receding j (n.V > 0) and vice versa
        const double nV = (ai + aj)*g.n.dot(E*g.n);
        const double exact = reynolds(eta, ai, aj, nV, h);
        EXPECT_NEAR(fa.F.dot(g.n), exact, 1e-9*std::abs(exact))
            << "ratio " << ratio;
    }
}
