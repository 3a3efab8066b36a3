#include "oscillatoryShear.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace Function1Types
{
    makeScalarFunction1(oscillatoryShear);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::Function1Types::oscillatoryShear::oscillatoryShear
(
    const word& entryName,
    const dictionary& dict
)
:
    Function1<scalar>(entryName),
    gamma0_(getScalarIn(dict, "strainAmplitude", interval::positive())),
    omega_(getScalarIn(dict, "omega", interval::positive()))
{
    checkEntries(dict, {"type", "strainAmplitude", "omega"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::Function1Types::oscillatoryShear::value(const scalar t) const
{
    return gamma0_*omega_*std::cos(omega_*t);
}


Foam::scalar Foam::Function1Types::oscillatoryShear::integrate
(
    const scalar t1,
    const scalar t2
) const
{
    return gamma0_*(std::sin(omega_*t2) - std::sin(omega_*t1));
}


void Foam::Function1Types::oscillatoryShear::writeData(Ostream& os) const
{
    os.beginBlock(name());
    os.writeEntry("type", type());
    os.writeEntry("strainAmplitude", gamma0_);
    os.writeEntry("omega", omega_);
    os.endBlock();
}


// ************************************************************************* //
