#include "meshSampled.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(meshSampled, 0);
    addToRunTimeSelectionTable(ambientFlow, meshSampled, dictionary);
}

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::autoPtr<Foam::ambientFlow> Foam::meshSampled::readFlow
(
    const dictionary& dict,
    const vector& box,
    const fvMesh* mesh
)
{
    checkEntries(dict, {"type", "flow"});

    return ambientFlow::New(dict.subDict("flow"), box, mesh);
}


const Foam::fvMesh& Foam::meshSampled::requireMesh
(
    const dictionary& dict,
    const fvMesh* mesh
)
{
    if (!mesh)
    {
        FatalIOErrorInFunction(dict)
            << "The ambientFlow type " << typeName << " samples its flow on"
            << " the case mesh, and none was given"
            << exit(FatalIOError);
    }
    return *mesh;
}


Foam::tmp<Foam::volVectorField> Foam::meshSampled::sampled
(
    const fvMesh& mesh,
    const ambientFlow& flow
)
{
    tmp<volVectorField> tU
    (
        new volVectorField
        (
            IOobject
            (
                "Uinf",
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh,
            dimensionedVector(dimVelocity, Zero)
        )
    );
    volVectorField& U = tU.ref();
    const volVectorField& C = mesh.C();
    U.primitiveFieldRef() = flow.periodicU(C.primitiveField());
    forAll(U.boundaryField(), patchi)
    {
        U.boundaryFieldRef()[patchi] == flow.periodicU(C.boundaryField()[patchi]);
    }
    return tU;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshSampled::meshSampled
(
    const dictionary& dict,
    const vector& box,
    const fvMesh* mesh
)
:
    ambientFlow(dict.subDict("flow"), box),
    flow_(readFlow(dict, box, mesh)),
    mesh_(requireMesh(dict, mesh)),
    interpolation_(sampled(mesh_, flow_())())
{
    Info<< "    sampled on " << mesh_.nCells() << " cells" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::meshSampled::samplePeriodic
(
    const point& p,
    ambientFlowSample& values
) const
{
    return interpolation_.sample(p, values);
}


Foam::scalar Foam::meshSampled::maxPeriodicGradient() const
{
    return flow_->maxPeriodicGradient();
}


Foam::boundBox Foam::meshSampled::bounds() const
{
    return mesh_.bounds();
}


// ************************************************************************* //
