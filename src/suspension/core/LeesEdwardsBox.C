#include "core/LeesEdwardsBox.H"

#include <cmath>
#include <stdexcept>
#include <string>

namespace suspension
{

namespace
{
    //- Largest integer <= x (|x| < 2^62: the callers keep x within
    //  maxWrapLengths), inlined
    inline long floorInt(double x)
    {
        const long t = static_cast<long>(x);
        return t - (x < t);
    }

    //- x - L floor(x/L), in [0, L)
    double periodic(double x, double L)
    {
        double y = x - L*floorInt(x/L);
        return y < L ? y : 0.0;
    }
}


LeesEdwardsBox::LeesEdwardsBox(const Vec3& L, double gammaDot)
:
    L_(L),
    invL_(L.cwiseInverse()),
    wrapLimit_(maxWrapLengths*L),
    gammaDot_(gammaDot),
    offset_(0)
{
    if (!(L.minCoeff() > 0))
    {
        throw std::invalid_argument
        (
            "LeesEdwardsBox: box lengths must be positive, got ("
          + std::to_string(L.x()) + " " + std::to_string(L.y()) + " "
          + std::to_string(L.z()) + ")"
        );
    }
}


void LeesEdwardsBox::setStrain(double gamma)
{
    setOffset(gamma*L_.y());
}


void LeesEdwardsBox::setOffset(double delta)
{
    if (!(std::abs(delta) < wrapLimit_.x()))
    {
        throw std::invalid_argument
        (
            "LeesEdwardsBox: the offset " + std::to_string(delta)
          + " of the image above cannot be wrapped (not finite, or 2^"
          + std::to_string(std::ilogb(maxWrapLengths)) + " box lengths or"
            " more): a non-finite or too large strain"
        );
    }
    offset_ = periodic(delta, L_.x());
}


long LeesEdwardsBox::wrap(Vec3& x, Vec3& u) const
{
    if (!wrappable(x))
    {
        return 0;
    }
    // eq. (16a,b,d): leaving through the top re-enters at the bottom with
    // x - delta and u_x - gammaDot Ly, and vice versa
    const long crossings = floorInt(x.y()/L_.y());
    if (crossings != 0)
    {
        x.y() -= crossings*L_.y();
        x.x() -= crossings*offset_;
        u.x() -= crossings*imageVelocity();
        if (x.y() >= L_.y()) x.y() = 0.0;  // round-off at the upper face
    }
    x.x() = periodic(x.x(), L_.x());      // eq. (16a)
    x.z() = periodic(x.z(), L_.z());      // eq. (16c)
    return crossings;
}

} // namespace suspension
