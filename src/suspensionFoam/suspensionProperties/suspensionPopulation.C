#include "suspensionPopulation.H"
#include "inputChecks.H"
#include "ambientFlowAdapter.H"
#include "Enum.H"
#include "OSspecific.H"
#include "IOmanip.H"
#include "scalarList.H"
#include "packing/RandomPacking.H"

#include <cstdlib>
#include <fstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using Foam::dictionary;
using Foam::interval;
using Foam::wordList;
using suspension::SizeDistribution;

const Foam::Enum<SizeDistribution::Type> distributionTypes
({
    {SizeDistribution::Type::monodisperse, "monodisperse"},
    {SizeDistribution::Type::bidisperse, "bidisperse"},
    {SizeDistribution::Type::uniform, "uniform"},
    {SizeDistribution::Type::logNormal, "logNormal"},
    {SizeDistribution::Type::discrete, "discrete"},
    {SizeDistribution::Type::list, "file"},
});


//- List entry `key` of dict, every element > 0, divided by unit
std::vector<double> getPositiveList
(
    const dictionary& dict,
    const Foam::word& key,
    const Foam::scalar unit
)
{
    const Foam::scalarList values = dict.get<Foam::scalarList>(key);
    if (values.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' of dictionary " << dict.name()
            << " is empty" << Foam::nl << Foam::exit(Foam::FatalIOError);
    }
    std::vector<double> v;
    forAll(values, k)
    {
        if (!interval::positive().contains(values[k]))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << key << "' of dictionary " << dict.name()
                << ": element " << k << " = " << values[k]
                << " is outside " << interval::positive() << Foam::nl
                << Foam::exit(Foam::FatalIOError);
        }
        v.push_back(values[k]/unit);
    }
    return v;
}


//- Discrete radii with exactly one of volumeFractions and numberFractions,
//  one per radius, summing to 1
SizeDistribution readDiscrete
(
    const dictionary& dict,
    const Foam::scalar lengthUnit,
    wordList& valid
)
{
    valid.append(wordList({"radii", "volumeFractions", "numberFractions"}));
    const std::vector<double> radii = getPositiveList(dict, "radii", lengthUnit);

    const bool byVolume = dict.found("volumeFractions");
    if (byVolume == dict.found("numberFractions"))
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary " << dict.name() << " (type discrete) needs"
            << " exactly one of the entries 'volumeFractions' and"
            << " 'numberFractions'" << Foam::nl << Foam::exit(Foam::FatalIOError);
    }
    const Foam::word key = byVolume ? "volumeFractions" : "numberFractions";
    const std::vector<double> fractions = getPositiveList(dict, key, 1);
    if (fractions.size() != radii.size())
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' of dictionary " << dict.name()
            << " holds " << Foam::label(fractions.size()) << " fractions for "
            << Foam::label(radii.size()) << " radii: give one per radius"
            << Foam::nl << Foam::exit(Foam::FatalIOError);
    }
    double sum = 0;
    for (double f : fractions)
    {
        sum += f;
    }
    if (!(std::abs(sum - 1) <= SizeDistribution::fractionTolerance))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' of dictionary " << dict.name()
            << " sums to " << Foam::setprecision(10) << sum
            << ", not to 1 within " << SizeDistribution::fractionTolerance
            << Foam::nl << Foam::exit(Foam::FatalIOError);
    }
    Foam::checkEntries(dict, valid);
    return Foam::engineCall
    (
        dict,
        [&]
        {
            return SizeDistribution::discrete
            (
                radii,
                fractions,
                byVolume
              ? SizeDistribution::Fractions::volume
              : SizeDistribution::Fractions::number
            );
        }
    );
}


//- The radii of the file named by entry 'file': whitespace-separated
//  numbers, each > 0, divided by lengthUnit
SizeDistribution readFile
(
    const dictionary& dict,
    const Foam::scalar lengthUnit,
    wordList& valid
)
{
    valid.append(wordList({"file"}));
    Foam::checkEntries(dict, valid);

    Foam::fileName file = dict.get<Foam::fileName>("file");
    file.expand();
    if (!file.isAbsolute())
    {
        file = Foam::fileName(Foam::getEnv("FOAM_CASE"))/file;
    }
    const auto fail = [&](const Foam::string& what)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'file' of dictionary " << dict.name() << ": " << what
            << Foam::nl << Foam::exit(Foam::FatalIOError);
    };

    std::ifstream is(file);
    if (!is)
    {
        fail("cannot open the radius file " + file);
    }
    std::vector<double> radii;
    std::string token;
    while (is >> token)
    {
        char* end = nullptr;
        const double a = std::strtod(token.c_str(), &end);
        const Foam::string where =
            "radius " + Foam::name(Foam::label(radii.size() + 1))
          + " of " + file;
        if (end != token.c_str() + token.size())
        {
            fail(where + ", '" + token + "', is not a number");
        }
        if (!interval::positive().contains(a))
        {
            fail(where + " = " + token + " is outside (0, inf)");
        }
        radii.push_back(a/lengthUnit);
    }
    if (radii.empty())
    {
        fail("the radius file " + file + " holds no radii");
    }
    Foam::Info<< "Read " << Foam::label(radii.size()) << " radii from "
        << file << Foam::endl;
    return SizeDistribution::list(std::move(radii));
}


//- The distribution named by 'type' with its entries, radii divided by
//  lengthUnit; the entries of the dictionary are checked against those of
//  the type
SizeDistribution readDistribution
(
    const dictionary& dict,
    const Foam::scalar lengthUnit
)
{
    const SizeDistribution::Type type =
        Foam::getEnum(dict, "type", distributionTypes);

    wordList valid({"type", "nParticles", "volumeFraction", "seed", "aspect"});
    const auto radius = [&](const char* key)
    {
        valid.append(key);
        return Foam::getScalarIn(dict, key, interval::positive())/lengthUnit;
    };

    if (type == SizeDistribution::Type::monodisperse)
    {
        const double a = radius("radius");
        Foam::checkEntries(dict, valid);
        return SizeDistribution::monodisperse(a);
    }
    if (type == SizeDistribution::Type::bidisperse)
    {
        const double a1 = radius("radius");
        valid.append(wordList({"sizeRatio", "volumeRatio"}));
        const double sizeRatio =
            Foam::getScalarIn(dict, "sizeRatio", interval::positive());
        const double volumeRatio =
            Foam::getScalarIn(dict, "volumeRatio", interval::positive());
        Foam::checkEntries(dict, valid);
        return SizeDistribution::bidisperse(a1, sizeRatio, volumeRatio);
    }
    if (type == SizeDistribution::Type::uniform)
    {
        const double aMin = radius("radiusMin");
        const double aMax = radius("radiusMax");
        Foam::checkEntries(dict, valid);
        return Foam::engineCall
        (
            dict,
            [&]{ return SizeDistribution::uniform(aMin, aMax); }
        );
    }

    if (type == SizeDistribution::Type::discrete)
    {
        return readDiscrete(dict, lengthUnit, valid);
    }
    if (type == SizeDistribution::Type::list)
    {
        return readFile(dict, lengthUnit, valid);
    }

    // logNormal
    const double mean = radius("radius");
    const double sd = radius("radiusStdDev");
    Foam::checkEntries(dict, valid);
    return SizeDistribution::logNormal(mean, sd);
}


//- nParticles: from the dictionary (at least the distribution's minN), or
//  the number of radii of a list, which an nParticles entry must match
Foam::label readNParticles
(
    const dictionary& dict,
    const SizeDistribution& distribution
)
{
    const Foam::label nMin = Foam::label(distribution.minN());
    if (!distribution.fixedN())
    {
        return Foam::getLabelAtLeast(dict, "nParticles", nMin);
    }
    Foam::label n = nMin;
    if (dict.readIfPresent("nParticles", n) && n != nMin)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'nParticles' = " << n << " of dictionary " << dict.name()
            << " does not match the " << nMin << " radii of the radius file;"
            << " remove it or correct it" << Foam::nl
            << Foam::exit(Foam::FatalIOError);
    }
    return n;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::suspensionPopulation::suspensionPopulation
(
    const dictionary& dict,
    const scalar lengthUnit
)
:
    dict_(dict),
    distribution_(readDistribution(dict, lengthUnit)),
    nParticles_(readNParticles(dict, distribution_)),
    volumeFraction_
    (
        getScalarIn
        (
            dict, "volumeFraction", interval::open(0, suspension::phiMax)
        )
    ),
    aspect_(dict.getOrDefault<vector>("aspect", vector::one)),
    seed_(getLabelAtLeast(dict, "seed", 0)),
    radii_
    (
        engineCall
        (
            dict,
            [this]{ return distribution_.radii(nParticles_); }
        )
    ),
    box_
    (
        toFoam
        (
            engineCall
            (
                dict,
                [this]
                {
                    return suspension::boxLengths
                    (
                        radii_, volumeFraction_, toEigen(aspect_)
                    );
                }
            )
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

suspension::RandomPacking::Params
Foam::suspensionPopulation::packingParams(const suspension::BoxRule& rule) const
{
    suspension::RandomPacking::Params params;
    params.phi = volumeFraction_;
    params.reach = rule.reach();
    params.seed = static_cast<std::uint64_t>(seed_);
    params.aspect = toEigen(aspect_);
    return params;
}


void Foam::suspensionPopulation::checkBox
(
    const suspension::BoxRule& rule,
    const string& hint
) const
{
    try
    {
        rule.check
        (
            distribution_, nParticles_, volumeFraction_, toEigen(aspect_)
        );
    }
    catch (const std::invalid_argument& err)
    {
        raiseEngineError(dict_, err, hint);
    }
}


Foam::scalar Foam::suspensionPopulation::removeOverlaps
(
    suspension::Particles& particles,
    const vector& L,
    const suspension::BoxRule& rule
) const
{
    return suspension::RandomPacking(packingParams(rule)).removeOverlaps
    (
        particles, toEigen(L)
    );
}


suspension::Particles Foam::suspensionPopulation::pack
(
    const scalar rho,
    const suspension::BoxRule& rule
) const
{
    const suspension::RandomPacking::Params params = packingParams(rule);

    try
    {
        suspension::RandomPacking::Result result = engineCall
        (
            dict_,
            [&]{ return suspension::RandomPacking(params).pack(radii_, rho); }
        );

        Info<< "Packed " << nParticles_ << " spheres at phi = "
            << volumeFraction_ << " in " << result.statistics.stages
            << " growth stages, " << result.statistics.iterations
            << " FIRE iterations" << nl;

        return std::move(result.particles);
    }
    catch (const suspension::PackingError& err)
    {
        raiseEngineError
        (
            dict_,
            err,
            "The densest overlap-free volume fraction reached is "
          + name(err.phiReached())
          + ": lower 'volumeFraction' or change 'seed'"
        );
    }
}


// ************************************************************************* //
