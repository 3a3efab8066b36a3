#include "suspensionRheology.H"
#include "rheologySeries.H"
#include "suspensionCloud.H"
#include "stress/SteadyState.H"
#include "addToRunTimeSelectionTable.H"

#include <iomanip>
#include <sstream>

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
      : {"strain", "shearRate", "sigma", "etaR", "N1", "N2", "Pi", "etaN"}
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


bool Foam::functionObjects::suspensionRheology::summarise(const bool report)
{
    bool precise = Pstream::master() && summariseHere(report);
    Pstream::scatter(precise);
    return precise;
}


bool Foam::functionObjects::suspensionRheology::summariseHere(const bool report)
{
    file().flush();
    const ambientFlow& flow = suspensionCloud::lookup(mesh_, name()).flow();
    if (!flow.programme().constant())
    {
        if (report)
        {
            Info<< nl << type() << ' ' << name() << ": the shear rate changes"
                << " in time (shearRate is not a constant): no steady-state"
                << " summary (an oscillation's moduli: suspensionOscillation)"
                << nl << endl;
        }
        return false;
    }
    const rheologySeries series(baseFileDir()/name(), time_.value());
    if (series.size() < 2)
    {
        return false;
    }
    const std::vector<double>& strain = series.column("strain");

    // Under stress control the viscosity is sigma/<shearRate>: the rate
    // leads (its transient, its error bar), not the rows' ratio
    const bool stress = flow.stressControlled() && series.found("shearRate");
    const word lead(stress ? "shearRate" : "etaR");

    // One steady window for every quantity: the transient of the lead
    suspension::SteadyState::Options opt;
    opt.minStrain = minSteadyStrain_;
    if (discardStrain_ >= 0)
    {
        opt.discardStrain = discardStrain_;
    }
    else
    {
        const std::size_t d = suspension::SteadyState::mserTruncation
        (
            series.column(lead), opt.batch
        );
        opt.discardStrain = strain[std::min(d, strain.size() - 1)] - strain[0];
    }

    wordList quantities({lead});
    for (const word& n : series.names())
    {
        const bool summarised =
            n == "etaR" || n == "N1" || n == "N2" || n == "Pi"
         || n == "shearRate" || n == "sigma" || n.starts_with("etaR_");
        if (summarised && n != lead)
        {
            quantities.append(n);
        }
    }

    std::vector<suspension::SteadyState> states;
    for (const word& q : quantities)
    {
        states.emplace_back(strain, series.column(q), opt);
    }
    const suspension::SteadyState& leading = states[0];
    const scalar relError =
        leading.nBlocks() > 1 && leading.mean() != 0
      ? leading.standardError()/mag(leading.mean())
      : GREAT;
    const bool precise = leading.reliable() && relError <= precision_;
    scalar viscosity = leading.mean();
    scalar viscosityError = leading.standardError();
    if (stress)
    {
        const suspension::SteadyState& sigma = states[quantities.find("sigma")];
        viscosity = sigma.mean()/leading.mean();
        viscosityError = mag(viscosity)*std::sqrt
        (
            sqr(relError)
          + sqr(sigma.mean() != 0 ? sigma.standardError()/sigma.mean() : 0.0)
        );
    }

    std::ostringstream table;
    table
        << std::left << std::setw(20) << "# quantity" << std::right
        << std::setw(14) << "mean" << std::setw(14) << "stdError"
        << std::setw(10) << "relError" << std::setw(18) << "correlationStrain"
        << std::setw(12) << "blockStrain" << std::setw(8) << "blocks"
        << std::setw(12) << "strainUsed" << std::setw(16) << "strainDiscarded"
        << std::setw(9) << "trusted" << '\n';
    forAll(quantities, i)
    {
        const word& q = quantities[i];
        const suspension::SteadyState& st = states[i];
        table
            << std::left << std::setw(20) << ("  " + q) << std::right
            << std::setprecision(6)
            << std::setw(14) << st.mean()
            << std::setw(14) << st.standardError()
            << std::setprecision(3) << std::setw(10)
            << (st.mean() != 0 ? st.standardError()/std::abs(st.mean()) : 0.0)
            << std::setprecision(4)
            << std::setw(18) << st.correlationStrain()
            << std::setw(12) << st.blockStrain()
            << std::setw(8) << st.nBlocks()
            << std::setw(12) << st.strainUsed()
            << std::setw(16) << st.strainDiscarded()
            << std::setw(9) << (st.reliable() ? "yes" : "no") << '\n';
    }

    std::ostringstream verdict;
    verdict
        << "etaR = " << (stress ? "<sigma>/<shearRate> = " : "")
        << std::setprecision(6) << viscosity << " +/- " << viscosityError
        << " (" << std::setprecision(3) << 100*relError << " %"
        << (stress ? " of the rate" : "") << ", " << leading.nBlocks()
        << " blocks of " << std::setprecision(4) << leading.blockStrain()
        << " strain)";
    if (precise)
    {
        verdict << ": within the precision " << 100*precision_ << " %";
    }
    else
    {
        verdict
            << (leading.reliable() ? ": above" : ": too few blocks to trust; for")
            << " the precision " << 100*precision_ << " % about "
            << std::max(0.0, leading.strainNeeded(precision_) - leading.strainUsed())
            << " more steady strain is needed";
    }

    // Next to this run's rheology.dat
    const fileName summaryFile
    (
        baseFileDir()/name()/time_.timeName(time_.startTime().value())
       /"rheologySummary.dat"
    );
    {
        OFstream os(summaryFile);
        os  << "# Steady-state rheology at time " << time_.timeName()
            << " (strain " << strain.back() << "), from " << series.size()
            << " rows of postProcessing/" << name()
            << "/*/rheology*.dat" << nl
            << "# start-up transient: "
            << (discardStrain_ >= 0 ? "discardStrain" : "MSER-5 rule on etaR")
            << ", strain " << strain.front() << " to "
            << strain.front() + opt.discardStrain << " discarded"
            << " (strainDiscarded adds, for each quantity, the oldest"
            << " samples that do not fill a block)" << nl
            << "# error bars: means of blocks of two correlation strains,"
            << " trusted with >= " << label(opt.minBlocks) << " blocks over"
            << " >= " << minSteadyStrain_ << " strain" << nl
            << "# " << verdict.str().c_str() << nl
            << table.str().c_str();
    }
    if (report)
    {
        Info<< nl << type() << ' ' << name() << ": steady state from strain "
            << strain.front() + opt.discardStrain << " to " << strain.back()
            << nl << table.str().c_str()
            << verdict.str().c_str() << nl
            << "(" << summaryFile << ")" << nl
            << endl;
    }
    return precise;
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
    contributions_(),
    precision_(0.02),
    stopAtPrecision_(false),
    discardStrain_(-1),
    minSteadyStrain_(1),
    summarised_(false)
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

    precision_ = dict.getOrDefault<scalar>("precision", 0.02);
    if (!(precision_ > 0 && precision_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'precision' " << precision_ << " of function object "
            << this->name() << " is not in (0, 1): it is the wanted standard"
            << " error of etaR relative to etaR" << nl << exit(FatalIOError);
    }
    stopAtPrecision_ = dict.getOrDefault<bool>("stopAtPrecision", false);
    discardStrain_ = dict.getOrDefault<scalar>("discardStrain", -1);
    if (dict.found("discardStrain") && !(discardStrain_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'discardStrain' " << discardStrain_
            << " of function object " << this->name() << " is negative:"
            << " give the start-up strain to discard, or leave it out for"
            << " the MSER-5 rule" << nl << exit(FatalIOError);
    }

    minSteadyStrain_ = dict.getOrDefault<scalar>("minSteadyStrain", 1);
    if (!(minSteadyStrain_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'minSteadyStrain' " << minSteadyStrain_
            << " of function object " << this->name() << " is negative"
            << nl << exit(FatalIOError);
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
    OFstream& os = file();
    writeCurrentTime(os);
    for
    (
        const scalar value
      : {sim.strain(), sim.shearRate(), r.sigma, r.etaR, r.N1, r.N2, r.Pi, r.etaN}
    )
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
        << tab << returnReduce(label(sim.pairs().nPairs()), sumOp<label>());
    if (const suspension::ImplicitEuler* implicit = sim.implicit())
    {
        os  << tab << label(implicit->statistics().iterations)
            << tab << implicit->statistics().residual;
    }
    os  << endl;

    if (time_.writeTime())
    {
        const bool precise = summarise(false);
        if (stopAtPrecision_ && precise)
        {
            Info<< nl << type() << ' ' << name() << ": etaR within the"
                << " precision " << precision_ << " at time "
                << time_.timeName() << ": writing and ending the run"
                << " (stopAtPrecision)" << endl;
            summarise(true);
            summarised_ = true;
            const_cast<Time&>(time_).writeAndEnd();
        }
    }
    return true;
}


bool Foam::functionObjects::suspensionRheology::end()
{
    if (!summarised_)
    {
        summarise(true);
        summarised_ = true;
    }
    return true;
}


// ************************************************************************* //
