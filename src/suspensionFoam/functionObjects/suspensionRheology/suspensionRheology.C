#include "suspensionRheology.H"
#include "suspensionCloud.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(suspensionRheology, 0);
    addToRunTimeSelectionTable(functionObject, suspensionRheology, dictionary);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::functionObjects::suspensionRheology::writeFileHeader
(
    const bool implicit
)
{
    OFstream& os = file();
    writeHeader
    (
        os,
        "Rheology of the suspension: bulk stress of eq. (8), Monti et al."
        " (2021); reduced units a0 = eta0 = gammaDot = 1"
    );
    writeCommented(os, "Time");
    for
    (
        const char* column
      : {"strain", "etaR", "N1", "N2", "Pi", "etaN"}
    )
    {
        writeTabbed(os, column);
    }
    for (const label c : contributions_)
    {
        writeTabbed(os, word("etaR_" + suspension::contributionNames()[c]));
    }
    for
    (
        const char* column
      : {"nContacts", "maxOverlap", "steps", "deltaT", "uFluct2", "pairSlots"}
    )
    {
        writeTabbed(os, column);
    }
    if (implicit)
    {
        writeTabbed(os, "cgIterations");
        writeTabbed(os, "cgResidual");
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::suspensionRheology::suspensionRheology
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "rheology", dict),
    contributions_()
{
    read(dict);
    writeFileHeader
    (
        suspensionCloud::lookup(mesh_, name).simulation().implicit()
     != nullptr
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::suspensionRheology::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    const std::vector<std::string>& names = suspension::contributionNames();
    wordList valid(label(names.size()));
    forAll(valid, c)
    {
        valid[c] = names[c];
    }

    const wordList selected(dict.getOrDefault<wordList>("contributions", valid));
    contributions_.setSize(selected.size());
    forAll(selected, i)
    {
        contributions_[i] = valid.find(selected[i]);
        if (contributions_[i] < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Unknown contribution '" << selected[i] << "' in entry"
                << " 'contributions' of function object " << this->name()
                << nl << "Valid contributions: " << valid << nl
                << exit(FatalIOError);
        }
    }

    return true;
}


bool Foam::functionObjects::suspensionRheology::execute()
{
    return true;
}


bool Foam::functionObjects::suspensionRheology::write()
{
    const suspensionCloud& cloud = suspensionCloud::lookup(mesh_, name());
    const suspension::Simulation& sim = cloud.simulation();
    const suspension::Rheology r = cloud.rheology();
    const scalar strain = sim.flow().shearRate()*sim.time();

    OFstream& os = file();
    writeCurrentTime(os);
    for (const scalar value : {strain, r.etaR, r.N1, r.N2, r.Pi, r.etaN})
    {
        os  << tab << value;
    }
    for (const label c : contributions_)
    {
        os  << tab << r.etaRPart[c];
    }
    os  << tab << label(sim.summary().nContacts)
        << tab << sim.summary().maxOverlap
        << tab << cloud.steps()
        << tab << cloud.meanDeltaT()
        << tab << sim.velocityFluctuation()
        << tab << label(sim.pairs().nPairs());
    if (const suspension::ImplicitEuler* implicit = sim.implicit())
    {
        os  << tab << label(implicit->statistics().iterations)
            << tab << implicit->statistics().residual;
    }
    os  << endl;

    return true;
}


// ************************************************************************* //
