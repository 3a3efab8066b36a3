/*---------------------------------------------------------------------------*\
Application
    userSolver

Description
    A user's own solver on the project's libraries, built with wmake from
    its own Make/files and Make/options (tests/userSolver/userSolverTest.sh
    builds and runs it; docs/user-guide.md, "Your own solver or function
    object").
    It selects an ambient flow from constant/suspensionProperties, prints it
    at the centre of the mesh, and evolves the suspension cloud in it.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "ambientFlow.H"
#include "suspensionCloud.H"
#include "core/Memory.H"

int main(int argc, char *argv[])
{
    suspension::useSystemForLargeArrays();
    #include "setRootCase.H"
    suspensionIO::selectStartTime(args);    // start from a complete time
    #include "createTime.H"
    #include "createMesh.H"

    const IOdictionary properties
    (
        IOobject("suspensionProperties", runTime.constant(), mesh, IOobject::MUST_READ)
    );
    autoPtr<ambientFlow> flow =
        ambientFlow::New(mesh, properties.subDict("ambientFlow"));
    Info<< "userSolver: U at the centre " << flow->U(mesh.bounds().centre()) << endl;

    suspensionCloud particles(runTime, mesh, std::move(flow));
    while (runTime.run())
    {
        ++runTime;
        particles.evolve();
        runTime.write();
    }
    particles.writeLastState();
    Info<< "End\n" << endl;
    return 0;
}
