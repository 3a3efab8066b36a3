/*---------------------------------------------------------------------------*\
Class
    Foam::functionObjects::particleCount

Description
    A user's function object, as a case test would write one: it finds the
    suspension cloud of wavyShearFoam in the mesh by name alone and appends
    the time, the number of particles and the engine's strain to
    postProcessing/<name>/<startTime>/particleCount.dat.

Usage
    \verbatim
    count
    {
        type            particleCount;
        libs            (suspensionTestFunctionObjects);
        writeControl    timeStep;
    }
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "fvMeshFunctionObject.H"
#include "writeFile.H"
#include "suspensionCloud.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{

class particleCount
:
    public fvMeshFunctionObject,
    public writeFile
{
public:

    TypeName("particleCount");

    particleCount(const word& name, const Time& runTime, const dictionary& dict)
    :
        fvMeshFunctionObject(name, runTime, dict),
        writeFile(mesh_, name, "particleCount", dict)
    {
        writeCommented(file(), "Time");
        writeTabbed(file(), "nParticles");
        writeTabbed(file(), "strain");
        file() << endl;
    }

    virtual bool execute()
    {
        return true;
    }

    virtual bool write()
    {
        // The cloud's registered name, as any user's code would know it
        if (!mesh_.foundObject<suspensionCloud>("suspension"))
        {
            FatalErrorInFunction
                << "no suspensionCloud 'suspension' in the mesh"
                << exit(FatalError);
        }
        const suspensionCloud& cloud =
            mesh_.lookupObject<suspensionCloud>("suspension");

        writeCurrentTime(file());
        file()
            << tab << label(cloud.simulation().particles().size())
            << tab << cloud.simulation().time() << endl;
        return true;
    }
};

defineTypeNameAndDebug(particleCount, 0);
addToRunTimeSelectionTable(functionObject, particleCount, dictionary);

} // End namespace functionObjects
} // End namespace Foam


// ************************************************************************* //
