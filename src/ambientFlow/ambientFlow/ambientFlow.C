#include "ambientFlow.H"
#include "ambientFlowAdapter.H"
#include "volFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(ambientFlow, 0);
    defineRunTimeSelectionTable(ambientFlow, dictionary);
}

const Foam::wordList Foam::ambientFlow::fieldNames
({
    "Uinf", "gradUinf", "shearRateInf"
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Write the field f(x) evaluated at the cell centres and at the boundary
//  face centres (calculated patches) of mesh, at the mesh's current time
template<class Type, class Function>
void writeCellAndFaceField
(
    const Foam::fvMesh& mesh,
    const Foam::word& name,
    const Foam::dimensionSet& dims,
    const Function& f
)
{
    using namespace Foam;

    GeometricField<Type, fvPatchField, volMesh> fld
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensioned<Type>(dims, Zero),
        calculatedFvPatchField<Type>::typeName
    );

    const volVectorField& C = mesh.C();

    Field<Type>& cells = fld.primitiveFieldRef();
    forAll(cells, celli)
    {
        cells[celli] = f(C[celli]);
    }

    auto& bf = fld.boundaryFieldRef();
    forAll(bf, patchi)
    {
        const fvPatchVectorField& Cf = C.boundaryField()[patchi];
        forAll(Cf, facei)
        {
            bf[patchi][facei] = f(Cf[facei]);
        }
    }

    fld.write();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ambientFlow::ambientFlow(const vector& box)
:
    box_(box)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::symmTensor Foam::ambientFlow::E(const point& p) const
{
    return symm(gradU(p));
}


Foam::vector Foam::ambientFlow::Omega(const point& p) const
{
    // *skew(T) = (T.yz - T.zy, T.zx - T.xz, T.xy - T.yx)/2 = curl(U)/2
    return *skew(gradU(p));
}


Foam::scalar Foam::ambientFlow::localShearRate(const point& p) const
{
    return gradU(p).yx();
}


void Foam::ambientFlow::writeFields
(
    const fvMesh& mesh,
    const wordHashSet& names
) const
{
    if (names.found("Uinf"))
    {
        writeCellAndFaceField<vector>
        (
            mesh, "Uinf", dimVelocity,
            [this](const point& p) { return U(p); }
        );
    }
    if (names.found("gradUinf"))
    {
        writeCellAndFaceField<tensor>
        (
            mesh, "gradUinf", dimless/dimTime,
            [this](const point& p) { return gradU(p); }
        );
    }
    if (names.found("shearRateInf"))
    {
        writeCellAndFaceField<scalar>
        (
            mesh, "shearRateInf", dimless/dimTime,
            [this](const point& p) { return localShearRate(p); }
        );
    }
}


suspension::FlowSample Foam::ambientFlow::sample(const point& p) const
{
    suspension::FlowSample f;
    f.U = toEigen(U(p));
    f.gradU = toEigen(gradU(p));
    f.laplacianU = toEigen(laplacianU(p));
    f.gradLaplacianU = toEigen(gradLaplacianU(p));
    return f;
}


// ************************************************************************* //
