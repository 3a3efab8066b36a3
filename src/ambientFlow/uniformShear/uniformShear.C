#include "uniformShear.H"
#include "ambientFlowAdapter.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(uniformShear, 0);
    addToRunTimeSelectionTable(ambientFlow, uniformShear, dictionary);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

suspension::FlowSample Foam::uniformShear::sample(const point& p) const
{
    return flow_.sample(toEigen(p));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::uniformShear::uniformShear
(
    const vector& box,
    const suspension::ShearFlow& flow
)
:
    ambientFlow(box),
    flow_(flow)
{}


Foam::uniformShear::uniformShear
(
    const dictionary& dict,
    const vector& box,
    const fvMesh*
)
:
    uniformShear(box, suspension::ShearFlow(dict.get<scalar>("shearRate")))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::uniformShear::U(const point& p) const
{
    return toFoam(sample(p).U);
}


Foam::tensor Foam::uniformShear::gradU(const point& p) const
{
    return toFoam(sample(p).gradU);
}


Foam::vector Foam::uniformShear::laplacianU(const point& p) const
{
    return toFoam(sample(p).laplacianU);
}


Foam::tensor Foam::uniformShear::gradLaplacianU(const point& p) const
{
    return toFoam(sample(p).gradLaplacianU);
}


Foam::scalar Foam::uniformShear::shearRate() const
{
    return flow_.shearRate();
}


Foam::scalar Foam::uniformShear::maxVelocityGradient() const
{
    return flow_.maxVelocityGradient();
}


// ************************************************************************* //
