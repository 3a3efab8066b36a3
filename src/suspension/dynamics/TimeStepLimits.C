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

    //- Resistance of a pair at surface gap h (12 dof: U_i, U_j, Omega_i,
    //  Omega_j, n = e_x): Stokes drag and torque (A.1), plus lubrication
    //  (A.2; at the regularised gap A.6 for h <= 0) when it is on and the
    //  pair is in its range
    Lubrication::PairMatrix pairResistance
    (
        const ForceModels& models,
        double ai,
        double aj,
        double h
    )
    {
        const double eta = models.drag().params().eta;
        Lubrication::PairMatrix R = Lubrication::PairMatrix::Zero();
        const PairGeometry g = PairGeometry::make(Vec3(ai + aj + h, 0, 0), ai, aj);
        models.forEach([&](const auto& m)
        {
            if constexpr (std::decay_t<decltype(m)>::hydrodynamic)
            {
                if (h < m.gap())
                {
                    R += Lubrication::resistanceMatrix(m.coefficients(g), g.n);
                }
            }
        });
        const double radius[2] = {ai, aj};
        for (int s = 0; s < 2; ++s)
        {
            const double a = radius[s];
            for (int d = 0; d < 3; ++d)
            {
                R(3*s + d, 3*s + d) += 6*pi*eta*a;
                R(6 + 3*s + d, 6 + 3*s + d) += 8*pi*eta*a*a*a;
            }
        }
        return R;
    }

    //- Inertia of the same 12 dof
    Eigen::Matrix<double, 12, 1> pairInertia(double ai, double aj, double rho)
    {
        Eigen::Matrix<double, 12, 1> M;
        const double radius[2] = {ai, aj};
        for (int s = 0; s < 2; ++s)
        {
            const double m = sphereMass(radius[s], rho);
            for (int d = 0; d < 3; ++d)
            {
                M(3*s + d) = m;
                M(6 + 3*s + d) = 0.4*m*radius[s]*radius[s];
            }
        }
        return M;
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
        const Lubrication::PairMatrix R = pairResistance(models, ai, aj, 0);
        // M^-1/2 R M^-1/2 is symmetric with the same eigenvalues
        const Eigen::Matrix<double, 12, 1> s =
            pairInertia(ai, aj, rho).cwiseInverse().cwiseSqrt();
        const Lubrication::PairMatrix A = s.asDiagonal()*R*s.asDiagonal();
        const double lambdaMax =
            Eigen::SelfAdjointEigenSolver<Lubrication::PairMatrix>
            (
                A, Eigen::EigenvaluesOnly
            ).eigenvalues().maxCoeff();
        return 1/lambdaMax;
    }

    //- Largest stable step of a spring k on a coordinate of inertia m
    //  with resistance zeta (implicit); see the header. zeta = 0: the
    //  explicit spring limit 2 sqrt(m/k).
    double modeLimit(double k, double m, double zeta)
    {
        return (zeta + std::sqrt(zeta*zeta + 4*k*m))/k;
    }

    //- Direction b of a contact mode of a touching pair in the 12 dof
    //  (n = e_x, t = e_y): the mode coordinate changes at b.v, so a spring
    //  k on it is the force -k (b.x) b. Normal: n.(u_j - u_i); tangential
    //  (4b, 5): t.u_t = t.(u_j - u_i) - (a_i omega_i + a_j omega_j).(n x t);
    //  rolling (B.1): t.u_r = a_ij (omega_i - omega_j).(t x n)
    Eigen::Matrix<double, 12, 1> modeDirection
    (
        TimeStepLimitBuilder::Mode mode,
        double ai,
        double aj
    )
    {
        Eigen::Matrix<double, 12, 1> b = Eigen::Matrix<double, 12, 1>::Zero();
        switch (mode)
        {
            case TimeStepLimitBuilder::Mode::normal:
                b(0) = -1;  b(3) = 1;
                break;
            case TimeStepLimitBuilder::Mode::tangential:
                b(1) = -1;  b(4) = 1;
                b(8) = -ai; b(11) = -aj;                // n x t = e_z
                break;
            case TimeStepLimitBuilder::Mode::rolling:
                b(8) = -harmonicRadius(ai, aj);         // t x n = -e_z
                b(11) = harmonicRadius(ai, aj);
                break;
        }
        return b;
    }

    //- b^T A^-1 b for a symmetric positive-definite A
    double quadraticInverse
    (
        const Lubrication::PairMatrix& A,
        const Eigen::Matrix<double, 12, 1>& b
    )
    {
        return b.dot(A.ldlt().solve(b));
    }

    //- Inverse effective inertia b^T M^-1 b and inverse effective
    //  resistance b^T R^-1 b of a mode b of a pair at gap h
    struct ModeInverses
    {
        double inertia;
        double resistance;
    };

    ModeInverses modeInverses
    (
        const ForceModels& models,
        double ai,
        double aj,
        double h,
        double rho,
        const Eigen::Matrix<double, 12, 1>& b
    )
    {
        return
        {
            b.cwiseAbs2().dot(pairInertia(ai, aj, rho).cwiseInverse()),
            quadraticInverse(pairResistance(models, ai, aj, h), b)
        };
    }

    //- The limits' view of the case (forces/PairModel.H)
    class Builder
    :
        public TimeStepLimitBuilder
    {
        const ForceModels& models_;
        const std::array<std::pair<double, double>, 3> pairs_;
        const double rho_;
        const bool explicit_;
        const bool implicitNormal_;
        const bool inertia_;
        const double maxGradU_;
        std::vector<TimeStepLimit>& limits_;

    public:

        Builder
        (
            const ForceModels& models,
            const std::array<std::pair<double, double>, 3>& pairs,
            double rho,
            bool explicitHydrodynamics,
            bool implicitNormalContact,
            bool inertia,
            double maxGradU,
            std::vector<TimeStepLimit>& limits
        )
        :
            models_(models),
            pairs_(pairs),
            rho_(rho),
            explicit_(explicitHydrodynamics),
            implicitNormal_(!explicitHydrodynamics && implicitNormalContact),
            inertia_(inertia),
            maxGradU_(maxGradU),
            limits_(limits)
        {}

        bool explicitHydrodynamics() const override { return explicit_; }
        bool implicitNormalContact() const override { return implicitNormal_; }
        double rho() const override { return rho_; }
        double maxVelocityGradient() const override { return maxGradU_; }

        //- No inertia when overdamped, no implicit resistance when the
        //  hydrodynamics is explicit
        double springLimit
        (
            double k,
            Mode mode,
            double ai,
            double aj,
            double h
        ) const override
        {
            const ModeInverses inv = modeInverses
            (
                models_, ai, aj, h, rho_, modeDirection(mode, ai, aj)
            );
            return modeLimit
            (
                k,
                inertia_ ? 1/inv.inertia : 0,
                explicit_ ? 0 : 1/inv.resistance
            );
        }

        //- At each gap the spring |dF/dh| on the normal mode against the
        //  resistance at that gap (with lubrication on, X^A grows towards
        //  contact as the force does)
        double centralForceLimit
        (
            const std::function<double(double)>& force,
            double ai,
            double aj,
            double hMax
        ) const override
        {
            const int samples = 2000;
            const double dh = hMax/(samples + 1);   // stay inside the cut-off
            double dt = std::numeric_limits<double>::infinity();
            double Fh = force(0);
            for (int s = 0; s < samples; ++s)
            {
                const double h = s*dh;
                const double Fnext = force(h + dh);
                const double k = std::abs(Fnext - Fh)/dh;
                Fh = Fnext;
                if (k > 0)
                {
                    dt = std::min(dt, springLimit(k, Mode::normal, ai, aj, h));
                }
            }
            return dt;
        }

        double pairRelaxationTime(double ai, double aj) const override
        {
            return suspension::pairRelaxationTime(models_, ai, aj, rho_);
        }

        void addOverPairs
        (
            const std::string& name,
            const std::function<double(double, double)>& limitOfPair
        ) override
        {
            double dt = std::numeric_limits<double>::infinity();
            for (const auto& ab : pairs_)
            {
                dt = std::min(dt, limitOfPair(ab.first, ab.second));
            }
            limits_.push_back({name, dt});
        }

        void add(const std::string& name, double value) override
        {
            limits_.push_back({name, value});
        }
    };
}
// End anonymous namespace


TimeStepLimits::TimeStepLimits
(
    const ForceModels& models,
    double aMin,
    double aMax,
    double rho,
    double safety,
    Integrator integrator,
    double maxVelocityGradient,
    bool implicitNormalContact
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

    Builder builder
    (
        models, {{{aMin, aMin}, {aMin, aMax}, {aMax, aMax}}}, rho,
        explicitHydrodynamics, implicitNormalContact, inertia,
        maxVelocityGradient, limits_
    );
    auto addLimits = [&](const auto& m) { m.addTimeStepLimits(builder); };
    models.forEachParticleModel(addLimits);
    models.forEach(addLimits);

    for (const TimeStepLimit& l : limits_)
    {
        if (!(l.value > 0))
        {
            throw std::invalid_argument
            (
                "TimeStepLimits: no stable step for the " + l.name + " forces"
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
