#include "dynamics/Simulation.H"
#include "dynamics/VelocityVerlet.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace suspension
{

namespace
{
    TimeStepLimits makeLimits
    (
        const ForceModels& models,
        const Particles& p,
        const Simulation::Params& params
    )
    {
        if (p.size() == 0)
        {
            throw std::invalid_argument("Simulation: no particles");
        }
        const auto [aMin, aMax] = std::minmax_element(p.a.begin(), p.a.end());
        return TimeStepLimits(models, *aMin, *aMax, params.rho, params.safety);
    }
}


Simulation::Simulation
(
    Particles particles,
    const LeesEdwardsBox& box,
    const AmbientFlow& flow,
    ForceModels models,
    const Params& params
)
:
    params_(params),
    particles_(std::move(particles)),
    box_(box),
    flow_(flow),
    forces_(std::move(models)),
    search_
    ({
        forces_.models().interactionGap(particles_.maxRadius(), particles_.maxRadius()),
        params.skin,
        params.stencil
    }),
    limits_(makeLimits(forces_.models(), particles_, params)),
    dtMax_(params.deltaT > 0 ? params.deltaT : limits_.deltaT()),
    time_(0),
    steps_(0)
{
    if (!(params.skin >= 0) || !(params.maxOverlap > 0))
    {
        throw std::invalid_argument
        (
            "Simulation: need skin >= 0 and maxOverlap > 0; got skin "
          + std::to_string(params.skin) + ", maxOverlap "
          + std::to_string(params.maxOverlap)
        );
    }
}


void Simulation::evaluateForces(double dt, std::vector<Mat3>* particleStresslet)
{
    summary_ = forces_.compute
    (
        particles_, box_, flow_, pairs_, dt, particleStresslet
    );
}


void Simulation::start(double t, bool forcesGiven)
{
    time_ = t;
    box_.setTime(t);
    search_.rebuild(particles_, box_, pairs_);
    if (!forcesGiven)
    {
        evaluateForces(0, nullptr);
    }
    else
    {
        // Summary (stress, contacts) of the given state, history unchanged
        std::vector<Vec3> F = particles_.F;
        std::vector<Vec3> T = particles_.T;
        PairList frozen = pairs_;
        evaluateForces(0, nullptr);
        pairs_ = std::move(frozen);
        particles_.F = std::move(F);
        particles_.T = std::move(T);
    }
    check();
}


void Simulation::step(double dt)
{
    // Path of each particle relative to the flow, for the list's skin
    const std::vector<FlowSample>& ambient = forces_.ambient();
    Uinf_.resize(particles_.size());
    for (std::size_t i = 0; i < Uinf_.size(); ++i)
    {
        Uinf_[i] = ambient[i].U;
    }
    search_.accumulate(particles_, Uinf_, dt);

    box_.setTime(time_ + dt);
    VelocityVerlet::predict(particles_, box_, dt);
    search_.update(particles_, box_, pairs_, flow_.maxVelocityGradient());
    evaluateForces(dt, nullptr);
    VelocityVerlet::correct(particles_, dt);

    time_ += dt;
    ++steps_;
    check();
}


void Simulation::advance(double interval)
{
    if (!(interval > 0))
    {
        return;
    }
    const auto n = static_cast<std::uint64_t>(std::ceil(interval/dtMax_*(1 - 1e-12)));
    const double dt = interval/static_cast<double>(n);
    const double t0 = time_;
    for (std::uint64_t k = 1; k <= n; ++k)
    {
        step(dt);
        time_ = t0 + k*dt;      // no round-off drift over many steps
    }
}


void Simulation::particleStresslets(std::vector<Mat3>& S)
{
    std::vector<Vec3> F = particles_.F;
    std::vector<Vec3> T = particles_.T;
    PairList frozen = pairs_;
    const ForceSummary summary = summary_;
    forces_.compute(particles_, box_, flow_, pairs_, 0, &S);
    pairs_ = std::move(frozen);
    particles_.F = std::move(F);
    particles_.T = std::move(T);
    summary_ = summary;
}


Rheology Simulation::rheology() const
{
    return Rheology
    (
        summary_, box_.volume(), forces_.models().drag.params().eta,
        flow_.shearRate()
    );
}


void Simulation::check() const
{
    const Particles& p = particles_;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (!p.x[i].allFinite() || !p.F[i].allFinite() || !p.T[i].allFinite()
         || !p.u[i].allFinite() || !p.omega[i].allFinite())
        {
            std::ostringstream msg;
            msg << "non-finite state of particle " << p.id[i]
                << " at step " << steps_ << " (t = " << time_ << "): x = "
                << p.x[i].transpose() << ", u = " << p.u[i].transpose()
                << ", F = " << p.F[i].transpose() << ", T = "
                << p.T[i].transpose();
            throw SimulationError(msg.str());
        }
    }
    if (summary_.maxOverlap > params_.maxOverlap)
    {
        std::ostringstream msg;
        msg << "runaway overlap " << summary_.maxOverlap
            << " of the smaller radius (limit " << params_.maxOverlap
            << ") between particles " << summary_.maxOverlapPair[0] << " and "
            << summary_.maxOverlapPair[1] << " at step " << steps_
            << " (t = " << time_ << "); the contact stiffness is too low "
               "for the forces, or the time step too large";
        throw SimulationError(msg.str());
    }
}

} // namespace suspension
