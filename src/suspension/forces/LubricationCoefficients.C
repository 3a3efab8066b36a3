#include "forces/LubricationCoefficients.H"

#include "core/Vector.H"

#include <algorithm>
#include <cmath>

namespace suspension
{

namespace
{
    using Gap = LubricationCoefficients::Gap;
    using Entries = LubricationCoefficients::Entries;

    //- Entries 11 and 12 of one function in units of c_k eta a_1^k, as
    //  functions of lambda = a_2/a_1 and id = 1/(1 + lambda) (Kim & Karrila
    //  normalisation)
    struct Reduced
    {
        double self;    // 11
        double cross;   // 12
    };

    //- X-type series g1/xi + g2 L + g3 xi L
    inline double seriesX(const Gap& s, double g1, double g2, double g3)
    {
        return g1*s.inv + g2*s.logX + g3*s.xiLog;
    }

    //- Y-type series g2 L + g3 xi L
    inline double seriesY(const Gap& s, double g2, double g3)
    {
        return g2*s.log + g3*s.xiLog;
    }


    // One struct per function: k (power of length), c (c_k/(pi eta)),
    // p (parity under relabelling), and the 11, 12 entries (the g's of
    // JO 1984 for A, B, C and J92 for G, H). The JO/J92 12 entries carry the prefactor
    // pi eta (a_1 + a_2)^k and a form factor in (1 + lambda); both are
    // folded into `cross` here, using a_1 + a_2 = a_1 (1 + lambda).
    // "(A.7)" gives the paper's g (units of 6 pi eta, alpha = lambda), as
    // corrected in LubricationCoefficients.H; the leading terms equal it.

    //- X^A: X_11 = 6 pi eta a_1 (g1/xi + g2 L + g3 xi L);
    //  -(1 + lambda)/2 X_12 = same series with prefactor 3 pi eta (a_1 + a_2),
    //  so X_12 = -X_11 (JO 3.17).
    //  (A.7): ii = 2 a_i alpha^2/(1 + alpha)^3,
    //         ij = -2 (a_i + a_j) alpha^2/(1 + alpha)^4
    struct XAFunction
    {
        static constexpr int k = 1;
        static constexpr double c = 6, p = 1;

        static Reduced eval(double l, double id, const Gap& s)
        {
            const double id3 = id*id*id;
            const double v = seriesX
            (
                s,
                2*l*l*id3,
                l*(1 + 7*l + l*l)*(1.0/5)*id3,
                (1 + 18*l - 29*l*l + 18*l*l*l + l*l*l*l)*(1.0/42)*id3
            );
            return {v, -v};
        }
    };

    //- Y^A: as X^A without the 1/xi term, Y_12 = -Y_11 (JO 4.15-4.16).
    //  (A.7): ii = (4 a_i/15) alpha (2 + alpha + 2 alpha^2)/(1 + alpha)^3,
    //         ij = -(4 (a_i + a_j)/15) alpha (2 + alpha + 2 alpha^2)
    //              /(1 + alpha)^4
    struct YAFunction
    {
        static constexpr int k = 1;
        static constexpr double c = 6, p = 1;

        static Reduced eval(double l, double id, const Gap& s)
        {
            const double id3 = id*id*id;
            const double v = seriesY
            (
                s,
                4*l*(2 + l + 2*l*l)*(1.0/15)*id3,
                2*(16 - 45*l + 58*l*l - 45*l*l*l + 16*l*l*l*l)*(1.0/375)*id3
            );
            return {v, -v};
        }
    };

    //- Y^B: Y_11 = 4 pi eta a_1^2 (g2 L + g3 xi L);
    //  -(1 + lambda)^2/4 Y_12 = same series with prefactor
    //  pi eta (a_1 + a_2)^2, so Y_12 = -Y_11 (JO 5.6). Normalisation
    //  4 pi eta a_1^2, not 8 (the rigid-rotation identity and the
    //  sphere-wall limit require it).
    //  (A.7): ii = -(2 a_i^2/15) alpha (4 + alpha)/(1 + alpha)^2,
    //         ij = (2 (a_i + a_j)^2/15) alpha (4 + alpha)/(1 + alpha)^4
    struct YBFunction
    {
        static constexpr int k = 2;
        static constexpr double c = 4, p = -1;

        static Reduced eval(double l, double id, const Gap& s)
        {
            const double id2 = id*id;
            const double v = seriesY
            (
                s,
                -l*(4 + l)*(1.0/5)*id2,
                -(32 - 33*l + 83*l*l + 43*l*l*l)*(1.0/250)*id2
            );
            return {v, -v};
        }
    };

    //- Y^C: Y_11 = 8 pi eta a_1^3 (g2 L + g3 xi L);
    //  Y_12 = pi eta (a_1 + a_2)^3 (g4 L + g5 xi L) (JO 7.10).
    //  (A.7): ii = (8 a_i^3/15) alpha/(1 + alpha),
    //         ij = (2 (a_i + a_j)^3/15) alpha^2/(1 + alpha)^4
    struct YCFunction
    {
        static constexpr int k = 3;
        static constexpr double c = 8, p = 1;

        static Reduced eval(double l, double id, const Gap& s)
        {
            // (1 + lambda)^3/8 times the JO 12 series in (1 + lambda)^-4
            return
            {
                seriesY
                (
                    s,
                    2*l*(1.0/5)*id,
                    (8 + 6*l + 33*l*l)*(1.0/125)*id
                ),
                (1.0/8)*id*seriesY
                (
                    s,
                    4*l*l*(1.0/5),
                    2*l*(43 - 24*l + 43*l*l)*(1.0/125)
                )
            };
        }
    };

    //- X^G: X_11 = 4 pi eta a_1^2 (g1/xi + g2 L + g3 xi L);
    //  -(1 + lambda)^2/4 X_12 = same series with prefactor
    //  pi eta (a_1 + a_2)^2, so X_12 = -X_11 (J92 19).
    //  (A.7): ii = 2 a_i^2 alpha^2/(1 + alpha)^3,
    //         ij = -2 (a_i + a_j)^2 alpha^2/(1 + alpha)^5
    //  (the paper's jj and ji rules are mislabelled ij and jj)
    struct XGFunction
    {
        static constexpr int k = 2;
        static constexpr double c = 4, p = -1;

        static Reduced eval(double l, double id, const Gap& s)
        {
            const double id3 = id*id*id;
            const double v = seriesX
            (
                s,
                3*l*l*id3,
                3*l*(1 + 12*l - 4*l*l)*(1.0/10)*id3,
                (5 + 181*l - 453*l*l + 566*l*l*l - 65*l*l*l*l)*(1.0/140)*id3
            );
            return {v, -v};
        }
    };

    //- Y^G: as X^G without the 1/xi term, Y_12 = -Y_11 (J92 27).
    //  (A.7): ii = (a_i^2/15) alpha (4 - alpha + 7 alpha^2)/(1 + alpha)^3,
    //         ij = -((a_i + a_j)^2/15) alpha (4 - alpha + 7 alpha^2)
    //              /(1 + alpha)^5
    //  (the paper swaps the labels ii and ij, and labels ji as jj)
    struct YGFunction
    {
        static constexpr int k = 2;
        static constexpr double c = 4, p = -1;

        static Reduced eval(double l, double id, const Gap& s)
        {
            const double id3 = id*id*id;
            const double v = seriesY
            (
                s,
                l*(4 - l + 7*l*l)*(1.0/10)*id3,
                (32 - 179*l + 532*l*l - 356*l*l*l + 221*l*l*l*l)*(1.0/500)*id3
            );
            return {v, -v};
        }
    };

    //- Y^H: Y_11 = 8 pi eta a_1^3 (g2 L + g3 xi L);
    //  (1 + lambda)^3/8 Y_12 = (g5 L + g6 xi L) with prefactor
    //  pi eta (a_1 + a_2)^3, so Y_12 = 8 pi eta a_1^3 (g5 L + g6 xi L)
    //  (J92 35).
    //  (A.7): ii = (2 a_i^3/15) alpha (2 - alpha)/(1 + alpha)^2,
    //         ij = ((a_i + a_j)^3/15) alpha^2 (1 + 7 alpha)/(1 + alpha)^5
    //  (the paper's ji rule refers to Y^G instead of Y^H)
    struct YHFunction
    {
        static constexpr int k = 3;
        static constexpr double c = 8, p = 1;

        static Reduced eval(double l, double id, const Gap& s)
        {
            const double id2 = id*id;
            return
            {
                seriesY
                (
                    s,
                    l*(2 - l)*(1.0/10)*id2,
                    (16 - 61*l + 180*l*l + 2*l*l*l)*(1.0/500)*id2
                ),
                seriesY
                (
                    s,
                    l*l*(1 + 7*l)*(1.0/20)*id2,
                    l*(43 + 147*l - 185*l*l + 221*l*l*l)*(1.0/1000)*id2
                )
            };
        }
    };


    //- Radii of the pair and the ratios the functions need, for (i, j) and
    //  for the relabelled pair (j, i)
    struct Radii
    {
        double aiPow[4];    // a_i^k
        double ajPow[4];    // a_j^k
        double lambda;      // a_j/a_i
        double lambdaInv;   // a_i/a_j
        double idI;         // 1/(1 + lambda)    = a_i/(a_i + a_j)
        double idJ;         // 1/(1 + 1/lambda)  = a_j/(a_i + a_j)

        Radii(double ai, double aj)
        :
            aiPow{1, ai, ai*ai, ai*ai*ai},
            ajPow{1, aj, aj*aj, aj*aj*aj},
            lambda(aj/ai),
            lambdaInv(ai/aj),
            idI(ai/(ai + aj)),
            idJ(aj/(ai + aj))
        {}
    };


    //- The four dimensional entries of one function. Relabelling (JO
    //  1984): F_22(a_i, a_j) = p F_11(a_j, a_i),
    //  F_21(a_i, a_j) = p F_12(a_j, a_i)
    template<class Function>
    Entries entries(const Radii& r, double eta, const Gap& s)
    {
        const Reduced f = Function::eval(r.lambda, r.idI, s);
        const Reduced fSwapped = Function::eval(r.lambdaInv, r.idJ, s);
        const double unit = Function::c*pi*eta;
        const double unitI = unit*r.aiPow[Function::k];
        const double unitJ = Function::p*unit*r.ajPow[Function::k];
        return
        {
            unitI*f.self,
            unitI*f.cross,
            unitJ*fSwapped.cross,
            unitJ*fSwapped.self
        };
    }
}


LubricationCoefficients::Gap LubricationCoefficients::Gap::make
(
    double xi,
    double epsilon,
    LubricationTerms terms
)
{
    // (A.6): xi_e = xi + epsilon, with xi = 0 for overlapping pairs
    const double xiE = std::max(xi, 0.0) + epsilon;

    // L = ln(1/xi_e), set to 0 when 1/xi_e <= 1
    const double L = xiE < 1 ? -std::log(xiE) : 0;

    const bool extended = terms == LubricationTerms::extended;
    return Gap{1/xiE, L, extended ? L : 0, extended ? xiE*L : 0};
}


LubricationCoefficients::LubricationCoefficients
(
    double ai,
    double aj,
    const Gap& gap,
    double eta
)
{
    const Radii r(ai, aj);
    XA = entries<XAFunction>(r, eta, gap);
    YA = entries<YAFunction>(r, eta, gap);
    YB = entries<YBFunction>(r, eta, gap);
    YC = entries<YCFunction>(r, eta, gap);
    XG = entries<XGFunction>(r, eta, gap);
    YG = entries<YGFunction>(r, eta, gap);
    YH = entries<YHFunction>(r, eta, gap);
}



LubricationFactors::LubricationFactors(double ai, double aj, double eta)
:
    basis
    {
        LubricationCoefficients(ai, aj, Gap{1, 0, 0, 0}, eta),
        LubricationCoefficients(ai, aj, Gap{0, 1, 0, 0}, eta),
        LubricationCoefficients(ai, aj, Gap{0, 0, 1, 0}, eta),
        LubricationCoefficients(ai, aj, Gap{0, 0, 0, 1}, eta)
    }
{}


LubricationCoefficients LubricationFactors::at
(
    const LubricationCoefficients::Gap& gap
) const
{
    using C = LubricationCoefficients;
    using Entries = C::Entries;
    static constexpr Entries C::* functions[] =
        {&C::XA, &C::YA, &C::YB, &C::YC, &C::XG, &C::YG, &C::YH};
    const double g[4] = {gap.inv, gap.log, gap.logX, gap.xiLog};

    // The leading terms have logX = xiLog = 0: two of the four basis
    // scalars are then skipped
    const int nTerms = (gap.logX != 0 || gap.xiLog != 0) ? 4 : 2;
    C c;
    for (Entries C::* f : functions)
    {
        Entries v{0, 0, 0, 0};
        for (int k = 0; k < nTerms; ++k)
        {
            const Entries& b = basis[k].*f;
            v.ii += g[k]*b.ii;
            v.ij += g[k]*b.ij;
            v.ji += g[k]*b.ji;
            v.jj += g[k]*b.jj;
        }
        c.*f = v;
    }
    return c;
}

} // namespace suspension
