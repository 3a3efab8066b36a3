#include "suspensionProperties.H"
#include "inputChecks.H"
#include "Enum.H"
#include "Time.H"
#include "forces/ElectroChemicalScales.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::suspensionProperties::dictName("suspensionProperties");


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

const Enum<suspension::LubricationTerms> lubricationTerms
({
    {suspension::LubricationTerms::leading, "leading"},
    {suspension::LubricationTerms::extended, "extended"},
});

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


//- Lubrication (eq. 3, appendix A), if active
void readLubrication(const dictionary& dict, suspension::ForceModels& models)
{
    checkEntries(dict, {"active", "delta", "epsilon", "terms"});
    if (!dict.get<bool>("active"))
    {
        return;
    }
    suspension::Lubrication::Params p;
    p.deltaLub = getScalarIn(dict, "delta", interval::positive());
    p.epsilon = getScalarIn(dict, "epsilon", interval::positive());
    p.terms = getEnum(dict, "terms", lubricationTerms);
    models.lubrication.emplace
    (
        engineCall(dict, [&]{ return suspension::Lubrication(p); })
    );
}


//- Frictional contact (eqs. 4-5, appendix B) from the groups of eqs. 12-13
void readContact(const dictionary& dict, suspension::ForceModels& models)
{
    checkEntries
    (
        dict,
        {
            "active", "stiffness", "stiffnessRatio", "damping", "friction",
            "rollingStiffnessRatio", "rollingFriction"
        }
    );
    if (!dict.get<bool>("active"))
    {
        return;
    }
    suspension::FrictionalContact::Params p =
        suspension::FrictionalContact::fromGroups
        (
            getScalarIn(dict, "stiffness", interval::positive()),
            getScalarIn(dict, "stiffnessRatio", interval::positive()),
            getScalarIn(dict, "damping", interval::nonNegative()),
            getScalarIn(dict, "friction", interval::nonNegative())
        );
    p.kr = p.kn*getScalarInOrDefault
    (
        dict, "rollingStiffnessRatio", 0, interval::nonNegative()
    );
    if (dict.found("rollingFriction", keyType::LITERAL))
    {
        p.muR = getScalarIn(dict, "rollingFriction", interval::nonNegative());
    }
    models.contact.emplace
    (
        engineCall(dict, [&]{ return suspension::FrictionalContact(p); })
    );
}


//- Repulsion (eq. 6) and attraction (eq. 7) from the groups of eq. 14
void readElectroChemical
(
    const dictionary& dict,
    suspension::ForceModels& models
)
{
    checkEntries
    (
        dict, {"shearRateRatio", "forceRatio", "repulsion", "attraction"}
    );
    const dictionary& repDict = dict.subDict("repulsion");
    const dictionary& attDict = dict.subDict("attraction");
    checkEntries(repDict, {"active", "debyeLength", "cutoff"});
    checkEntries(attDict, {"active", "epsilon", "cutoff"});

    const bool attraction = attDict.get<bool>("active");

    suspension::ElectroChemicalScales::Params sp;
    sp.shearRateRatio = getScalarIn(dict, "shearRateRatio", interval::positive());
    sp.forceRatio = getScalarIn(dict, "forceRatio", interval::positive());
    if (attraction)
    {
        sp.epsilonFraction = getScalarInOrDefault
        (
            attDict, "epsilon", sp.epsilonFraction, interval::positive()
        );
    }
    const suspension::ElectroChemicalScales scales
    (
        engineCall(dict, [&]{ return suspension::ElectroChemicalScales(sp); })
    );

    if (repDict.get<bool>("active"))
    {
        suspension::ElectrostaticRepulsion::Params p = scales.repulsion
        (
            getScalarIn(repDict, "debyeLength", interval::positive())
        );
        p.cutoffFactor = getScalarIn(repDict, "cutoff", interval::positive());
        models.repulsion.emplace
        (
            engineCall
            (
                repDict, [&]{ return suspension::ElectrostaticRepulsion(p); }
            )
        );
    }
    if (attraction)
    {
        suspension::VanDerWaalsAttraction::Params p = scales.attraction();
        p.cutoffGap = getScalarIn(attDict, "cutoff", interval::nonNegative());
        models.attraction.emplace
        (
            engineCall
            (
                attDict, [&]{ return suspension::VanDerWaalsAttraction(p); }
            )
        );
    }
}


suspension::ForceModels readModels(const dictionary& dict)
{
    suspension::ForceModels models;
    readLubrication(dict.subDict("lubrication"), models);
    readContact(dict.subDict("contact"), models);
    if (dict.found("electroChemical", keyType::LITERAL))
    {
        readElectroChemical(dict.subDict("electroChemical"), models);
    }
    return models;
}


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
            "maxDisplacement", "solver"
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


//- Profile bins: the entry, or bins one reference diameter 2 a0 high
label readProfileBins(const dictionary& dict, const scalar Ly)
{
    return dict.found("profileBins", keyType::LITERAL)
      ? getLabelAtLeast(dict, "profileBins", 1)
      : max(label(1), label(Ly/2));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::suspensionProperties::suspensionProperties(const objectRegistry& obr)
:
    IOdictionary
    (
        IOobject
        (
            dictName,
            obr.time().constant(),
            obr,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    units_(*this),
    population_(subDict("population"), units_.lengthUnit()),
    models_(readModels(units_.reduced())),
    simulationParams_
    (
        readIntegration
        (
            subDict("integration"),
            getScalarIn(units_.reduced(), "StokesNumber", interval::positive())
        )
    ),
    rheologyInterval_(getLabelAtLeast(subDict("output"), "rheologyInterval", 1)),
    profileBins_(readProfileBins(subDict("output"), population_.box().y()))
{
    checkEntries
    (
        *this,
        {
            "units", "dimensional", "population", "StokesNumber",
            "lubrication", "contact", "electroChemical", "integration",
            "ambientFlow", "output"
        }
    );
    checkEntries(subDict("output"), {"rheologyInterval", "profileBins"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::suspensionProperties::neighbourCutoff(const scalar aMax) const
{
    return 2*aMax + models_.interactionGap(aMax, aMax) + simulationParams_.skin;
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
        << ", radii [" << population_.radii().front() << ", "
        << population_.radii().back() << "], box " << population_.box() << nl
        << "    models       " << m.summary().c_str() << nl
        << "    Stokes drag  eta0 = " << m.drag.params().eta
        << ", rho = St = " << s.rho << nl;

    if (m.lubrication)
    {
        const auto& p = m.lubrication->params();
        os  << "    lubrication  deltaLub = " << p.deltaLub
            << ", epsilon = " << p.epsilon << ", terms "
            << lubricationTerms.get(p.terms) << nl;
    }
    if (m.contact)
    {
        const auto& p = m.contact->params();
        os  << "    contact      kn = " << p.kn << ", kt = " << p.kt
            << ", gammaN = " << p.gammaN << ", muC = " << p.muC
            << ", kr = " << p.kr << ", muR = " << m.contact->muR() << nl;
    }
    if (m.repulsion)
    {
        const auto& p = m.repulsion->params();
        os  << "    repulsion    F_ER = " << p.FER << ", lambdaD = "
            << p.lambdaD << ", cut-off gap " << p.cutoffFactor*p.lambdaD
            << " (" << p.cutoffFactor << " lambdaD)" << nl;
    }
    if (m.attraction)
    {
        const auto& p = m.attraction->params();
        os  << "    attraction   A = " << p.A << ", eps/abar = "
            << p.epsilonFraction << ", cut-off gap " << p.cutoffGap << nl;
    }
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
