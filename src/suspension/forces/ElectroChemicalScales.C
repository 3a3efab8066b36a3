#include "forces/ElectroChemicalScales.H"

namespace suspension
{

ElectroChemicalScales::ElectroChemicalScales(const Params& p)
:
    p_(p)
{
    const char* model = "ElectroChemicalScales";
    checkPositive(model, "shearRateRatio", p.shearRateRatio);
    checkPositive(model, "forceRatio", p.forceRatio);
    checkPositive(model, "epsilonFraction", p.epsilonFraction);
}


double ElectroChemicalScales::FER() const
{
    return 1/p_.shearRateRatio;                                 // eq. (14)
}


double ElectroChemicalScales::hamaker() const
{
    const double eps = p_.epsilonFraction;                      // abar = a0 = 1
    return 12*eps*eps*FER()/p_.forceRatio;                      // eqs. (6), (7)
}


ElectrostaticRepulsion::Params ElectroChemicalScales::repulsion
(
    double lambdaD
) const
{
    ElectrostaticRepulsion::Params r;
    r.FER = FER();
    r.lambdaD = lambdaD;
    return r;
}


VanDerWaalsAttraction::Params ElectroChemicalScales::attraction() const
{
    VanDerWaalsAttraction::Params a;
    a.A = hamaker();
    a.epsilonFraction = p_.epsilonFraction;
    return a;
}


ElectroChemicalScales ElectroChemicalScales::read
(
    const ModelInput& electroChemical
)
{
    Params p;
    p.shearRateRatio = electroChemical.scalar
    (
        "shearRateRatio", ModelInput::Range::positive(),
        "gammaDot/gammaDot0 (eq. 14)"
    );
    p.forceRatio = electroChemical.scalar
    (
        "forceRatio", ModelInput::Range::positive(), "F^R/F^A at contact"
    );
    return ElectroChemicalScales(p);
}

} // namespace suspension
