/*---------------------------------------------------------------------------*\
Application
    wavyShearFoam

Group
    grpLagrangianSolvers

Description
    Rheology of a dense non-Brownian suspension of rigid spheres in an
    imposed uniform or wavy shear flow (Monti, Rathee, Shen & Rosti 2021):
    Newton-Euler dynamics with Stokes drag and Faxen terms, lubrication,
    frictional contact, electrostatic repulsion and van der Waals
    attraction, in a Lees-Edwards box.

    Set-up: constant/suspensionProperties (see suspensionProperties.H). The
    mesh spans the particle box; it carries the Eulerian output only.
    Units are reduced (a0 = eta0 = gammaDot = 1): time is strain at the
    reference rate (a rate programme or stress control: docs/rheometry.md).

    The OpenFOAM time step deltaT is the sampling interval: each time step
    advances the particles by deltaT in engine steps of the stability
    limit (times safety) and one shorter last step that lands on the time.
    The run starts from the suspension stored at the start time (startFrom
    latestTime continues a run bitwise, for any number of threads; an
    incomplete latest time, from a write stopped by a kill or a crash, is
    set aside as <time>.incomplete and the latest complete one taken:
    suspensionIO::selectStartTime), or from a new random packing of the
    population if the start time holds none.

    Parallel: decomposePar (system/decomposeParDict: method simple, n
    (1 ny nz); the particles go with their cells), mpirun -np P
    wavyShearFoam -parallel, reconstructPar. The particles are decomposed
    in slabs in y and z, each spanning the box in x, and migrate between
    processes with their contact history; the results are the serial
    run's to round-off (docs/parallel.md).

    The suspension (Foam::suspensionCloud) is registered in the mesh as
    "suspension"; function objects find it by
    mesh.lookupObject<suspensionCloud>("suspension").

    Output: at write times the cloud lagrangian/suspension (with positions
    for ParaView), the contact history and, last, uniform/suspensionState
    (what a restart reads, with the sizes and digests of the time's files:
    a time is complete or has no state). A failure (a non-finite value, a
    runaway overlap, an unconverged solve, any engine error) stops the run
    with the cause and the last good state on disk (suspensionCloud.H).
    The rest is written by the function objects of
    libsuspensionFunctionObjects selected in system/controlDict:
    suspensionRheology (postProcessing/<name>/<startTime>/rheology.dat),
    suspensionProfiles (postProcessing/<name>/<time>/profiles.dat) and
    suspensionFields (Uinf, gradUinf, shearRateInf, particleStress, alpha).
    runTime.run() executes them at the start of the next time step and at
    the end of the run, so they see the state after evolve() and write().

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "suspensionCloud.H"
#include "core/Memory.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    suspension::useSystemForLargeArrays();
    argList::addNote
    (
        "Rheology of a dense suspension of rigid spheres in a uniform or"
        " wavy shear flow (Monti et al. 2021)"
    );

    #include "setRootCase.H"

    // An incomplete latest time (a write stopped by a kill or a crash) is
    // set aside, so that the run starts from the latest complete time
    suspensionIO::selectStartTime(args);

    #include "createTime.H"
    #include "createMesh.H"
    #include "createFields.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    Info<< "\nStarting time loop\n" << endl;

    // runTime.run() executes the function objects on the state of the
    // time step before (and at the end, of the last one)
    while (runTime.run())
    {
        ++runTime;

        particles.evolve();

        runTime.write();
    }
    particles.writeLastState();

    particles.reportKernelTimes();
    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
