#include "suspensionOscillation.H"
#include "rheologySeries.H"
#include "suspensionCloud.H"
#include "oscillatoryShear.H"
#include "stress/Oscillation.H"
#include "addToRunTimeSelectionTable.H"

#include <iomanip>
#include <stdexcept>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(suspensionOscillation, 0);
    addToRunTimeSelectionTable(functionObject, suspensionOscillation, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::suspensionOscillation::analyse(const bool report)
{
    using Cycle = suspension::Oscillation::Cycle;
    if (!Pstream::master())
    {
        return;     // the files are the master's (a parallel run)
    }

    // The rows up to now (their Time column rounded: half a step of slack)
    const rheologySeries series
    (
        baseFileDir()/rheology_, time_.value() + 0.5*time_.deltaTValue()
    );
    const suspension::Oscillation osc = [&]()
    {
        try
        {
            return suspension::Oscillation
            (
                series.column("Time"), series.column("strain"),
                series.column("sigma"), omega_, discardCycles_
            );
        }
        catch (const std::invalid_argument& err)
        {
            FatalErrorInFunction
                << "Function object " << name() << " cannot analyse "
                << baseFileDir()/rheology_ << ": " << err.what() << nl
                << exit(FatalError);
            throw;
        }
    }();

    const fileName dir
    (
        baseFileDir()/name()/time_.timeName(time_.startTime().value())
    );
    mkDir(dir);

    const std::pair<const char*, double Cycle::*> quantities[] =
    {
        {"gamma0", &Cycle::gamma0}, {"Gp", &Cycle::Gp}, {"Gpp", &Cycle::Gpp},
        {"etaP", &Cycle::etaP}, {"etaPP", &Cycle::etaPP},
        {"I3overI1", &Cycle::I3}
    };
    {
        OFstream os(dir/"oscillation.dat");
        os  << "# Whole cycles of omega = " << omega_ << " of postProcessing/"
            << rheology_ << "/*/rheology*.dat (suspensionOscillation)" << nl
            << "# cycle start";
        for (const auto& q : quantities)
        {
            os  << ' ' << q.first;
        }
        os  << " used" << nl;
        for (const Cycle& c : osc.cycles())
        {
            os  << label(c.n) << ' ' << c.start;
            for (const auto& q : quantities)
            {
                os  << ' ' << c.*q.second;
            }
            os  << ' ' << osc.used(c) << nl;
        }
    }

    std::ostringstream table;
    table
        << std::left << std::setw(12) << "# quantity" << std::right
        << std::setw(14) << "mean" << std::setw(14) << "stdError"
        << std::setw(8) << "cycles" << '\n';
    for (const auto& q : quantities)
    {
        const suspension::Oscillation::Estimate e = osc.estimate(q.second);
        table
            << std::left << std::setw(12) << (std::string("  ") + q.first)
            << std::right << std::setprecision(6)
            << std::setw(14) << e.mean << std::setw(14) << e.error
            << std::setw(8) << osc.nUsed() << '\n';
    }
    {
        OFstream os(dir/"oscillationSummary.dat");
        os  << "# Oscillatory shear at omega = " << omega_ << ", time "
            << time_.timeName() << ": " << osc.cycles().size()
            << " whole cycles sampled, those before cycle " << discardCycles_
            << " left out (start-up);"
            << " error bars: the cycles' scatter over sqrt(cycles)" << nl
            << table.str().c_str();
    }
    if (report)
    {
        Info<< nl << type() << ' ' << name() << ": omega = " << omega_
            << ", " << osc.nUsed() << " cycles from cycle " << discardCycles_
            << " (the first " << discardCycles_ << " from t = 0: start-up)" << nl << table.str().c_str()
            << "(" << dir/"oscillationSummary.dat" << ")" << nl << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::suspensionOscillation::suspensionOscillation
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "oscillation", dict),
    rheology_("rheology"),
    discardCycles_(1),
    omega_(0),
    summarised_(false)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::suspensionOscillation::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    rheology_ = dict.getOrDefault<word>("rheology", "rheology");
    discardCycles_ = dict.getOrDefault<label>("discardCycles", 1);
    if (discardCycles_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'discardCycles' " << discardCycles_ << " of function"
            << " object " << name() << " is negative" << nl
            << exit(FatalIOError);
    }

    const Function1<scalar>& rate =
        suspensionCloud::lookup(mesh_, name()).flow().programme().function();
    const auto* oscillatory =
        dynamic_cast<const Function1Types::oscillatoryShear*>(&rate);
    if (dict.found("omega"))
    {
        omega_ = dict.get<scalar>("omega");
        if (!(omega_ > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'omega' " << omega_ << " of function object "
                << name() << " is not positive" << nl << exit(FatalIOError);
        }
    }
    else if (oscillatory)
    {
        omega_ = oscillatory->omega();
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << " needs the entry 'omega': the"
            << " ambient flow's shearRate is '" << rate.type() << "', not"
            << " oscillatory, so it does not give the frequency" << nl
            << exit(FatalIOError);
    }
    return true;
}


bool Foam::functionObjects::suspensionOscillation::execute()
{
    return true;
}


bool Foam::functionObjects::suspensionOscillation::write()
{
    if (time_.writeTime())
    {
        analyse(false);
    }
    return true;
}


bool Foam::functionObjects::suspensionOscillation::end()
{
    if (!summarised_)
    {
        analyse(true);
        summarised_ = true;
    }
    return true;
}


// ************************************************************************* //
