#include "forces/VanDerWaalsAttraction.H"
#include "forces/PairRadii.H"

#include <algorithm>

namespace suspension
{

VanDerWaalsAttraction::VanDerWaalsAttraction(const Params& p)
:
    p_(p)
{
    const char* model = "VanDerWaalsAttraction";
    checkPositive(model, "A", p.A);
    checkPositive(model, "epsilonFraction", p.epsilonFraction);
    checkNonNegative(model, "cutoffGap", p.cutoffGap);
}


PairForce VanDerWaalsAttraction::eval(const PairGeometry& g) const
{
    PairForce f;
    if (g.dist >= range(g.ai, g.aj))
    {
        return f;
    }

    // Overlap (h < 0) feels the contact value                      eq. (7a)
    const double abar = harmonicRadius(g.ai, g.aj);
    const double eps = p_.epsilonFraction*abar;
    const double h = std::max(g.h, 0.0);
    f.F = p_.A*abar/(12*(h*h + eps*eps))*g.n;
    f.S = symm(outer(g.r, f.F));                                // eq. (9d)
    return f;
}

} // namespace suspension
