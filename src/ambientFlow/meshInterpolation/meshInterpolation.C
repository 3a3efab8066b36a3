#include "meshInterpolation.H"
#include "fvcGrad.H"
#include "fvcLaplacian.H"
#include "indexedOctree.H"
#include "treeDataCell.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::meshInterpolation::boundaryTolerance = 1e-9;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The field of t under the name `name`, not registered
template<class Type>
Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh> unregistered
(
    const Foam::word& name,
    const Foam::tmp<Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>>& t
)
{
    using namespace Foam;
    return GeometricField<Type, fvPatchField, volMesh>
    (
        IOobject
        (
            name,
            t().instance(),
            t().db(),
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        t
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshInterpolation::fields::fields(const volVectorField& field)
:
    U(unregistered(field.name() + "Sampled", tmp<volVectorField>(field))),
    gradU(unregistered("grad(" + U.name() + ")", fvc::grad(U))),
    laplacianU(unregistered("laplacian(" + U.name() + ")", fvc::laplacian(U))),
    gradLaplacianU
    (
        unregistered("grad(" + laplacianU.name() + ")", fvc::grad(laplacianU))
    ),
    interpolateU(U),
    interpolateGradU(gradU),
    interpolateLaplacianU(laplacianU),
    interpolateGradLaplacianU(gradLaplacianU)
{}


Foam::meshInterpolation::meshInterpolation(const volVectorField& U)
:
    mesh_(U.mesh()),
    tolerance_(boundaryTolerance*mag(mesh_.bounds().span())),
    fields_(new fields(U))
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
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::meshInterpolation::cell(const point& p) const
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshInterpolation::update(const volVectorField& U)
{
    // The old copies go first: nothing of the same name lives twice
    fields_.reset();
    fields_.reset(new fields(U));
}


bool Foam::meshInterpolation::sample
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
    const fields& f = *fields_;
    values.U = f.interpolateU.interpolate(p, celli);
    values.gradU = f.interpolateGradU.interpolate(p, celli);
    values.laplacianU = f.interpolateLaplacianU.interpolate(p, celli);
    values.gradLaplacianU = f.interpolateGradLaplacianU.interpolate(p, celli);
    return true;
}


Foam::scalar Foam::meshInterpolation::maxGradient() const
{
    const volTensorField& g = fields_->gradU;
    scalar m = 0;
    for (const tensor& t : g.primitiveField())
    {
        m = max(m, mag(t));
    }
    for (const fvPatchTensorField& pg : g.boundaryField())
    {
        for (const tensor& t : pg)
        {
            m = max(m, mag(t));
        }
    }
    return returnReduce(m, maxOp<scalar>());
}


// ************************************************************************* //
