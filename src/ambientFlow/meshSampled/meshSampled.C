#include "meshSampled.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "fvcGrad.H"
#include "fvcLaplacian.H"
#include "indexedOctree.H"
#include "treeDataCell.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(meshSampled, 0);
    addToRunTimeSelectionTable(ambientFlow, meshSampled, dictionary);
}

const Foam::scalar Foam::meshSampled::boundaryTolerance = 1e-9;


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
    U.primitiveFieldRef() = flow.U(C.primitiveField());
    forAll(U.boundaryField(), patchi)
    {
        U.boundaryFieldRef()[patchi] == flow.U(C.boundaryField()[patchi]);
    }
    return tU;
}


Foam::label Foam::meshSampled::cell(const point& p) const
{
    const label celli = mesh_.findCell(p);
    if (celli >= 0)
    {
        return celli;
    }

    // Not inside any cell's tets: p may be on the boundary (a particle on a
    // face of the Lees-Edwards box, within round-off). It belongs to the
    // nearest cell if p moved towards that cell's centre by tolerance_ is in
    // it; otherwise it is outside the mesh.
    const label nearest =
        mesh_.cellTree().findNearest(p, magSqr(mesh_.bounds().span())).index();
    if (nearest < 0)
    {
        return -1;
    }
    const vector d = mesh_.cellCentres()[nearest] - p;
    const scalar dist = mag(d);
    const point q = p + min(scalar(1), tolerance_/(dist + VSMALL))*d;
    return mesh_.pointInCell(q, nearest) ? nearest : -1;
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
    flow_(readFlow(dict, box, mesh)),
    mesh_(requireMesh(dict, mesh)),
    U_(sampled(mesh_, flow_())),
    gradU_(fvc::grad(U_)),
    laplacianU_(fvc::laplacian(U_)),
    gradLaplacianU_(fvc::grad(laplacianU_)),
    interpolateU_(U_),
    interpolateGradU_(gradU_),
    interpolateLaplacianU_(laplacianU_),
    interpolateGradLaplacianU_(gradLaplacianU_),
    tolerance_(boundaryTolerance*mag(mesh_.bounds().span()))
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

bool Foam::meshSampled::sample
(
    const point& p,
    ambientFlowSample& values
) const
{
    const label celli = cell(p);
    if (celli < 0)
    {
        return false;
    }
    values.U = interpolateU_.interpolate(p, celli);
    values.gradU = interpolateGradU_.interpolate(p, celli);
    values.laplacianU = interpolateLaplacianU_.interpolate(p, celli);
    values.gradLaplacianU = interpolateGradLaplacianU_.interpolate(p, celli);
    return true;
}


Foam::scalar Foam::meshSampled::shearRate() const
{
    return flow_->shearRate();
}


Foam::scalar Foam::meshSampled::maxVelocityGradient() const
{
    return flow_->maxVelocityGradient();
}


Foam::boundBox Foam::meshSampled::bounds() const
{
    return mesh_.bounds();
}


// ************************************************************************* //
