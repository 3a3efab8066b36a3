#include "forces/Lubrication.H"

#include "forces/ParamCheck.H"

#include <algorithm>
#include <sstream>

namespace suspension
{

Lubrication::Lubrication(const Params& params)
:
    params_(params)
{
    const char* model = "Lubrication";
    checkPositive(model, "eta", params_.eta);
    checkPositive(model, "epsilon", params_.epsilon);
    checkPositive(model, "deltaLub", params_.deltaLub);
}


void Lubrication::prepare(const std::vector<double>& radii)
{
    std::vector<double> distinct(radii);
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    radii_.clear();
    factors_.clear();
    if (distinct.size() > maxTabulatedRadii)
    {
        return;
    }
    for (const double ai : distinct)
    {
        for (const double aj : distinct)
        {
            factors_.emplace_back(ai, aj, params_.eta);
        }
    }
    radii_ = std::move(distinct);
}


LubricationCoefficients Lubrication::coefficients(const PairGeometry& g) const
{
    const double xi = 2*g.h/(g.ai + g.aj);      // d*_ij (A.6)
    const LubricationCoefficients::Gap gap =
        LubricationCoefficients::Gap::make(xi, params_.epsilon, params_.terms);

    const std::size_t n = radii_.size();
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < n && radii_[i] != g.ai) ++i;
    while (j < n && radii_[j] != g.aj) ++j;
    if (i < n && j < n)
    {
        return factors_[i*n + j].at(gap);
    }
    return LubricationCoefficients(g.ai, g.aj, gap, params_.eta);
}


Lubrication::PairVector Lubrication::strainForces
(
    const LubricationCoefficients& c,
    const Vec3& n,
    const Mat3& Ei,
    const Mat3& Ej
)
{
    const Vec3 Ein = Ei*n;
    const Vec3 Ejn = Ej*n;

    // P_b (A.4), Q_b . n = 2 T.E_b.n (A.5), n_perp,b = 2 n x (E_b.n) (eq. 3)
    const double Pi = n.dot(Ein) - Ei.trace()/3;
    const double Pj = n.dot(Ejn) - Ej.trace()/3;
    const Vec3 Qin = 2*(Ein - n.dot(Ein)*n);
    const Vec3 Qjn = 2*(Ejn - n.dot(Ejn)*n);
    const Vec3 perpi = 2*n.cross(Ein);
    const Vec3 perpj = 2*n.cross(Ejn);

    // (A.3): the strain of sphere b multiplies G_ba, H_ba
    PairVector f;
    f.segment<3>(0) =
        (c.XG.ii*Pi + c.XG.ji*Pj)*n + c.YG.ii*Qin + c.YG.ji*Qjn;
    f.segment<3>(3) =
        (c.XG.ij*Pi + c.XG.jj*Pj)*n + c.YG.ij*Qin + c.YG.jj*Qjn;
    f.segment<3>(6) = c.YH.ii*perpi + c.YH.ji*perpj;
    f.segment<3>(9) = c.YH.ij*perpi + c.YH.jj*perpj;
    return f;
}


Lubrication::PairVector Lubrication::strainForces
(
    const PairGeometry& g,
    const Mat3& Ei,
    const Mat3& Ej
) const
{
    return strainForces(coefficients(g), g.n, Ei, Ej);
}


PairForce Lubrication::eval
(
    const PairGeometry& g,
    const PairKinematics& k
) const
{
    const LubricationCoefficients c = coefficients(g);
    const Vec3& n = g.n;

    // Normal (N v) and tangential (T v) parts
    const Vec3 uiN = n.dot(k.ui)*n;
    const Vec3 ujN = n.dot(k.uj)*n;
    const Vec3 uiT = k.ui - uiN;
    const Vec3 ujT = k.uj - ujN;
    const Vec3 wiT = k.wi - n.dot(k.wi)*n;
    const Vec3 wjT = k.wj - n.dot(k.wj)*n;

    const PairVector fE = strainForces(c, n, k.Ei, k.Ej);

    PairForce f;

    // eq. (3), rows F_i, T_i, T_j of R_Lub (A.2) and R'_Lub (A.3)
    f.F =
      - c.XA.ii*uiN - c.YA.ii*uiT - c.XA.ij*ujN - c.YA.ij*ujT
      - c.YB.ii*n.cross(k.wi) - c.YB.ji*n.cross(k.wj)
      + fE.segment<3>(0);

    f.Ti =
        c.YB.ii*n.cross(k.ui) + c.YB.ij*n.cross(k.uj)
      - c.YC.ii*wiT - c.YC.ij*wjT
      + fE.segment<3>(6);

    f.Tj =
        c.YB.ji*n.cross(k.ui) + c.YB.jj*n.cross(k.uj)
      - c.YC.ji*wiT - c.YC.jj*wjT
      + fE.segment<3>(9);

    // eq. (9b)
    f.S = symm(outer(g.r, f.F));

    return f;
}


Lubrication::PairMatrix Lubrication::resistanceMatrix
(
    const LubricationCoefficients& c,
    const Vec3& n
)
{
    const Mat3 N = outer(n, n);
    const Mat3 T = Mat3::Identity() - N;
    const Mat3 nx = crossMatrix(n);

    PairMatrix R;

    // A: force - velocity
    R.block<3, 3>(0, 0) = c.XA.ii*N + c.YA.ii*T;
    R.block<3, 3>(0, 3) = c.XA.ij*N + c.YA.ij*T;
    R.block<3, 3>(3, 0) = c.XA.ji*N + c.YA.ji*T;
    R.block<3, 3>(3, 3) = c.XA.jj*N + c.YA.jj*T;

    // B~_ab = Y^B_ba [n x]: force - spin (reciprocal theorem, index swap)
    R.block<3, 3>(0, 6) = c.YB.ii*nx;
    R.block<3, 3>(0, 9) = c.YB.ji*nx;
    R.block<3, 3>(3, 6) = c.YB.ij*nx;
    R.block<3, 3>(3, 9) = c.YB.jj*nx;

    // B_ab = -Y^B_ab [n x]: torque - velocity
    R.block<3, 3>(6, 0) = -c.YB.ii*nx;
    R.block<3, 3>(6, 3) = -c.YB.ij*nx;
    R.block<3, 3>(9, 0) = -c.YB.ji*nx;
    R.block<3, 3>(9, 3) = -c.YB.jj*nx;

    // C: torque - spin (Y^C T, not Y^C n x as printed in (A.2))
    R.block<3, 3>(6, 6) = c.YC.ii*T;
    R.block<3, 3>(6, 9) = c.YC.ij*T;
    R.block<3, 3>(9, 6) = c.YC.ji*T;
    R.block<3, 3>(9, 9) = c.YC.jj*T;

    return R;
}


Lubrication::PairMatrix Lubrication::resistanceMatrix
(
    const PairGeometry& g
) const
{
    return resistanceMatrix(coefficients(g), g.n);
}

Lubrication::Params Lubrication::read(const ModelInput& input)
{
    Params p;
    p.deltaLub = input.scalar
    (
        "delta", ModelInput::Range::positive(),
        "delta_lub/a0: largest surface gap with lubrication (fig. 1)"
    );
    p.epsilon = input.scalar
    (
        "epsilon", ModelInput::Range::positive(),
        "gap regularisation (A.6)"
    );
    p.terms = input.word
    (
        "terms", {"leading", "extended"}, true,
        "orders of the near-contact expansions kept"
    ) == "extended" ? Terms::extended : Terms::leading;
    return p;
}


std::string Lubrication::describe() const
{
    std::ostringstream os;
    os  << "deltaLub = " << params_.deltaLub << ", epsilon = "
        << params_.epsilon << ", terms "
        << (params_.terms == Terms::leading ? "leading" : "extended");
    return os.str();
}


void Lubrication::addTimeStepLimits(TimeStepLimitBuilder& limits) const
{
    if (limits.explicitHydrodynamics())
    {
        // The squeeze mode of a touching pair: relaxation with tau
        // (TimeStepLimits.H), stable for dt < 2 tau
        limits.addOverPairs("lubrication", [&](double ai, double aj)
        {
            return 2*limits.pairRelaxationTime(ai, aj);
        });
    }
    else if (limits.maxVelocityGradient() > 0)
    {
        // Accuracy: a step moves a touching pair by at most 10
        // regularised gaps at the default safety (TimeStepLimits.H)
        limits.add
        (
            "lubricationGap", 25*params_.epsilon/limits.maxVelocityGradient()
        );
    }
}

} // namespace suspension
