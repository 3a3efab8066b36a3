#include "suspensionFields.H"
#include "suspensionCloud.H"
#include "volFields.H"
#include "zeroGradientFvPatchFields.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(suspensionFields, 0);
    addToRunTimeSelectionTable(functionObject, suspensionFields, dictionary);
}
}

const Foam::wordList
Foam::functionObjects::suspensionFields::particleFieldNames
({
    "particleStress", "alpha"
});


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


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::functionObjects::suspensionFields::writeParticleFields() const
{
    const suspensionCloud& cloud = suspensionCloud::lookup(mesh_, name());
    const suspension::Particles& p = cloud.simulation().particles();
    const std::vector<suspension::Mat3>& S = cloud.particleStresslets();
    const labelList cells = cloud.particleCells();

    if (fields_.found("particleStress"))
    {
        tmp<volSymmTensorField> tstress =
            newField<symmTensor>(mesh_, "particleStress", dimPressure);
        symmTensorField& stress = tstress.ref().primitiveFieldRef();
        forAll(cells, i)
        {
            if (cells[i] >= 0)
            {
                stress[cells[i]] += symm(toFoam(S[i]));
            }
        }
        stress /= mesh_.V().field();
        tstress.ref().correctBoundaryConditions();
        tstress().write();
    }

    if (fields_.found("alpha"))
    {
        tmp<volScalarField> talpha = newField<scalar>(mesh_, "alpha", dimless);
        scalarField& alpha = talpha.ref().primitiveFieldRef();
        forAll(cells, i)
        {
            if (cells[i] >= 0)
            {
                alpha[cells[i]] += sphereVolume(p.a[i]);
            }
        }
        alpha /= mesh_.V().field();
        talpha.ref().correctBoundaryConditions();
        talpha().write();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::suspensionFields::suspensionFields
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    fields_()
{
    read(dict);

    if
    (
        dict.getOrDefault<bool>("writeAtStart", true)
     && suspensionCloud::lookup(mesh_, name).newPackingWritten()
    )
    {
        write();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::suspensionFields::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);

    wordList valid(ambientFlow::fieldNames);
    valid.append(particleFieldNames);
    const wordList selected(dict.getOrDefault<wordList>("fields", valid));
    for (const word& f : selected)
    {
        if (!valid.found(f))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown field '" << f << "' in entry 'fields' of"
                << " function object " << name() << nl
                << "Valid fields: " << valid << nl
                << exit(FatalIOError);
        }
    }
    fields_ = wordHashSet(selected);

    return true;
}


bool Foam::functionObjects::suspensionFields::execute()
{
    return true;
}


bool Foam::functionObjects::suspensionFields::write()
{
    suspensionCloud::lookup(mesh_, name()).flow().writeFields(mesh_, fields_);
    writeParticleFields();

    return true;
}


// ************************************************************************* //
