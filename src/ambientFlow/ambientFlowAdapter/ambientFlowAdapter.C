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
    const point p(toFoam(x));

    suspension::FlowSample f;
    f.U = toEigen(flow_.U(p));
    f.gradU = toEigen(flow_.gradU(p));
    f.laplacianU = toEigen(flow_.laplacianU(p));
    f.gradLaplacianU = toEigen(flow_.gradLaplacianU(p));
    return f;
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
