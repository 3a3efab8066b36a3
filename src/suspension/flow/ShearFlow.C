#include "flow/ShearFlow.H"

#include <cmath>
#include <stdexcept>
#include <string>

namespace suspension
{

ShearFlow::ShearFlow(double gammaDot0)
:
    gammaDot0_(gammaDot0),
    amplitude_(0),
    k_(0)
{}


ShearFlow::ShearFlow(double gammaDot0, double amplitude, double periods, double Ly)
:
    gammaDot0_(gammaDot0),
    amplitude_(amplitude),
    k_(0)
{
    if (!(Ly > 0))
    {
        throw std::invalid_argument
        (
            "ShearFlow: box height Ly must be positive, got " + std::to_string(Ly)
        );
    }
    k_ = 2*pi*periods/Ly;
}


FlowSample ShearFlow::sample(const Vec3& x, double gammaDot) const
{
    const double s = std::sin(k_*x.y());
    const double c = std::cos(k_*x.y());

    FlowSample f;
    f.U.x() = gammaDot*x.y() + amplitude_*s;                // eq. (17)
    f.gradU(1, 0) = gammaDot + amplitude_*k_*c;              // d_y U_x
    f.laplacianU.x() = -amplitude_*k_*k_*s;                 // d_yy U_x
    f.gradLaplacianU(1, 0) = -amplitude_*k_*k_*k_*c;        // d_yyy U_x
    return f;
}


double ShearFlow::maxShearRate() const
{
    return std::abs(gammaDot0_);
}


double ShearFlow::maxPeriodicGradient() const
{
    return std::abs(amplitude_*k_);
}

} // namespace suspension
