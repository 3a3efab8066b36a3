#include "stress/Rheology.H"

#include <limits>

namespace suspension
{

Rheology::Rheology
(
    const ForceSummary& summary,
    double volume,
    double eta0,
    double gammaDot
)
{
    // 2 eta0 <E_inf>: the fluid's own stress (eq. 8)
    Sigma = Mat3::Zero();
    Sigma(0, 1) = Sigma(1, 0) = eta0*gammaDot;

    // At a zero rate (a reversal, an oscillation) the viscosities are not
    // defined: NaN, not a division by zero
    const double scale = eta0*gammaDot;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto per = [&](double x) { return scale != 0 ? x/scale : nan; };
    const std::size_t nC = summary.stresslet.size();
    part.resize(nC);
    etaRPart.resize(nC);
    for (std::size_t c = 0; c < nC; ++c)
    {
        part[c] = summary.stresslet[c]/volume;
        Sigma += part[c];
        etaRPart[c] = per(part[c](0, 1));
    }

    sigma = Sigma(0, 1);
    N1 = Sigma(0, 0) - Sigma(1, 1);
    N2 = Sigma(1, 1) - Sigma(2, 2);
    Pi = -Sigma.trace()/3;
    etaR = per(sigma);
    etaN = per(Pi);
}

} // namespace suspension
