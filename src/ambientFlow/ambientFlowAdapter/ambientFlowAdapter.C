#include "ambientFlowAdapter.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ambientFlowAdapter::ambientFlowAdapter(const ambientFlow& flow)
:
    flow_(flow)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

suspension::FlowSample Foam::ambientFlowAdapter::sample
(
    const suspension::Vec3& x
) const
{
    return flow_.sample(toFoam(x));
}


double Foam::ambientFlowAdapter::shearRate() const
{
    return flow_.shearRate();
}


double Foam::ambientFlowAdapter::maxVelocityGradient() const
{
    return flow_.maxVelocityGradient();
}


// ************************************************************************* //
