#include "suspensionPopulation.H"
#include "inputChecks.H"
#include "ambientFlowAdapter.H"
#include "Enum.H"
#include "packing/RandomPacking.H"

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
});


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

    // logNormal
    const double mean = radius("radius");
    const double sd = radius("radiusStdDev");
    Foam::checkEntries(dict, valid);
    return SizeDistribution::logNormal(mean, sd);
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
    nParticles_(getLabelAtLeast(dict, "nParticles", 1)),
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
Foam::suspensionPopulation::packingParams() const
{
    suspension::RandomPacking::Params params;
    params.phi = volumeFraction_;
    params.seed = static_cast<std::uint64_t>(seed_);
    params.aspect = toEigen(aspect_);
    return params;
}


Foam::scalar Foam::suspensionPopulation::removeOverlaps
(
    suspension::Particles& particles,
    const vector& L
) const
{
    return suspension::RandomPacking(packingParams()).removeOverlaps
    (
        particles, toEigen(L)
    );
}


suspension::Particles Foam::suspensionPopulation::pack(const scalar rho) const
{
    const suspension::RandomPacking::Params params = packingParams();

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
