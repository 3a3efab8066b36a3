#include "forces/ElectrostaticRepulsion.H"
#include "forces/ElectroChemicalScales.H"
#include "forces/PairRadii.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace suspension
{

ElectrostaticRepulsion::ElectrostaticRepulsion(const Params& p)
:
    p_(p)
{
    const char* model = "ElectrostaticRepulsion";
    checkPositive(model, "FER", p.FER);
    checkPositive(model, "lambdaD", p.lambdaD);
    checkPositive(model, "cutoffDebyeLengths", p.cutoffDebyeLengths);
}


ElectrostaticRepulsion::Params ElectrostaticRepulsion::read
(
    const ModelInput& input
)
{
    Params p = ElectroChemicalScales::read(input.parent()).repulsion
    (
        input.scalar("debyeLength", ModelInput::Range::positive(), "lambda_D/a0")
    );
    p.cutoffDebyeLengths = input.scalar
    (
        "cutoffDebyeLengths", ModelInput::Range::positive(),
        "cut-off gap/lambda_D"
    );
    return p;
}


std::string ElectrostaticRepulsion::describe() const
{
    std::ostringstream os;
    os  << "F_ER = " << p_.FER << ", lambdaD = " << p_.lambdaD
        << ", cut-off gap " << gap() << " (" << p_.cutoffDebyeLengths << " lambdaD)";
    return os.str();
}


void ElectrostaticRepulsion::addTimeStepLimits
(
    TimeStepLimitBuilder& limits
) const
{
    addCentralForceLimit
    (
        limits, "repulsion", *this, [&](double, double) { return gap(); }
    );
}

} // namespace suspension
