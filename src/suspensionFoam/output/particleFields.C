#include "particleFields.H"
#include "volFields.H"
#include "zeroGradientFvPatchFields.H"
#include "ambientFlowAdapter.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A zero field of the mesh at its current time, zero-gradient boundaries
template<class Type>
Foam::tmp<Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>>
newField
(
    const Foam::fvMesh& mesh,
    const Foam::word& name,
    const Foam::dimensionSet& dims
)
{
    using namespace Foam;
    return tmp<GeometricField<Type, fvPatchField, volMesh>>::New
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
        zeroGradientFvPatchField<Type>::typeName
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::writeParticleFields
(
    const fvMesh& mesh,
    const suspension::Particles& p,
    const std::vector<suspension::Mat3>& S,
    const labelList& cells
)
{
    tmp<volSymmTensorField> tstress =
        newField<symmTensor>(mesh, "particleStress", dimPressure);
    tmp<volScalarField> talpha = newField<scalar>(mesh, "alpha", dimless);
    symmTensorField& stress = tstress.ref().primitiveFieldRef();
    scalarField& alpha = talpha.ref().primitiveFieldRef();

    forAll(cells, i)
    {
        stress[cells[i]] += symm(toFoam(S[i]));
        alpha[cells[i]] += sphereVolume(p.a[i]);
    }
    stress /= mesh.V().field();
    alpha /= mesh.V().field();

    tstress.ref().correctBoundaryConditions();
    talpha.ref().correctBoundaryConditions();
    tstress().write();
    talpha().write();
}


// ************************************************************************* //
