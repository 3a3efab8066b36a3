#include "noBodyForce.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyForces
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(bodyForce, none, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyForces::none::none(const dictionary& dict, const vector& box)
:
    bodyForce(box)
{
    checkEntries(dict, {"type"});
}


// ************************************************************************* //
