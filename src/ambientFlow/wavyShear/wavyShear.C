#include "wavyShear.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "flow/ShearFlow.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(wavyShear, 0);
    addToRunTimeSelectionTable(ambientFlow, wavyShear, dictionary);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Read and check the entries of eq. (17); Ly is the y edge of the box
std::unique_ptr<const suspension::ShearFlow> readWavyShear
(
    const Foam::dictionary& dict,
    const Foam::vector& box
)
{
    using namespace Foam;

    checkEntries(dict, {"type", "shearRate", "shearStress", "amplitude", "periods"});

    const interval finite = interval::open(-GREAT, GREAT);
    const scalar amplitude = getScalarIn(dict, "amplitude", finite);
    const scalar n = dict.get<scalar>("periods");

    if (n < 1 || n != std::round(n))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'periods' = " << n << " in dictionary " << dict.name()
            << " must be an integer >= 1: whole periods over the box"
            << " height Ly keep the flow periodic in y" << nl
            << exit(FatalIOError);
    }

    const scalar Ly = box.y();

    if (!(Ly > 0))
    {
        FatalIOErrorInFunction(dict)
            << "box height Ly must be positive, got Ly = " << Ly
            << " (box " << box << ") for dictionary " << dict.name() << nl
            << exit(FatalIOError);
    }

    return std::make_unique<const suspension::ShearFlow>
    (
        0.0, amplitude, n, Ly
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wavyShear::wavyShear
(
    const dictionary& dict,
    const vector& box,
    const fvMesh*
)
:
    uniformShear(dict, box, readWavyShear(dict, box))
{}


// ************************************************************************* //
