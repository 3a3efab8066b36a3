#include "dynamics/ImplicitEuler.H"
#include "dynamics/MoveAndWrap.H"
#include "dynamics/SimulationError.H"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace suspension
{

ImplicitEuler::ImplicitEuler
(
    const ForceModels& models,
    bool inertia,
    const ConjugateGradient::Params& solver,
    bool implicitNormalContact,
    bool rateChanges,
    const Domain* domain
)
:
    inertia_(inertia),
    resistance_(models, implicitNormalContact, rateChanges),
    solver_(solver, domain),
    iterations_(0),
    stepShearStress_(0),
    domain_(domain)
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
    for (std::size_t h = 0; h < S.pairs.size(); ++h)
    {
        summary.stresslet[resistance_.pairContributions()[h]] = S.pairs[h];
    }
}


const std::vector<FlowSample>& ImplicitEuler::shiftedFlow
(
    const Particles& p,
    const std::vector<FlowSample>& sampled,
    double shift
)
{
    if (shift == 0)
    {
        return sampled;
    }
    if (!resistance_.rateChanges())
    {
        throw std::logic_error
        (
            "ImplicitEuler: a step at another shear rate than the samples'"
            " needs an integrator constructed with rateChanges"
        );
    }
    const std::size_t N = p.size();
    shifted_ = sampled;
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        shifted_[i].U.x() += shift*p.x[i].y();
        shifted_[i].gradU(1, 0) += shift;
    }
    return shifted_;
}


void ImplicitEuler::rightHandSide
(
    const Particles& p,
    const std::vector<FlowSample>& ambient,
    double shift,
    double dt
)
{
    // V'^n and the right-hand side, relative to the flow at x^n, and the
    // predictor of the warm start, d = dt (du/dt, domega/dt): the last
    // step's rate of change carried over this step
    const std::size_t N = p.size();
    const double invDt = inertia_ ? 1/dt : 0;
    const Eigen::VectorXd& Famb = resistance_.ambientForces();
    const Eigen::VectorXd& Fs = resistance_.shearForces();
    v_.resize(6*N);
    b_.resize(6*N);
    d_.resize(6*N);
    #pragma omp parallel for schedule(static) if(threaded(N))
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
    resistance_.zeroGhostRows(b_);
}


void ImplicitEuler::setVelocities
(
    Particles& p,
    const std::vector<FlowSample>& ambient,
    double dt
) const
{
    #pragma omp parallel for schedule(static) if(threaded(p.size()))
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Vec3 u = ambient[i].U + v_.segment<3>(6*i);
        const Vec3 w = ambient[i].Omega() + v_.segment<3>(6*i + 3);
        p.dudt[i] = (u - p.u[i])/dt;
        p.domegadt[i] = (w - p.omega[i])/dt;
        p.u[i] = u;
        p.omega[i] = w;
    }
}


bool ImplicitEuler::solve
(
    Particles& p,
    const std::vector<FlowSample>& sampled,
    double shift,
    double dt,
    const StressControl* stress
)
{
    resistance_.setStep(p, dt, inertia_, domain_);
    const std::vector<FlowSample>& ambient = shiftedFlow(p, sampled, shift);
    rightHandSide(p, ambient, shift, dt);

    // Warm start: V'^n moved along d as far as it lowers the error
    // (ConjugateGradient.H)
    statistics_ = solver_.solve(resistance_, b_, v_, &d_);
    iterations_ += statistics_.iterations;
    if (!statistics_.converged)
    {
        return false;
    }
    if (stress)
    {
        double local[2] =
        {
            shift*resistance_.stokesShearStresslet()(0, 1),
            resistance_.lubricationStresslet(v_, 1, shift)(0, 1)
        };
        sumOverProcesses(domain_, local, 2);
        stepShearStress_ =
            stress->eta0*(stress->rate + shift)
          + (stress->fixedXY + stress->stokesXY + local[0] + local[1])/stress->volume;
    }
    setVelocities(p, ambient, dt);
    return true;
}


bool ImplicitEuler::solveForStress
(
    Particles& p,
    const std::vector<FlowSample>& sampled,
    const StressControl& control,
    double dt,
    double& shift
)
{
    const std::size_t N = p.size();
    resistance_.setStep(p, dt, inertia_, domain_);

    // The right-hand side at the samples' rate, b0, and its change per
    // unit of rate, b1 = F_s + the contacts' ambient terms of a unit
    // shear (the velocities relative to the flow do not change with the
    // rate: Simulation carries them)
    rightHandSide(p, sampled, 0, dt);
    b1_ = resistance_.shearForces();
    Eigen::VectorXd c0 = Eigen::VectorXd::Zero(6*N);
    resistance_.contactRightHandSide(v_, sampled, 0, dt, c0);
    resistance_.contactRightHandSide(v_, shiftedFlow(p, sampled, 1), 1, dt, b1_);
    b1_ -= c0;
    resistance_.zeroGhostRows(b1_);

    // V'(s) = V'0 + s V'1: two solves
    statistics_ = solver_.solve(resistance_, b_, v_, &d_);
    iterations_ += statistics_.iterations;
    if (!statistics_.converged)
    {
        return false;
    }
    // The shear stress of the step at the samples' rate, sigma0 (eq. 8)
    const double V = control.volume;
    const double sigma0 =
        control.eta0*control.rate
      + (control.fixedXY + control.stokesXY
       + total(resistance_.lubricationStresslet(v_, 1, 0)(0, 1)))/V;

    // V'1 from zero moved along V'0/gammaDot_s to the energy minimum on
    // that line (where the stress is the rate's, V' is nearly proportional
    // to it): a start from the state, as a restart needs. Its error enters
    // V' times the shift s, which is small where the rate changes little
    // in a step: the tolerance is that of V' over the shift estimated with
    // the hydrodynamic stress taken proportional to the rate (at most
    // 1e-3), so that s V'1 meets the tolerance of V'
    v1_.setZero(b1_.size());
    d1_ = v_;
    double tolerance = solver_.params().tolerance;
    if (control.rate != 0)
    {
        d1_ /= control.rate;
        const double slope = std::abs((sigma0 - control.fixedXY/V)/control.rate);
        const double estimate = std::abs((control.target - sigma0)/slope);
        tolerance = std::min
        (
            1e-3,
            tolerance*std::abs(control.rate)/std::max(estimate, 1e-300)
        );
        tolerance = std::max(tolerance, solver_.params().tolerance);
    }
    const ConjugateGradient::Result second = solver_.solve
    (
        resistance_, b1_, v1_, control.rate != 0 ? &d1_ : nullptr, tolerance
    );
    iterations_ += second.iterations;
    statistics_.iterations += second.iterations;
    statistics_.residual = std::max(statistics_.residual, second.residual);
    if (!second.converged)
    {
        statistics_.converged = false;
        statistics_.outcome = second.outcome;
        return false;
    }

    // Its change per unit of rate, sigma1, and the shift that makes the
    // stress of the step the target
    const double sigma1 =
        control.eta0
      + total
        (
            resistance_.stokesShearStresslet()(0, 1)
          + resistance_.lubricationStresslet(v1_, 0, 1)(0, 1)
        )/V;
    shift = (control.target - sigma0)/sigma1;
    if (!(sigma1 > 0) || !std::isfinite(shift))
    {
        std::ostringstream msg;
        msg << "stress control: the shear stress of the step does not grow"
               " with the shear rate (d sigma/d gammaDot = " << sigma1
            << ", sigma at the last rate " << sigma0 << ", target "
            << control.target << ")";
        throw SimulationError(msg.str());
    }
    stepShearStress_ = sigma0 + shift*sigma1;

    v_ += shift*v1_;
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        p.u[i].x() += shift*p.x[i].y();
        p.omega[i].z() -= 0.5*shift;
    }
    setVelocities(p, shiftedFlow(p, sampled, shift), dt);
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
