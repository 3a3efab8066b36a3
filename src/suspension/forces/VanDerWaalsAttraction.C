#include "forces/VanDerWaalsAttraction.H"
#include "forces/ElectroChemicalScales.H"
#include "forces/PairRadii.H"

#include <algorithm>
#include <sstream>

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


VanDerWaalsAttraction::Params VanDerWaalsAttraction::read
(
    const ModelInput& input
)
{
    using Range = ModelInput::Range;
    ElectroChemicalScales::Params scales =
        ElectroChemicalScales::read(input.parent()).params();
    scales.epsilonFraction = input.scalarOr
    (
        "epsilon", scales.epsilonFraction, Range::positive(),
        "eps/abar, regularisation of eq. (7)"
    );
    Params p = ElectroChemicalScales(scales).attraction();
    p.cutoffGap = input.scalar
    (
        "cutoffGap", Range::nonNegative(), "cut-off surface gap/a0"
    );
    return p;
}


std::string VanDerWaalsAttraction::describe() const
{
    std::ostringstream os;
    os  << "A = " << p_.A << ", eps/abar = " << p_.epsilonFraction
        << ", cut-off gap " << p_.cutoffGap;
    return os.str();
}


void VanDerWaalsAttraction::addTimeStepLimits
(
    TimeStepLimitBuilder& limits
) const
{
    addCentralForceLimit
    (
        limits, "attraction", *this,
        [](double ai, double aj) { return 0.1*std::min(ai, aj); }
    );
}

} // namespace suspension
