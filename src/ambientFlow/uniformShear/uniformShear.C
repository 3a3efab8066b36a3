#include "uniformShear.H"
#include "ambientFlowAdapter.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "flow/ShearFlow.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(uniformShear, 0);
    addToRunTimeSelectionTable(ambientFlow, uniformShear, dictionary);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Check the entries of simple shear (the base reads shearRate): the
//  engine's flow without a wave
std::unique_ptr<const suspension::ShearFlow> readUniformShear
(
    const Foam::dictionary& dict
)
{
    Foam::checkEntries(dict, {"type", "shearRate", "shearStress"});
    return std::make_unique<const suspension::ShearFlow>(0.0);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::uniformShear::uniformShear
(
    const dictionary& dict,
    const vector& box,
    std::unique_ptr<const suspension::ShearFlow> flow
)
:
    ambientFlow(dict, box),
    flow_(std::move(flow))
{}


Foam::uniformShear::uniformShear
(
    const dictionary& dict,
    const vector& box,
    const fvMesh*
)
:
    uniformShear(dict, box, readUniformShear(dict))
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::uniformShear::~uniformShear() = default;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::uniformShear::samplePeriodic
(
    const point& p,
    ambientFlowSample& values
) const
{
    values = toFoam(flow_->sample(toEigen(p), 0));
    return true;
}


Foam::scalar Foam::uniformShear::maxPeriodicGradient() const
{
    return flow_->maxPeriodicGradient();
}


// ************************************************************************* //
