#include "forces/FrictionalContact.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace suspension
{

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


FrictionalContact::Params FrictionalContact::read(const ModelInput& input)
{
    using Range = ModelInput::Range;
    const double kHat = input.scalar
    (
        "stiffness", Range::positive(), "k_hat = kn/(eta0 a0 gammaDot) (eq. 12)"
    );
    const double ktOverKn =
        input.scalar("stiffnessRatio", Range::positive(), "kt/kn (eq. 13)");
    const double gammaNOverKn = input.scalar
    (
        "damping", Range::nonNegative(), "gamma_n gammaDot/kn (eq. 13)"
    );
    const double muC = input.scalar("friction", Range::nonNegative(), "mu_C (eq. 5)");
    Params p = fromGroups(kHat, ktOverKn, gammaNOverKn, muC);
    p.kr = p.kn*input.scalarOr
    (
        "rollingStiffnessRatio", 0, Range::nonNegative(),
        "kr/kn, 0: no rolling resistance (appendix B)"
    );
    p.muR = input.scalarOr
    (
        "rollingFriction", p.muC, Range::nonNegative(),
        "mu_r (appendix B; default mu_C)"
    );
    return p;
}


std::string FrictionalContact::describe() const
{
    std::ostringstream os;
    os  << "kn = " << p_.kn << ", kt = " << p_.kt << ", gammaN = "
        << p_.gammaN << ", muC = " << p_.muC << ", kr = " << p_.kr
        << ", muR = " << muR_;
    return os.str();
}


void FrictionalContact::addTimeStepLimits(TimeStepLimitBuilder& limits) const
{
    using Mode = TimeStepLimitBuilder::Mode;
    if (limits.explicitHydrodynamics())
    {
        limits.addOverPairs("contact", [&](double ai, double aj)
        {
            const double rho = limits.rho();
            auto mass = [rho](double a) { return 4.0/3.0*pi*a*a*a*rho; };
            return 2*contactTimeScale(p_, mass(ai), ai, mass(aj), aj)/pi;
        });
        return;
    }

    // Implicit: the normal spring when it is explicit, against the pair's
    // resistance at contact (the regularised gap); the normal dashpot,
    // gamma_n << that resistance, sets no limit
    if (!limits.implicitNormalContact())
    {
        limits.addOverPairs("contact", [&](double ai, double aj)
        {
            return limits.springLimit(p_.kn, Mode::normal, ai, aj, 0);
        });
    }

    // and the sliding stretches' explicit Coulomb forces (Description)
    const bool sliding = p_.muC > 0;
    const bool rolling = p_.kr > 0 && muR_ > 0;
    if (!sliding && !rolling)
    {
        return;
    }
    limits.addOverPairs("slidingFriction", [&](double ai, double aj)
    {
        double dt = std::numeric_limits<double>::infinity();
        if (sliding)
        {
            dt = limits.springLimit(p_.kt, Mode::tangential, ai, aj, 0);
        }
        if (rolling)
        {
            dt = std::min(dt, limits.springLimit(p_.kr, Mode::rolling, ai, aj, 0));
        }
        return slidingFrictionFactor*dt;
    });
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
