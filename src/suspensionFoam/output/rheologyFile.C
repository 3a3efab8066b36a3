#include "rheologyFile.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rheologyFile::rheologyFile
(
    const objectRegistry& obr,
    const bool implicit
)
:
    functionObjects::writeFile(obr, "rheology", "rheology")
{
    resetFile("rheology");

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
    for (const std::string& c : suspension::contributionNames())
    {
        writeTabbed(os, word("etaR_" + c));
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rheologyFile::write
(
    const suspension::Simulation& sim,
    const std::uint64_t steps,
    const scalar deltaT
)
{
    const suspension::Rheology r = sim.rheology();
    const scalar strain = sim.flow().shearRate()*sim.time();

    OFstream& os = file();
    writeCurrentTime(os);
    for (const scalar value : {strain, r.etaR, r.N1, r.N2, r.Pi, r.etaN})
    {
        os  << tab << value;
    }
    for (const double share : r.etaRPart)
    {
        os  << tab << share;
    }
    os  << tab << label(sim.summary().nContacts)
        << tab << sim.summary().maxOverlap
        << tab << steps
        << tab << deltaT
        << tab << sim.velocityFluctuation()
        << tab << label(sim.pairs().nPairs());
    if (const suspension::ImplicitEuler* implicit = sim.implicit())
    {
        os  << tab << label(implicit->statistics().iterations)
            << tab << implicit->statistics().residual;
    }
    os  << endl;
}


// ************************************************************************* //
