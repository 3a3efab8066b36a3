#include "dynamics/TimeStepLimits.H"
#include "forces/PairRadii.H"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace suspension
{

namespace
{
    double sphereMass(double a, double rho)
    {
        return 4.0/3.0*pi*a*a*a*rho;
    }

    //- Fastest relaxation time of a touching pair under Stokes drag and
    //  lubrication: 1/lambda_max of R v = lambda M v (12 dof)
    double pairRelaxationTime
    (
        const ForceModels& models,
        double ai,
        double aj,
        double rho
    )
    {
        const double eta = models.drag.params().eta;
        const PairGeometry g =
            PairGeometry::make(Vec3(ai + aj, 0, 0), ai, aj);

        Lubrication::PairMatrix R = models.lubrication->resistanceMatrix(g);
        Eigen::Matrix<double, 12, 1> M;
        const double radius[2] = {ai, aj};
        for (int s = 0; s < 2; ++s)
        {
            const double a = radius[s];
            const double m = sphereMass(a, rho);
            for (int d = 0; d < 3; ++d)
            {
                R(3*s + d, 3*s + d) += 6*pi*eta*a;          // (A.1)
                R(6 + 3*s + d, 6 + 3*s + d) += 8*pi*eta*a*a*a;
                M(3*s + d) = m;
                M(6 + 3*s + d) = 0.4*m*a*a;
            }
        }
        // M^-1/2 R M^-1/2 is symmetric with the same eigenvalues
        const Eigen::Matrix<double, 12, 1> s = M.cwiseInverse().cwiseSqrt();
        const Lubrication::PairMatrix A = s.asDiagonal()*R*s.asDiagonal();
        const double lambdaMax =
            Eigen::SelfAdjointEigenSolver<Lubrication::PairMatrix>
            (
                A, Eigen::EigenvaluesOnly
            ).eigenvalues().maxCoeff();
        return 1/lambdaMax;
    }

    //- Largest stable step of a spring k with dashpot gamma (explicit) on
    //  a coordinate of inertia m with resistance zeta (implicit); see the
    //  header. zeta = gamma = 0: the explicit spring limit 2 sqrt(m/k).
    double modeLimit(double k, double gamma, double m, double zeta)
    {
        const double c = zeta - gamma;
        double dt = (c + std::sqrt(c*c + 4*k*m))/k;
        if (gamma > zeta)
        {
            dt = std::min(dt, 2*m/(gamma - zeta));
        }
        return dt;
    }

    //- Inverse effective inertias of the normal, tangential and rolling
    //  contact modes of a pair, from the translational (t) and rotational
    //  (r) inertias of its spheres: masses and moments of inertia, or the
    //  Stokes resistances 6 pi eta a and 8 pi eta a^3
    std::array<double, 3> contactModes
    (
        double ai,
        double ti,
        double ri,
        double aj,
        double tj,
        double rj
    )
    {
        const double aij = harmonicRadius(ai, aj);
        const double normal = 1/ti + 1/tj;
        return {normal, normal + ai*ai/ri + aj*aj/rj, aij*aij*(1/ri + 1/rj)};
    }

    //- Largest |dF/dh| of a central force over h in [0, hMax], sampled
    template<class Model>
    double sampledStiffness(const Model& model, double ai, double aj, double hMax)
    {
        const int n = 2000;
        const double dh = hMax/n;
        double k = 0;
        double Fprev = 0;
        for (int s = 0; s <= n; ++s)
        {
            const double h = s*dh;
            const PairGeometry g =
                PairGeometry::make(Vec3(ai + aj + h, 0, 0), ai, aj);
            const double F = model.eval(g).F.x();
            if (s > 0)
            {
                k = std::max(k, std::abs(F - Fprev)/dh);
            }
            Fprev = F;
        }
        return k;
    }
}


TimeStepLimits::TimeStepLimits
(
    const ForceModels& models,
    double aMin,
    double aMax,
    double rho,
    double safety,
    Integrator integrator
)
:
    safety_(safety)
{
    if (!(aMin > 0) || !(aMax >= aMin) || !(rho > 0) || !(safety > 0 && safety <= 1))
    {
        throw std::invalid_argument
        (
            "TimeStepLimits: need 0 < aMin <= aMax, rho > 0 and 0 < safety <= 1; got aMin "
          + std::to_string(aMin) + ", aMax " + std::to_string(aMax) + ", rho "
          + std::to_string(rho) + ", safety " + std::to_string(safety)
        );
    }

    const bool explicitHydrodynamics = integrator == Integrator::velocityVerlet;
    const bool inertia = integrator != Integrator::overdamped;
    const double eta = models.drag.params().eta;
    const double mMin = sphereMass(aMin, rho);
    if (explicitHydrodynamics)
    {
        limits_.push_back
        ({
            "stokesDrag",
            2*std::min
            (
                StokesDrag::relaxationTime(mMin, aMin, eta),
                StokesDrag::rotationalRelaxationTime(0.4*mMin*aMin*aMin, aMin, eta)
            )
        });
    }

    const std::pair<double, double> pairs[3] =
        {{aMin, aMin}, {aMin, aMax}, {aMax, aMax}};

    // Contact modes of a pair: inverse inertias (overdamped: none) and
    // inverse Stokes resistances (explicit drag: none)
    auto inverseInertia = [&](double ai, double aj)
    {
        const double mi = sphereMass(ai, rho);
        const double mj = sphereMass(aj, rho);
        return contactModes(ai, mi, 0.4*mi*ai*ai, aj, mj, 0.4*mj*aj*aj);
    };
    auto inverseResistance = [&](double ai, double aj)
    {
        return contactModes
        (
            ai, 6*pi*eta*ai, 8*pi*eta*ai*ai*ai,
            aj, 6*pi*eta*aj, 8*pi*eta*aj*aj*aj
        );
    };
    auto limit = [&](double k, double gamma, double invM, double invZeta)
    {
        return modeLimit
        (
            k, gamma,
            inertia ? 1/invM : 0,
            explicitHydrodynamics ? 0 : 1/invZeta
        );
    };

    auto addLimit = [&](const char* name, auto limitOfPair)
    {
        double dt = limitOfPair(pairs[0].first, pairs[0].second);
        for (const auto& ab : pairs)
        {
            dt = std::min(dt, limitOfPair(ab.first, ab.second));
        }
        limits_.push_back({name, dt});
    };
    auto springLimit = [&](double k, double ai, double aj)
    {
        return limit
        (
            k, 0, inverseInertia(ai, aj)[0], inverseResistance(ai, aj)[0]
        );
    };

    if (models.lubrication && explicitHydrodynamics)
    {
        addLimit("lubrication", [&](double ai, double aj)
        {
            return 2*pairRelaxationTime(models, ai, aj, rho);
        });
    }
    if (models.contact)
    {
        const FrictionalContact::Params& c = models.contact->params();
        addLimit("contact", [&](double ai, double aj)
        {
            if (explicitHydrodynamics)
            {
                const double tc = FrictionalContact::contactTimeScale
                (
                    c, sphereMass(ai, rho), ai, sphereMass(aj, rho), aj
                );
                return 2*tc/pi;
            }
            const std::array<double, 3> invM = inverseInertia(ai, aj);
            std::array<double, 3> invZeta = inverseResistance(ai, aj);
            if (models.lubrication)
            {
                // A pair in contact always carries lubrication at the
                // regularised gap (A.6); along n only X^A acts besides the
                // drag, F_i = X^A_ii (u_j - u_i), so the normal mode's
                // resistance is the relative Stokes resistance plus X^A_ii
                const PairGeometry touching =
                    PairGeometry::make(Vec3(ai + aj, 0, 0), ai, aj);
                const double XA =
                    models.lubrication->coefficients(touching).XA.ii;
                invZeta[0] = 1/(1/invZeta[0] + XA);
            }
            double dt = limit(c.kn, c.gammaN, invM[0], invZeta[0]);
            // Without friction (mu_C = 0) the tangential spring never
            // pulls, and without rolling stiffness or friction neither
            // does the rolling one
            if (c.muC > 0)
            {
                dt = std::min(dt, limit(c.kt, 0, invM[1], invZeta[1]));
            }
            if (c.kr > 0 && models.contact->muR() > 0)
            {
                dt = std::min(dt, limit(c.kr, 0, invM[2], invZeta[2]));
            }
            return dt;
        });
    }
    if (models.repulsion)
    {
        addLimit("repulsion", [&](double ai, double aj)
        {
            return springLimit(models.repulsion->maxStiffness(ai, aj), ai, aj);
        });
    }
    if (models.attraction)
    {
        addLimit("attraction", [&](double ai, double aj)
        {
            const double hMax = 0.1*std::min(ai, aj);
            return springLimit
            (
                sampledStiffness(*models.attraction, ai, aj, hMax), ai, aj
            );
        });
    }

    for (const TimeStepLimit& l : limits_)
    {
        if (!(l.value > 0))
        {
            throw std::invalid_argument
            (
                "TimeStepLimits: no stable step for the " + l.name
              + " forces; overdamped, an explicit dashpot must be weaker"
                " than the Stokes resistance of the pair"
            );
        }
    }
}


const TimeStepLimit& TimeStepLimits::binding() const
{
    static const TimeStepLimit none
        {"none", std::numeric_limits<double>::infinity()};
    if (limits_.empty())
    {
        return none;
    }
    return *std::min_element
    (
        limits_.begin(), limits_.end(),
        [](const TimeStepLimit& a, const TimeStepLimit& b)
        {
            return a.value < b.value;
        }
    );
}

} // namespace suspension
