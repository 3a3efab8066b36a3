#include "suspensionUnits.H"
#include "inputChecks.H"
#include "forces/CriticalLoadContact.H"
#include "forces/ElectroChemicalScales.H"
#include "forces/ForceModels.H"

#include <utility>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

enum class unitSystem
{
    reduced,
    dimensional
};

const Enum<unitSystem> unitSystems
({
    {unitSystem::reduced, "reduced"},
    {unitSystem::dimensional, "dimensional"},
});


//- The entries of the sub-dictionary 'dimensional' and their SI units
const std::pair<const char*, const char*> siEntries[] =
{
    {"a0", "m"},
    {"eta0", "Pa s"},
    {"gammaDot", "1/s"},
    {"rho", "kg/m3"},
    {"deltaLub", "m"},
    {"kn", "N/m"},
    {"kt", "N/m"},
    {"gammaN", "kg/s"},
    {"criticalLoad", "N"},
    {"FER", "N"},
    {"hamaker", "J"},
    {"debyeLength", "m"},
};


bool readDimensional(const dictionary& dict)
{
    return
        dict.found("units", keyType::LITERAL)
     && getEnum(dict, "units", unitSystems) == unitSystem::dimensional;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::suspensionUnits::input(const word& key)
{
    const scalar x = getScalarIn
    (
        reduced_.subDict("dimensional"),
        key,
        key == "gammaN" ? interval::nonNegative() : interval::positive()
    );
    for (const auto& e : siEntries)
    {
        if (key == e.first)
        {
            inputs_.append({key, e.second, x});
        }
    }
    return x;
}


void Foam::suspensionUnits::setGroup
(
    const fileName& path,
    const scalar value,
    const string& formula
)
{
    const wordList keys(path.components());
    dictionary* dict = &reduced_;
    for (label i = 0; i < keys.size() - 1; ++i)
    {
        dict = &dict->subDict(keys[i]);
    }
    if (dict->found(keys.last(), keyType::LITERAL))
    {
        FatalIOErrorInFunction(*dict)
            << "Entry '" << keys.last() << "' in dictionary " << dict->name()
            << " is set from the sub-dictionary 'dimensional' (units"
            << " dimensional) as " << formula.c_str() << ": remove it, or"
            << " set 'units reduced'" << nl << exit(FatalIOError);
    }
    dict->add(keys.last(), value);
    groups_.append({path, formula, value});
}


void Foam::suspensionUnits::checkMapped() const
{
    // The model dictionaries that convert() sets from SI input
    const wordList mapped({"lubrication", "contact", "electroChemical"});
    auto check = [&](auto tag)
    {
        using M = typename decltype(tag)::type;
        const wordList path(fileName(M::dictName).components());
        if (path.empty() || mapped.found(path.first()))
        {
            return;
        }
        const dictionary* d = &reduced_;
        for (const word& part : path)
        {
            d = d->isDict(part, keyType::LITERAL) ? &d->subDict(part) : nullptr;
            if (!d)
            {
                return;
            }
        }
        if (d->getOrDefault<bool>("active", false))
        {
            FatalIOErrorInFunction(*d)
                << "Dictionary " << d->name() << " (model " << M::typeName
                << ") has no SI mapping under 'units dimensional': its"
                << " entries would be read in reduced units. Set 'units"
                << " reduced' and give them in units of a0, eta0 and gammaDot,"
                << " or switch the model off (active false)" << nl
                << exit(FatalIOError);
        }
    };
    suspension::forEachParticleModelType(check);
    suspension::forEachPairModelType(check);
}


void Foam::suspensionUnits::convert()
{
    checkMapped();
    wordList valid;
    for (const auto& e : siEntries)
    {
        valid.append(e.first);
    }
    checkEntries(reduced_.subDict("dimensional"), valid);

    const scalar a0 = input("a0");
    const scalar eta0 = input("eta0");
    const scalar gammaDot = input("gammaDot");
    lengthUnit_ = a0;

    setGroup
    (
        "StokesNumber",
        input("rho")*sqr(a0)*gammaDot/eta0,
        "rho a0^2 gammaDot/eta0"
    );

    if (reduced_.subDict("lubrication").get<bool>("active"))
    {
        setGroup("lubrication/delta", input("deltaLub")/a0, "deltaLub/a0");
    }

    if (reduced_.subDict("contact").get<bool>("active"))
    {
        const scalar kn = input("kn");
        setGroup
        (
            "contact/stiffness", kn/(eta0*a0*gammaDot), "kn/(eta0 a0 gammaDot)"
        );
        setGroup("contact/stiffnessRatio", input("kt")/kn, "kt/kn");
        setGroup
        (
            "contact/damping", input("gammaN")*gammaDot/kn, "gammaN gammaDot/kn"
        );
        const dictionary& contact = reduced_.subDict("contact");
        if
        (
            contact.getOrDefault<word>("type", "")
         == suspension::CriticalLoadContact::typeName
        )
        {
            setGroup
            (
                "contact/criticalLoad",
                input("criticalLoad")/(eta0*sqr(a0)*gammaDot),
                "F_CL/(eta0 a0^2 gammaDot)"
            );
        }
    }

    if (reduced_.found("electroChemical", keyType::LITERAL))
    {
        const dictionary& ecDict = reduced_.subDict("electroChemical");
        const dictionary& attDict = ecDict.subDict("attraction");

        // eps/abar of eq. (7), as the attraction reads it
        const scalar epsDefault =
            suspension::ElectroChemicalScales::Params().epsilonFraction;
        const scalar eps = attDict.get<bool>("active")
          ? getScalarInOrDefault
            (
                attDict, "epsilon", epsDefault, interval::positive()
            )
          : epsDefault;

        const scalar FER = input("FER");
        setGroup
        (
            "electroChemical/shearRateRatio",
            eta0*sqr(a0)*gammaDot/FER,
            "eta0 a0^2 gammaDot/F_ER"
        );
        setGroup
        (
            "electroChemical/forceRatio",
            FER/(input("hamaker")*a0/(12*sqr(eps*a0))),
            "F_ER/F^A, F^A = A a0/(12 eps^2), eps = attraction/epsilon a0"
        );
        if (ecDict.subDict("repulsion").get<bool>("active"))
        {
            setGroup
            (
                "electroChemical/repulsion/debyeLength",
                input("debyeLength")/a0,
                "debyeLength/a0"
            );
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::suspensionUnits::suspensionUnits(const dictionary& dict)
:
    dimensional_(readDimensional(dict)),
    lengthUnit_(1),
    reduced_(dict),
    inputs_(),
    groups_()
{
    if (dimensional_)
    {
        convert();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::suspensionUnits::report(Ostream& os) const
{
    if (!dimensional_)
    {
        return;
    }
    os  << "Dimensional input (SI; times stay in units of 1/gammaDot)"
        << nl;
    for (const quantity& q : inputs_)
    {
        os  << "    input        " << q.name.c_str() << " = " << q.value << ' '
            << q.note.c_str() << nl;
    }
    os  << "    input        population radii in m, divided by a0" << nl;
    for (const quantity& q : groups_)
    {
        os  << "    group        " << q.name.c_str() << " = " << q.value
            << "  (" << q.note.c_str() << ')' << nl;
    }
}


// ************************************************************************* //
