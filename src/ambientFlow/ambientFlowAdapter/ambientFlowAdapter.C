#include "ambientFlowAdapter.H"
#include "core/Particles.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ambientFlowAdapter::ambientFlowAdapter(const ambientFlow& flow)
:
    flow_(flow),
    notKnown_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

suspension::FlowSample Foam::ambientFlowAdapter::sample
(
    const suspension::Vec3& x
) const
{
    ambientFlowSample values;
    if (!flow_.sample(toFoam(x), values))
    {
        // Threads may not stop the run: sampled() does, after the loop
        notKnown_.store(true, std::memory_order_relaxed);
        return suspension::FlowSample();
    }
    return toEigen(values);
}


double Foam::ambientFlowAdapter::shearRate() const
{
    return flow_.shearRate();
}


double Foam::ambientFlowAdapter::maxVelocityGradient() const
{
    return flow_.maxVelocityGradient();
}


void Foam::ambientFlowAdapter::sampled
(
    const suspension::Particles& particles
) const
{
    if (!notKnown_.exchange(false))
    {
        return;
    }

    // Rare: search again, in particle order, for the first one
    ambientFlowSample values;
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        const point x = toFoam(particles.x[i]);
        if (!flow_.sample(x, values))
        {
            flow_.notKnownAt
            (
                "particle id " + Foam::name(particles.id[i])
              + " (index " + Foam::name(label(i)) + " of "
              + Foam::name(label(particles.size())) + ")",
                x
            );
        }
    }
}


// ************************************************************************* //
