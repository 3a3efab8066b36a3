#include "suspensionProperties.H"
#include "core/Parallel.H"
#include "forceModelsReader.H"
#include "inputChecks.H"
#include "Enum.H"
#include "Time.H"

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <string>
#include <utility>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::suspensionProperties::dictName("suspensionProperties");


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

const Enum<suspension::Integrator> integrators
({
    {suspension::Integrator::velocityVerlet, "velocityVerlet"},
    {suspension::Integrator::implicitEuler, "implicitEuler"},
    {suspension::Integrator::overdamped, "overdamped"},
});

const Enum<suspension::Stencil> stencils
({
    {suspension::Stencil::half, "half"},
    {suspension::Stencil::full, "full"},
    {suspension::Stencil::bruteForce, "bruteForce"},
});


//- Integration parameters; rho = St in reduced units (eq. 11)
suspension::Simulation::Params readIntegration
(
    const dictionary& dict,
    const scalar St
)
{
    checkEntries
    (
        dict,
        {
            "integrator", "deltaT", "safety", "skin", "stencil", "maxOverlap",
            "maxDisplacement", "normalContact", "solver", "threads"
        }
    );

    suspension::Simulation::Params p;
    p.rho = St;
    if (dict.found("integrator", keyType::LITERAL))
    {
        p.integrator = getEnum(dict, "integrator", integrators);
    }

    // deltaT: the word 'auto' (step from the stability limits) or a value
    ITstream& is = dict.lookup("deltaT");
    const token t(is);
    if (t.isWord() && t.wordToken() == "auto")
    {
        p.deltaT = 0;
    }
    else if (t.isNumber() && interval::positive().contains(t.number()))
    {
        p.deltaT = t.number();
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'deltaT' = " << t << " in dictionary " << dict.name()
            << " must be 'auto' or a time step in " << interval::positive()
            << nl << exit(FatalIOError);
    }

    p.safety = getScalarIn(dict, "safety", interval(0, false, 1, false));
    p.skin = getScalarIn(dict, "skin", interval::nonNegative());
    p.stencil = getEnum(dict, "stencil", stencils);
    p.maxOverlap = getScalarIn(dict, "maxOverlap", interval::positive());
    p.maxDisplacement = getScalarInOrDefault
    (
        dict, "maxDisplacement", p.maxDisplacement, interval::positive()
    );

    // Threads: the count that runs fastest (adaptive, the default), or all
    // that OpenMP allows (fixed)
    const word threads(dict.getOrDefault<word>("threads", "adaptive"));
    if (threads != "adaptive" && threads != "fixed")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'threads' = " << threads << " in dictionary "
            << dict.name() << " must be adaptive or fixed" << nl
            << exit(FatalIOError);
    }
    p.adaptiveThreads = threads == "adaptive";

    // The normal contact springs of the implicit integrators: auto (unset),
    // implicit or explicit; read only by them
    if
    (
        p.integrator != suspension::Integrator::velocityVerlet
     && dict.found("normalContact", keyType::LITERAL)
    )
    {
        const word w(dict.get<word>("normalContact"));
        if (w == "implicit" || w == "explicit")
        {
            p.implicitNormalContact = w == "implicit";
        }
        else if (w != "auto")
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'normalContact' = " << w << " in dictionary "
                << dict.name() << " must be auto, implicit or explicit"
                << nl << exit(FatalIOError);
        }
    }

    // CG of the implicit integrators; read only by them, as the entries of
    // a model that is off
    if
    (
        p.integrator != suspension::Integrator::velocityVerlet
     && dict.found("solver", keyType::LITERAL)
    )
    {
        const dictionary& solverDict = dict.subDict("solver");
        checkEntries(solverDict, {"tolerance", "maxIterations"});
        p.solver.tolerance = getScalarInOrDefault
        (
            solverDict, "tolerance", p.solver.tolerance, interval::open(0, 1)
        );
        if (solverDict.found("maxIterations", keyType::LITERAL))
        {
            p.solver.maxIterations =
                getLabelAtLeast(solverDict, "maxIterations", 1);
        }
    }
    return p;
}


//- The output settings of earlier versions are function objects now
void rejectOutputDict(const dictionary& dict)
{
    if (dict.found("output", keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'output' of " << dict.name() << " is no longer read:"
            << " the output is selected by function objects in"
            << " system/controlDict" << nl
            << "    rheologyInterval n  ->  functions { rheology { type"
            << " suspensionRheology; libs (suspensionFunctionObjects);"
            << " writeControl timeStep; writeInterval n; } }" << nl
            << "    profileBins n       ->  functions { profiles { type"
            << " suspensionProfiles; libs (suspensionFunctionObjects);"
            << " writeControl writeTime; nBins n; } }" << nl
            << "    Remove 'output' (see the tutorials' controlDict)" << nl
            << exit(FatalIOError);
    }
}

//- Bytes of engine state per particle, at least: every case measured
//  needs more (docs/performance.md, "Memory")
constexpr double bytesPerParticle = 1024;


//- The memory this process may use, in bytes, and what sets it: the
//  physical memory, a control group's limit, or the address-space limit
std::pair<double, std::string> memoryLimit()
{
    std::pair<double, std::string> limit
    {
        double(::sysconf(_SC_PHYS_PAGES))*double(::sysconf(_SC_PAGESIZE)),
        "physical memory"
    };
    std::ifstream cgroup("/sys/fs/cgroup/memory.max");
    double bytes;
    if (cgroup >> bytes && bytes < limit.first)
    {
        limit = {bytes, "memory limit of its control group"};
    }
    struct rlimit as;
    if
    (
        ::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY
     && double(as.rlim_cur) < limit.first
    )
    {
        limit = {double(as.rlim_cur), "address-space limit (ulimit -v)"};
    }
    return limit;
}


//- The file of the properties, read (MUST_READ) or to hold a dictionary
IOobject propertiesFile(const objectRegistry& obr, const IOobject::readOption r)
{
    return IOobject
    (
        suspensionProperties::dictName,
        obr.time().constant(),
        obr,
        r,
        IOobject::NO_WRITE,
        r == IOobject::MUST_READ ? false : true
    );
}


//- The contents of the file, parsed without floating-point traps: a number
//  too large for a double (1e999) is then an IOerror that names the file,
//  the entry and the line (suspension::NonStopArithmetic)
dictionary readWithoutTraps(const objectRegistry& obr)
{
    const suspension::NonStopArithmetic nonStop;
    return IOdictionary(propertiesFile(obr, IOobject::MUST_READ));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::suspensionProperties::suspensionProperties(const objectRegistry& obr)
:
    IOdictionary
    (
        propertiesFile(obr, IOobject::NO_READ),
        readWithoutTraps(obr)
    ),
    units_(*this),
    population_(subDict("population"), units_.lengthUnit()),
    models_(forceModelsReader(units_.reduced()).models()),
    simulationParams_
    (
        readIntegration
        (
            subDict("integration"),
            getScalarIn(units_.reduced(), "StokesNumber", interval::positive())
        )
    )
{
    rejectOutputDict(*this);
    wordList valid
    ({
        "units", "dimensional", "population", "StokesNumber", "integration",
        "ambientFlow"
    });
    valid.append(forceModelsReader::dictionaries());
    checkEntries(*this, valid);

    // A case larger than the machine stops here, not after the packing
    const double needed = bytesPerParticle*population_.nParticles();
    const std::pair<double, std::string> limit = memoryLimit();
    if (needed > limit.first)
    {
        FatalIOErrorInFunction(population_.dict())
            << "Entry 'nParticles' = " << population_.nParticles() << " in "
            << population_.dict().name() << ": the suspension needs at least "
            << needed/1e9 << " GB (" << bytesPerParticle/1024 << " kB of"
            << " engine state per particle, a lower bound), and this machine"
            << " has " << limit.first/1e9 << " GB (its "
            << limit.second.c_str() << ")" << nl << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

suspension::BoxRule Foam::suspensionProperties::boxRule() const
{
    return suspension::BoxRule
    (
        models_.interactionGap() + simulationParams_.skin
    );
}


void Foam::suspensionProperties::report(Ostream& os) const
{
    const suspension::ForceModels& m = models_;
    const suspension::Simulation::Params& s = simulationParams_;

    units_.report(os);
    os  << "Suspension (reduced units a0 = eta0 = gammaDot = 1)" << nl
        << "    population   " << population_.dict().get<word>("type")
        << ", N = " << population_.nParticles()
        << ", phi = " << population_.volumeFraction()
        << ", box " << population_.box() << nl
        << "    models       " << m.summary().c_str() << nl
        << "    Stokes drag  eta0 = " << m.drag().params().eta
        << ", rho = St = " << s.rho << nl;

    m.forEach([&](const auto& model)
    {
        os  << "    " << std::decay_t<decltype(model)>::typeName << "  "
            << model.describe().c_str() << nl;
    });
    os  << "    integration  " << integrators.get(s.integrator) << ", deltaT "
        << (s.deltaT > 0 ? Foam::name(s.deltaT) : word("auto"))
        << ", safety " << s.safety << ", skin " << s.skin << ", stencil "
        << stencils.get(s.stencil) << ", maxOverlap " << s.maxOverlap
        << ", maxDisplacement "
        << (s.maxDisplacement > 0 ? Foam::name(s.maxDisplacement) : word("off"))
        << nl;
    if (s.integrator != suspension::Integrator::velocityVerlet)
    {
        os  << "    CG solver    tolerance " << s.solver.tolerance
            << ", maxIterations " << label(s.solver.maxIterations) << nl;
    }
}


// ************************************************************************* //
