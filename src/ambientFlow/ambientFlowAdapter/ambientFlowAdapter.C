#include "ambientFlowAdapter.H"
#include "core/Particles.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ambientFlowAdapter::ambientFlowAdapter
(
    const ambientFlow& flow,
    const scalar tStart,
    const scalar tEnd
)
:
    flow_(flow),
    maxShearRate_(flow.programme().max(tStart, Foam::max(tStart, tEnd))),
    notKnown_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

suspension::FlowSample Foam::ambientFlowAdapter::sample
(
    const suspension::Vec3& x,
    const double gammaDot
) const
{
    suspension::FlowSample s;
    if (!sampleHere(x, gammaDot, s))
    {
        // Threads may not stop the run: sampled() does, after the loop
        notKnown_.store(true, std::memory_order_relaxed);
        return suspension::FlowSample();
    }
    return s;
}


bool Foam::ambientFlowAdapter::sampleHere
(
    const suspension::Vec3& x,
    const double gammaDot,
    suspension::FlowSample& s
) const
{
    ambientFlowSample values;
    if (!flow_.sample(toFoam(x), gammaDot, values))
    {
        return false;
    }
    s = toEigen(values);
    return true;
}


bool Foam::ambientFlowAdapter::sampledAnywhere() const
{
    return !Pstream::parRun() || flow_.bounds() == boundBox::greatBox;
}


double Foam::ambientFlowAdapter::shearRate(const double t) const
{
    return flow_.stressControlled() ? 0 : flow_.programme().value(t);
}


double Foam::ambientFlowAdapter::meanShearRate
(
    const double t0,
    const double t1
) const
{
    return flow_.programme().mean(t0, t1);
}


double Foam::ambientFlowAdapter::maxShearRate() const
{
    return maxShearRate_;
}


bool Foam::ambientFlowAdapter::shearRateChanges() const
{
    return !flow_.stressControlled() && !flow_.programme().constant();
}


bool Foam::ambientFlowAdapter::stressControlled() const
{
    return flow_.stressControlled();
}


double Foam::ambientFlowAdapter::shearStress(const double t) const
{
    return flow_.programme().value(t);
}


double Foam::ambientFlowAdapter::maxPeriodicGradient() const
{
    return flow_.maxPeriodicGradient();
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

    // Rare: search again, in particle order, for the first one (an owned
    // particle before a ghost)
    ambientFlowSample values;
    for (const bool ghosts : {false, true})
    {
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            if (particles.isGhost(i) != ghosts)
            {
                continue;
            }
            const point x = toFoam(particles.x[i]);
            if (!flow_.samplePeriodic(x, values))
            {
                flow_.notKnownAt
                (
                    "particle id " + Foam::name(particles.id[i])
                  + (ghosts ? ", a ghost," : "")
                  + " (index " + Foam::name(label(i)) + " of "
                  + Foam::name(label(particles.size())) + ")",
                    x
                );
            }
        }
    }
}


// ************************************************************************* //
