#include "forces/StokesDrag.H"
#include "forces/ParamCheck.H"

#include <algorithm>
#include <sstream>

namespace suspension
{

StokesDrag::StokesDrag()
:
    StokesDrag(Params())
{}


StokesDrag::StokesDrag(const Params& p)
:
    p_(p)
{
    checkPositive("StokesDrag", "eta", p.eta);
}


StokesDrag::Result StokesDrag::eval
(
    double a,
    const Vec3& u,
    const Vec3& omega,
    const FlowSample& flow
) const
{
    const double a2 = a*a;
    const double a3 = a2*a;
    return Result
    {
        6*pi*p_.eta*a*(flow.U + a2/6*flow.laplacianU - u),          // eq. (A.1)
        8*pi*p_.eta*a3*(flow.Omega() - omega),                      // eq. (A.1)
        20.0/3.0*pi*p_.eta*a3*(flow.E() + a2/10*flow.lapE())        // eq. (9a)
    };
}


double StokesDrag::relaxationTime(double m, double a, double eta)
{
    return m/(6*pi*eta*a);
}


double StokesDrag::rotationalRelaxationTime(double I, double a, double eta)
{
    return I/(8*pi*eta*a*a*a);
}

std::string StokesDrag::describe() const
{
    std::ostringstream os;
    os  << "eta0 = " << p_.eta;
    return os.str();
}


void StokesDrag::addTimeStepLimits(TimeStepLimitBuilder& limits) const
{
    if (!limits.explicitHydrodynamics())
    {
        return;
    }
    const double rho = limits.rho();
    limits.addOverPairs("stokesDrag", [&](double ai, double aj)
    {
        const double a = std::min(ai, aj);
        const double m = 4.0/3.0*pi*a*a*a*rho;
        return 2*std::min
        (
            relaxationTime(m, a, p_.eta),
            rotationalRelaxationTime(0.4*m*a*a, a, p_.eta)
        );
    });
}

} // namespace suspension
