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

//- Read and check the entries of simple shear
std::unique_ptr<const suspension::ShearFlow> readUniformShear
(
    const Foam::dictionary& dict
)
{
    using namespace Foam;

    checkEntries(dict, {"type", "shearRate"});

    return std::make_unique<const suspension::ShearFlow>
    (
        getScalarIn(dict, "shearRate", interval::open(-GREAT, GREAT))
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::uniformShear::uniformShear
(
    const vector& box,
    std::unique_ptr<const suspension::ShearFlow> flow
)
:
    ambientFlow(box),
    flow_(std::move(flow))
{}


Foam::uniformShear::uniformShear
(
    const dictionary& dict,
    const vector& box,
    const fvMesh*
)
:
    uniformShear(box, readUniformShear(dict))
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::uniformShear::~uniformShear() = default;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::uniformShear::sample
(
    const point& p,
    ambientFlowSample& values
) const
{
    values = toFoam(flow_->sample(toEigen(p)));
    return true;
}


Foam::scalar Foam::uniformShear::shearRate() const
{
    return flow_->shearRate();
}


Foam::scalar Foam::uniformShear::maxVelocityGradient() const
{
    return flow_->maxVelocityGradient();
}


// ************************************************************************* //
