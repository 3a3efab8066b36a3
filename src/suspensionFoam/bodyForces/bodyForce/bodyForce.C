#include "bodyForce.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bodyForce, 0);
    defineRunTimeSelectionTable(bodyForce, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyForce::bodyForce(const vector& box)
:
    box_(box)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField> Foam::bodyForce::field
(
    const fvMesh& mesh
) const
{
    tmp<volVectorField> tf
    (
        new volVectorField
        (
            IOobject
            (
                "bodyForce",
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            mesh,
            dimensionedVector(dimForce/dimVolume, Zero)
        )
    );
    volVectorField& f = tf.ref();
    forAll(f, celli)
    {
        f[celli] = value(mesh.C()[celli]);
    }
    f.correctBoundaryConditions();
    return tf;
}


// ************************************************************************* //
