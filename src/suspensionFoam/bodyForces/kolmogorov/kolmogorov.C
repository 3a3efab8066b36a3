#include "kolmogorov.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyForces
{
    defineTypeNameAndDebug(kolmogorov, 0);
    addToRunTimeSelectionTable(bodyForce, kolmogorov, dictionary);
}
}


// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

const Foam::dictionary& checked(const Foam::dictionary& dict)
{
    Foam::checkEntries(dict, {"type", "amplitude", "periods"});
    return dict;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyForces::kolmogorov::kolmogorov
(
    const dictionary& dict,
    const vector& box
)
:
    bodyForce(box),
    F_(getScalarIn(checked(dict), "amplitude", interval::open(-GREAT, GREAT))),
    n_(getLabelAtLeast(dict, "periods", 1)),
    k_(constant::mathematical::twoPi*n_/box.y())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::bodyForces::kolmogorov::value(const point& p) const
{
    return vector(F_*std::sin(k_*p.y()), 0, 0);
}


// ************************************************************************* //
