#include "forces/FrictionalContact.H"
#include "forces/PairRadii.H"

#include <algorithm>
#include <cmath>

namespace suspension
{

namespace
{
    //- One step of a Luding spring stretch (eq. 5, Luding 2008): rotate xi
    //  onto the tangent plane of n keeping its length, advance it by the
    //  tangential velocity v over dt, cap its length at maxLength
    void advanceStretch
    (
        Vec3& xi,
        const Vec3& n,
        const Vec3& v,
        double dt,
        double maxLength
    )
    {
        const double length = xi.norm();
        const Vec3 projected = xi - n.dot(xi)*n;
        const double projectedLength = projected.norm();
        xi = projectedLength > 0
           ? Vec3(projected*(length/projectedLength))
           : Vec3::Zero();

        xi += v*dt;

        const double newLength = xi.norm();
        if (newLength > maxLength)
        {
            xi *= maxLength/newLength;
        }
    }
}


FrictionalContact::FrictionalContact(const Params& p)
:
    p_(p),
    muR_(p.muR.value_or(p.muC))
{
    const char* model = "FrictionalContact";
    checkPositive(model, "kn", p.kn);
    checkPositive(model, "kt", p.kt);
    checkNonNegative(model, "gammaN", p.gammaN);
    checkNonNegative(model, "muC", p.muC);
    checkNonNegative(model, "kr", p.kr);
    checkNonNegative(model, "muR", muR_);
}


FrictionalContact::Params FrictionalContact::fromGroups
(
    double kHat,
    double ktOverKn,
    double gammaNOverKn,
    double muC
)
{
    Params p;
    p.kn = kHat;                    // eq. (12), eta0 = a0 = gammaDot = 1
    p.kt = ktOverKn*p.kn;           // eq. (13)
    p.gammaN = gammaNOverKn*p.kn;   // eq. (13), gammaDot = 1
    p.muC = muC;
    return p;
}


PairForce FrictionalContact::eval
(
    const PairGeometry& g,
    const PairKinematics& kin,
    ContactState& state,
    double dt
) const
{
    PairForce f;
    if (!inContact(g))
    {
        return f;
    }

    const Vec3& n = g.n;

    // Normal spring-dashpot on i; h < 0 pushes i away from j      eq. (4a)
    const double un = n.dot(kin.du);
    const double fn = p_.kn*g.h + p_.gammaN*un;
    const double FnMag = std::abs(fn);

    // Relative velocity of the contact points, tangential         eq. (5)
    const Vec3 ut =
        kin.du - un*n - (g.ai*kin.omegai + g.aj*kin.omegaj).cross(n);

    // Stick-and-slide stretch and force                            eqs. (5), (4b)
    advanceStretch(state.xiT, n, ut, dt, p_.muC*FnMag/p_.kt);
    const Vec3 Ft = p_.kt*state.xiT;

    f.F = fn*n + Ft;
    f.Ti = g.ai*n.cross(Ft);                                    // eq. (4d)
    f.Tj = (g.aj/g.ai)*f.Ti;                                    // eq. (4e)

    if (p_.kr > 0)
    {
        // Rolling velocity; xiR holds n x xi_r (see Description)   App. B
        const double aij = harmonicRadius(g.ai, g.aj);
        const Vec3 ur = aij*(n.cross(kin.omegai) - n.cross(kin.omegaj));
        advanceStretch(state.xiR, n, n.cross(ur), dt, muR_*FnMag/p_.kr);

        const Vec3 Fr = p_.kr*state.xiR.cross(n);               // eq. (B.1a)
        const Vec3 Tr = aij*n.cross(Fr);                        // eq. (B.1b)
        f.Ti += Tr;
        f.Tj -= Tr;                                             // eq. (B.1c)
    }

    f.S = symm(outer(g.r, f.F));                                // eq. (9c)
    return f;
}


double FrictionalContact::contactTimeScale
(
    const Params& p,
    double mi,
    double ai,
    double mj,
    double aj
)
{
    const double mRed = mi*mj/(mi + mj);
    const double Ii = 0.4*mi*ai*ai;
    const double Ij = 0.4*mj*aj*aj;

    const double omegaN2 = p.kn/mRed;
    const double omegaT2 = p.kt*(1/mRed + ai*ai/Ii + aj*aj/Ij);
    const double aij = harmonicRadius(ai, aj);
    const double omegaR2 = aij*aij*p.kr*(1/Ii + 1/Ij);

    double t = pi/std::sqrt(std::max({omegaN2, omegaT2, omegaR2}));
    if (p.gammaN > 0)
    {
        t = std::min(t, mRed/p.gammaN);
    }
    return t;
}

} // namespace suspension
