#include "forces/ElectrostaticRepulsion.H"
#include "forces/PairRadii.H"

#include <algorithm>
#include <cmath>

namespace suspension
{

ElectrostaticRepulsion::ElectrostaticRepulsion(const Params& p)
:
    p_(p)
{
    const char* model = "ElectrostaticRepulsion";
    checkPositive(model, "FER", p.FER);
    checkPositive(model, "lambdaD", p.lambdaD);
    checkPositive(model, "cutoffFactor", p.cutoffFactor);
}


PairForce ElectrostaticRepulsion::eval(const PairGeometry& g) const
{
    PairForce f;
    if (g.dist >= range(g.ai, g.aj))
    {
        return f;
    }

    // Overlap (h < 0) feels the contact value                      eq. (6a)
    const double abar = harmonicRadius(g.ai, g.aj);
    const double h = std::max(g.h, 0.0);
    f.F = -p_.FER*abar*std::exp(-h/p_.lambdaD)*g.n;
    f.S = symm(outer(g.r, f.F));                                // eq. (9d)
    return f;
}


double ElectrostaticRepulsion::maxStiffness(double ai, double aj) const
{
    return p_.FER*harmonicRadius(ai, aj)/p_.lambdaD;
}

} // namespace suspension
