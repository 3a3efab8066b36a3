#include "meshSampled.H"
#include "ambientFlowAdapter.H"
#include "addToRunTimeSelectionTable.H"
#include "fvcGrad.H"
#include "fvcLaplacian.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(meshSampled, 0);
    addToRunTimeSelectionTable(ambientFlow, meshSampled, dictionary);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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
                "UinfSampled",
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            mesh,
            dimensionedVector(dimVelocity, Zero)
        )
    );
    volVectorField& U = tU.ref();
    const volVectorField& C = mesh.C();
    forAll(C, celli)
    {
        U[celli] = flow.U(C[celli]);
    }
    forAll(U.boundaryField(), patchi)
    {
        fvPatchVectorField& Up = U.boundaryFieldRef()[patchi];
        const fvPatchVectorField& Cp = C.boundaryField()[patchi];
        forAll(Up, facei)
        {
            Up[facei] = flow.U(Cp[facei]);
        }
    }
    return tU;
}


Foam::label Foam::meshSampled::cell(const point& p) const
{
    const label celli = mesh_.findCell(p);
    return celli >= 0 ? celli : mesh_.findNearestCell(p);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshSampled::meshSampled
(
    const dictionary& dict,
    const vector& box,
    const fvMesh* mesh
)
:
    ambientFlow(box),
    flow_(ambientFlow::New(dict.subDict("flow"), box, mesh)),
    mesh_(requireMesh(dict, mesh)),
    U_(sampled(mesh_, flow_())),
    gradU_(fvc::grad(U_)),
    laplacianU_(fvc::laplacian(U_)),
    gradLaplacianU_(fvc::grad(laplacianU_)),
    interpolateU_(U_),
    interpolateGradU_(gradU_),
    interpolateLaplacianU_(laplacianU_),
    interpolateGradLaplacianU_(gradLaplacianU_)
{
    // Build now what the cell search and the cell-point interpolation
    // build on first use (OpenFOAM's demand-driven mesh data): the engine
    // samples the flow from many threads
    (void)mesh_.cellTree();
    (void)mesh_.tetBasePtIs();
    (void)mesh_.cellCentres();
    (void)mesh_.faceCentres();
    (void)mesh_.faceAreas();
    (void)mesh_.cellPoints();
    (void)mesh_.pointCells();

    Info<< "    sampled on " << mesh_.nCells() << " cells" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::meshSampled::U(const point& p) const
{
    return interpolateU_.interpolate(p, cell(p));
}


Foam::tensor Foam::meshSampled::gradU(const point& p) const
{
    return interpolateGradU_.interpolate(p, cell(p));
}


Foam::vector Foam::meshSampled::laplacianU(const point& p) const
{
    return interpolateLaplacianU_.interpolate(p, cell(p));
}


Foam::tensor Foam::meshSampled::gradLaplacianU(const point& p) const
{
    return interpolateGradLaplacianU_.interpolate(p, cell(p));
}


suspension::FlowSample Foam::meshSampled::sample(const point& p) const
{
    const label celli = cell(p);
    suspension::FlowSample f;
    f.U = toEigen(interpolateU_.interpolate(p, celli));
    f.gradU = toEigen(interpolateGradU_.interpolate(p, celli));
    f.laplacianU = toEigen(interpolateLaplacianU_.interpolate(p, celli));
    f.gradLaplacianU = toEigen(interpolateGradLaplacianU_.interpolate(p, celli));
    return f;
}


Foam::scalar Foam::meshSampled::shearRate() const
{
    return flow_->shearRate();
}


Foam::scalar Foam::meshSampled::maxVelocityGradient() const
{
    return flow_->maxVelocityGradient();
}


// ************************************************************************* //
