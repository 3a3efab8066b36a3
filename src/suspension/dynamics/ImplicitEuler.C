#include "dynamics/ImplicitEuler.H"
#include "dynamics/MoveAndWrap.H"

#include <stdexcept>

namespace suspension
{

ImplicitEuler::ImplicitEuler
(
    const ForceModels& models,
    bool inertia,
    const ConjugateGradient::Params& solver,
    bool implicitNormalContact,
    bool rateChanges
)
:
    inertia_(inertia),
    resistance_
    (
        models.drag(), models.get<Lubrication>(), implicitNormalContact,
        rateChanges
    ),
    solver_(solver),
    iterations_(0)
{}


void ImplicitEuler::evaluate
(
    const Particles& p,
    const LeesEdwardsBox& box,
    const std::vector<FlowSample>& ambient,
    const PairList& pairs,
    const std::vector<LinearisedContact>& contacts,
    ForceSummary& summary
)
{
    const HydrodynamicResistance::Stresslets S =
        resistance_.assemble(p, box, ambient, pairs, contacts);
    summary.stresslet[contributionIndex("stokes")] = S.stokes;
    summary.stresslet[contributionIndex(Lubrication::contribution)] = S.lubrication;
}


bool ImplicitEuler::solve
(
    Particles& p,
    const std::vector<FlowSample>& sampled,
    double shift,
    double dt
)
{
    const std::size_t N = p.size();
    const bool parallel = threaded(N);
    const double invDt = inertia_ ? 1/dt : 0;
    resistance_.setStep(p, dt, inertia_);

    // The flow at the step's rate: the samples shifted by a simple shear
    // (U_inf is affine in the rate)
    if (shift != 0 && !resistance_.rateChanges())
    {
        throw std::logic_error
        (
            "ImplicitEuler: a step at another shear rate than the samples'"
            " needs an integrator constructed with rateChanges"
        );
    }
    if (shift != 0)
    {
        shifted_ = sampled;
        #pragma omp parallel for schedule(static) if(parallel)
        for (std::size_t i = 0; i < N; ++i)
        {
            shifted_[i].U.x() += shift*p.x[i].y();
            shifted_[i].gradU(1, 0) += shift;
        }
    }
    const std::vector<FlowSample>& ambient = shift != 0 ? shifted_ : sampled;

    // V'^n and the right-hand side, relative to the flow at x^n, and the
    // predictor of the warm start, d = dt (du/dt, domega/dt): the last
    // step's rate of change carried over this step
    const Eigen::VectorXd& Famb = resistance_.ambientForces();
    const Eigen::VectorXd& Fs = resistance_.shearForces();
    v_.resize(6*N);
    b_.resize(6*N);
    d_.resize(6*N);
    #pragma omp parallel for schedule(static) if(parallel)
    for (std::size_t i = 0; i < N; ++i)
    {
        const Vec3 u = p.u[i] - ambient[i].U;
        const Vec3 w = p.omega[i] - ambient[i].Omega();
        v_.segment<3>(6*i) = u;
        v_.segment<3>(6*i + 3) = w;
        b_.segment<3>(6*i) = Famb.segment<3>(6*i) + p.F[i] + invDt*p.m[i]*u;
        b_.segment<3>(6*i + 3) = Famb.segment<3>(6*i + 3) + p.T[i] + invDt*p.I[i]*w;
        if (shift != 0)
        {
            b_.segment<6>(6*i) += shift*Fs.segment<6>(6*i);
        }
        d_.segment<3>(6*i) = dt*p.dudt[i];
        d_.segment<3>(6*i + 3) = dt*p.domegadt[i];
    }

    // The springs' load by the ambient motion and the dashpot's of V'^n
    resistance_.contactRightHandSide(v_, ambient, shift, dt, b_);

    // Warm start: V'^n moved along d as far as it lowers the error
    // (ConjugateGradient.H)
    statistics_ = solver_.solve(resistance_, b_, v_, &d_);
    iterations_ += statistics_.iterations;
    if (!statistics_.converged)
    {
        return false;
    }

    #pragma omp parallel for schedule(static) if(parallel)
    for (std::size_t i = 0; i < N; ++i)
    {
        const Vec3 u = ambient[i].U + v_.segment<3>(6*i);
        const Vec3 w = ambient[i].Omega() + v_.segment<3>(6*i + 3);
        p.dudt[i] = (u - p.u[i])/dt;
        p.domegadt[i] = (w - p.omega[i])/dt;
        p.u[i] = u;
        p.omega[i] = w;
    }
    return true;
}


std::size_t ImplicitEuler::move(Particles& p, const LeesEdwardsBox& box, double dt)
{
    return moveAndWrap(p, box, [&p, dt](std::size_t i)
    {
        p.x[i] += dt*p.u[i];
    });
}


std::size_t ImplicitEuler::nonFiniteParticle() const
{
    const Eigen::VectorXd& y =
        statistics_.outcome == ConjugateGradient::Outcome::nonFiniteRightHandSide
      ? b_ : v_;
    const std::size_t N = y.size()/6;
    for (std::size_t i = 0; i < N; ++i)
    {
        if (!y.segment<6>(6*i).allFinite())
        {
            return i;
        }
    }
    return N;
}

} // namespace suspension
