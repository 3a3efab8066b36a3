#include "meshField.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(meshField, 0);
    addToRunTimeSelectionTable(ambientFlow, meshField, dictionary);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::volVectorField& Foam::meshField::lookupField
(
    const dictionary& dict,
    const fvMesh* mesh
)
{
    checkEntries(dict, {"type", "shearRate", "shearStress", "field"});
    const word name = fieldName(dict);
    const volVectorField* field =
        mesh ? mesh->findObject<volVectorField>(name) : nullptr;
    if (!field)
    {
        FatalIOErrorInFunction(dict)
            << "The ambientFlow type " << typeName << " takes the field '"
            << name << "' (entry 'field') that a solver registers on the"
            << " case mesh, and "
            << (mesh ? "the mesh holds no field of that name" : "there is no mesh")
            << ": suspensionCoupledFoam registers Uprime (field Uprime;)"
            << nl << exit(FatalIOError);
    }
    return *field;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshField::meshField
(
    const dictionary& dict,
    const vector& box,
    const fvMesh* mesh
)
:
    ambientFlow(dict, box),
    field_(lookupField(dict, mesh)),
    interpolation_(field_),
    maxGradU_(interpolation_.maxGradient())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::word Foam::meshField::fieldName(const dictionary& dict)
{
    return dict.getOrDefault<word>("field", "Uprime");
}


bool Foam::meshField::samplePeriodic
(
    const point& p,
    ambientFlowSample& values
) const
{
    return interpolation_.sample(p, values);
}


bool Foam::meshField::correct()
{
    // Bitwise: a field the solver set to the same values is no change
    const volVectorField& inUse = interpolation_.U();
    const auto values = [](const vectorField& f) -> const UList<vector>&
    {
        return f;
    };
    bool same = values(field_) == values(inUse);
    forAll(field_.boundaryField(), patchi)
    {
        same = same
         && values(field_.boundaryField()[patchi])
         == values(inUse.boundaryField()[patchi]);
    }
    // Collective: the processors decide together (the update and the
    // engine's continuation in the new flow are)
    if (returnReduce(same, andOp<bool>()))
    {
        return false;
    }
    interpolation_.update(field_);
    maxGradU_ = interpolation_.maxGradient();
    return true;
}


Foam::scalar Foam::meshField::maxPeriodicGradient() const
{
    return maxGradU_;
}


Foam::boundBox Foam::meshField::bounds() const
{
    return interpolation_.U().mesh().bounds();
}


// ************************************************************************* //
