/*---------------------------------------------------------------------------*\
Application
    makeSuspension

Group
    grpPreProcessingUtilities

Description
    Sets up the particles of a wavyShearFoam case from the population of
    constant/suspensionProperties:

    - writes the particle box to constant/particleBox (entries Lx, Ly, Lz),
      which blockMeshDict includes so that the mesh spans the box;
    - unless -boxOnly, packs the population at random without overlaps
      and writes it as the suspension of the start time (cloud, contact
      history, state), with the fields and profiles of the case's
      suspensionFields and suspensionProfiles function objects
      (system/controlDict), ready for the solver and ParaView.

    Typical sequence: makeSuspension -boxOnly; blockMesh; makeSuspension.
    The solver packs a new suspension itself when the start time holds
    none; makeSuspension makes the initial state visible beforehand. A
    decomposed case: makeSuspension then decomposePar, or decomposePar
    (the mesh) then mpirun -np P makeSuspension -parallel, which packs the
    whole population on every process alike and writes each process's
    slab: the same particles either way.

Usage
    \b makeSuspension [OPTION]

    Options:
      - \par -boxOnly
        Write constant/particleBox only (no mesh needed)

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "suspensionCloud.H"
#include "core/Memory.H"
#include "meshField.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    suspension::useSystemForLargeArrays();
    argList::addNote
    (
        "Write the particle box and a random packing of the population of"
        " constant/suspensionProperties at the start time"
    );
    argList::addBoolOption
    (
        "boxOnly",
        "Write constant/particleBox only (before blockMesh)"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    {
        const suspensionProperties properties(runTime);
        const vector& box = properties.population().box();
        suspensionIO::writeBox(runTime, box);
        Info<< "Particle box " << box << " written to "
            << runTime.constant()/"particleBox" << nl << endl;
    }

    if (!args.found("boxOnly"))
    {
        if (suspensionIO::found(runTime))
        {
            FatalErrorInFunction
                << "Time " << runTime.timeName() << " already holds a"
                << " suspension: remove " << runTime.timeName()
                << "/lagrangian and " << runTime.timeName()
                << "/uniform to pack a new one" << exit(FatalError);
        }

        #include "createMesh.H"

        // A flow solved on the mesh (ambientFlow meshField) starts from
        // u' = 0, as in the coupled solver when it packs
        autoPtr<volVectorField> UprimePtr;
        {
            const suspensionProperties properties(runTime);
            const dictionary& flowDict = properties.ambientFlowDict();
            if (flowDict.get<word>("type") == meshField::typeName)
            {
                UprimePtr.reset
                (
                    new volVectorField
                    (
                        IOobject
                        (
                            meshField::fieldName(flowDict),
                            runTime.timeName(),
                            mesh,
                            IOobject::NO_READ,
                            IOobject::NO_WRITE
                        ),
                        mesh,
                        dimensionedVector(dimVelocity, Zero)
                    )
                );
            }
        }

        // Packs the population and writes it at the start time
        const suspensionCloud particles(runTime, mesh);

        // The fields and profiles of the packing: the case's function
        // objects of these types write them when they are constructed
        // (writeAtStart), as they do in a solver run that packs; the
        // others (rheology, a user's) are left to the solver
        const wordList startTypes({"suspensionFields", "suspensionProfiles"});
        const dictionary* functionsPtr =
            runTime.controlDict().subDictPtr("functions");
        if (functionsPtr)
        {
            for (const entry& e : *functionsPtr)
            {
                if
                (
                    e.isDict()
                 && startTypes.found(e.dict().get<word>("type"))
                )
                {
                    functionObject::New(e.keyword(), runTime, e.dict());
                }
            }
        }
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
