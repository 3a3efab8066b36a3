#include "meshInterpolation.H"
#include "fvcGrad.H"
#include "fvcLaplacian.H"
#include "indexedOctree.H"
#include "treeDataCell.H"
#include "volPointInterpolation.H"
#include "cellPointWeight.H"
#include "syncTools.H"

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

//- The points of mesh on coupled patches (cyclic, processor) and on no
//  other patch (of any processor)
Foam::labelList coupledOnlyPoints(const Foam::polyMesh& mesh)
{
    using namespace Foam;
    boolList coupled(mesh.nPoints(), false);
    boolList other(mesh.nPoints(), false);
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        boolList& on = pp.coupled() ? coupled : other;
        for (const label pointi : pp.meshPoints())
        {
            on[pointi] = true;
        }
    }
    syncTools::syncPointList(mesh, other, orEqOp<bool>(), false);
    DynamicList<label> points;
    forAll(coupled, pointi)
    {
        if (coupled[pointi] && !other[pointi])
        {
            points.append(pointi);
        }
    }
    return labelList(std::move(points));
}


//- The values of the cell field psi at the points: volPointInterpolation's,
//  but at the coupledPoints the inverse-distance mean over the cells
//  around the point on every side (Description)
template<class Type>
Foam::Field<Type> pointValues
(
    const Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>& psi,
    const Foam::labelList& coupledPoints
)
{
    using namespace Foam;
    const fvMesh& mesh = psi.mesh();
    Field<Type> values
    (
        volPointInterpolation::New(mesh).interpolate(psi)().primitiveField()
    );
    scalarField weight(mesh.nPoints(), 0);
    Field<Type> sum(mesh.nPoints(), Zero);
    for (const label pointi : coupledPoints)
    {
        for (const label celli : mesh.pointCells()[pointi])
        {
            const scalar w =
                1/mag(mesh.points()[pointi] - mesh.cellCentres()[celli]);
            weight[pointi] += w;
            sum[pointi] += w*psi[celli];
        }
    }
    syncTools::syncPointList(mesh, weight, plusEqOp<scalar>(), scalar(0));
    syncTools::syncPointList(mesh, sum, plusEqOp<Type>(), Type(Zero));
    for (const label pointi : coupledPoints)
    {
        values[pointi] = sum[pointi]/weight[pointi];
    }
    return values;
}


//- The cell-point interpolate of the cell values psi and the point values
//  psip with the weights w (interpolationCellPoint::interpolate)
template<class Type>
Type interpolate
(
    const Foam::cellPointWeight& w,
    const Foam::UList<Type>& psi,
    const Foam::UList<Type>& psip
)
{
    const Foam::barycentric& b = w.weights();
    const Foam::triFace& tri = w.faceVertices();
    Type t = psi[w.cell()]*b[0];
    t += psip[tri[0]]*b[1];
    t += psip[tri[1]]*b[2];
    t += psip[tri[2]]*b[3];
    return t;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshInterpolation::fields::fields
(
    const volVectorField& field,
    const labelList& coupledPoints
)
:
    U(unregistered(field.name() + "Sampled", tmp<volVectorField>(field))),
    gradU(unregistered("grad(" + U.name() + ")", fvc::grad(U))),
    laplacianU(unregistered("laplacian(" + U.name() + ")", fvc::laplacian(U))),
    gradLaplacianU
    (
        unregistered("grad(" + laplacianU.name() + ")", fvc::grad(laplacianU))
    ),
    pointU(pointValues(U, coupledPoints)),
    pointGradU(pointValues(gradU, coupledPoints)),
    pointLaplacianU(pointValues(laplacianU, coupledPoints)),
    pointGradLaplacianU(pointValues(gradLaplacianU, coupledPoints))
{}


Foam::meshInterpolation::meshInterpolation(const volVectorField& U)
:
    mesh_(U.mesh()),
    tolerance_(boundaryTolerance*mag(mesh_.bounds().span())),
    localBounds_
    (
        boundBox(mesh_.points(), false).min() - vector::uniform(tolerance_),
        boundBox(mesh_.points(), false).max() + vector::uniform(tolerance_)
    ),
    coupledPoints_(coupledOnlyPoints(mesh_)),
    fields_(new fields(U, coupledPoints_))
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
    // Farther than tolerance_ outside the bounding box of this processor's
    // points: in no cell, even moved by tolerance_ (most of the ghosts of
    // a decomposed run)
    if (!localBounds_.contains(p))
    {
        return -1;
    }
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
    fields_.reset(new fields(U, coupledPoints_));
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
    const cellPointWeight w(mesh_, p, celli);
    values.U = interpolate(w, f.U, f.pointU);
    values.gradU = interpolate(w, f.gradU, f.pointGradU);
    values.laplacianU = interpolate(w, f.laplacianU, f.pointLaplacianU);
    values.gradLaplacianU =
        interpolate(w, f.gradLaplacianU, f.pointGradLaplacianU);
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
