#include "dynamics/Simulation.H"
#include "dynamics/VelocityVerlet.H"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace suspension
{

namespace
{
    //- The smallest and largest radius of all processes; throws without
    //  particles
    std::pair<double, double> radiusRange
    (
        const Particles& p,
        const std::unique_ptr<Domain>& domain
    )
    {
        double e[2] =
        {
            -std::numeric_limits<double>::infinity(),
            -std::numeric_limits<double>::infinity()
        };
        for (const double a : p.a)
        {
            e[0] = std::max(e[0], -a);
            e[1] = std::max(e[1], a);
        }
        if (domain)
        {
            domain->comm().max(e, 2);
        }
        if (!(e[1] > 0))
        {
            throw std::invalid_argument("Simulation: no particles");
        }
        return {-e[0], e[1]};
    }

    TimeStepLimits makeLimits
    (
        const ForceModels& models,
        const std::pair<double, double>& radii,
        const AmbientFlow& flow,
        const Simulation::Params& params,
        bool implicitNormalContact,
        double maxRate
    )
    {
        return TimeStepLimits
        (
            models, radii.first, radii.second, params.rho, params.safety,
            params.integrator, flow.maxVelocityGradient(maxRate),
            implicitNormalContact
        );
    }

    std::unique_ptr<Domain> makeDomain
    (
        const Decomposition& d,
        const LeesEdwardsBox& box
    )
    {
        if (!d.comm)
        {
            return nullptr;
        }
        return std::make_unique<Domain>(*d.comm, d.layout, box.L());
    }

    //- The implicit integrators take the normal contact springs
    //  implicitly when asked to or, unset, when their explicit limit
    //  ("contact") is below half of every other limit: implicitly they
    //  cost accuracy at equal step (TimeStepLimits.H)
    bool implicitNormalContact
    (
        const ForceModels& models,
        const std::pair<double, double>& radii,
        const AmbientFlow& flow,
        const Simulation::Params& params
    )
    {
        if (params.integrator == Integrator::velocityVerlet)
        {
            return false;
        }
        if (params.implicitNormalContact)
        {
            return *params.implicitNormalContact;
        }
        double contact = std::numeric_limits<double>::infinity();
        double others = contact;
        const TimeStepLimits explicitNormal =
            makeLimits(models, radii, flow, params, false, flow.maxShearRate());
        for (const TimeStepLimit& l : explicitNormal.all())
        {
            double& v = l.name == "contact" ? contact : others;
            v = std::min(v, l.value);
        }
        return contact < 0.5*others;
    }

    //- A decomposed run's completion of the samples of a flow known on
    //  each process's part: the owned particles not known here from their
    //  ghosts (Domain::fillFromGhosts), then the ghosts from their owners
    //  (Domain::refresh), of the FlowSample entries as doubles; none in a
    //  serial run
    ForceField::GhostSamples ghostSamples(const Domain* domain)
    {
        static_assert
        (
            sizeof(FlowSample) == 24*sizeof(double),
            "FlowSample is 24 doubles, exchanged as such"
        );
        if (!domain)
        {
            return nullptr;
        }
        return [domain]
        (
            std::vector<FlowSample>& samples,
            std::vector<unsigned char>& known
        )
        {
            double* v = reinterpret_cast<double*>(samples.data());
            const std::size_t width = sizeof(FlowSample)/sizeof(double);
            domain->fillFromGhosts(v, width, known);
            domain->refresh(v, width);
        };
    }
}


Simulation::Simulation
(
    Particles particles,
    const LeesEdwardsBox& box,
    const AmbientFlow& flow,
    ForceModels models,
    const Params& params,
    const Decomposition& decomposition
)
:
    params_(params),
    particles_(std::move(particles)),
    box_(box),
    flow_(flow),
    domain_(makeDomain(decomposition, box)),
    forces_
    (
        std::move(models),
        domain_ ? domain_->distinctRadii(particles_.a) : particles_.a,
        ghostSamples(domain_.get()),
        params.pairPasses
    ),
    radii_(radiusRange(particles_, domain_)),
    search_
    ({
        forces_.nearGap(),
        params.skin,
        params.stencil,
        forces_.farGap()
    }),
    implicitNormalContact_
    (
        suspension::implicitNormalContact(forces_.models(), radii_, flow, params)
    ),
    limits_
    (
        makeLimits
        (
            forces_.models(), radii_, flow, params, implicitNormalContact_,
            flow.maxShearRate()
        )
    ),
    dtMax_(params.deltaT > 0 ? params.deltaT : limits_.deltaT()),
    stepLimitCounts_
    {
        {params.deltaT > 0 ? "deltaT" : limits_.binding().name, 0},
        {"maxDisplacement", 0}
    },
    time_(0),
    strain_(0),
    steps_(0)
{
    if
    (
        !(params.skin >= 0) || !(params.maxOverlap > 0)
     || !(params.maxDisplacement >= 0)
    )
    {
        throw std::invalid_argument
        (
            "Simulation: need skin >= 0, maxOverlap > 0 and maxDisplacement"
            " >= 0; got skin " + std::to_string(params.skin)
          + ", maxOverlap " + std::to_string(params.maxOverlap)
          + ", maxDisplacement " + std::to_string(params.maxDisplacement)
        );
    }
    if (!std::isfinite(dtMax_) && params.maxDisplacement == 0)
    {
        throw std::invalid_argument
        (
            "Simulation: no force limits the step of the implicit integrator;"
            " set deltaT or maxDisplacement"
        );
    }
    if (flow.stressControlled() && params.integrator == Integrator::velocityVerlet)
    {
        throw std::invalid_argument
        (
            "Simulation: stress control needs an implicit integrator"
            " (implicitEuler or overdamped), whose velocities and stress are"
            " affine in the rate: velocityVerlet has no controller"
        );
    }
    if (params.adaptiveThreads && threaded(particles_.size()))
    {
        governor_.emplace(omp_get_max_threads());
    }
    if (params.integrator != Integrator::velocityVerlet)
    {
        makeImplicit
        (
            implicitNormalContact_,
            flow.shearRateChanges() || flow.stressControlled()
        );
    }
}


void Simulation::makeImplicit(bool normal, bool rateChanges)
{
    implicit_.emplace
    (
        forces_.models(),
        params_.integrator == Integrator::implicitEuler,
        params_.solver,
        normal,
        rateChanges,
        domain_.get()
    );
}


void Simulation::evaluateForces(double dt)
{
    if (implicit_)
    {
        summary_ = forces_.advance
        (
            particles_, box_, flow_, pairs_, search_.far(), dt,
            ForceField::Forces::nonHydrodynamic, &contacts_
        );
        ScopedTime timer(times_.hydrodynamics);
        implicit_->evaluate
        (
            particles_, box_, forces_.ambient(), pairs_, contacts_, summary_
        );
    }
    else
    {
        summary_ = forces_.advance(particles_, box_, flow_, pairs_, search_.far(), dt);
    }
    reduce(summary_);
}


void Simulation::reduce(ForceSummary& summary) const
{
    if (!domain_)
    {
        return;
    }
    const Communicator& comm = domain_->comm();
    std::vector<double> sums;
    for (const Mat3& S : summary.stresslet)
    {
        sums.insert(sums.end(), S.data(), S.data() + 9);
    }
    sums.push_back(double(summary.nContacts));
    comm.sum(sums.data(), sums.size());
    for (std::size_t c = 0; c < summary.stresslet.size(); ++c)
    {
        summary.stresslet[c] = Eigen::Map<const Mat3>(sums.data() + 9*c);
    }
    summary.nContacts = static_cast<std::size_t>(sums.back());

    // The largest overlap, and its pair as the processes that see it name it
    double largest = summary.maxOverlap;
    comm.max(&largest, 1);
    double pair[2] = {-1, -1};
    if (summary.maxOverlap == largest)
    {
        pair[0] = double(summary.maxOverlapPair[0]);
        pair[1] = double(summary.maxOverlapPair[1]);
    }
    comm.max(pair, 2);
    summary.maxOverlap = largest;
    summary.maxOverlapPair[0] = static_cast<std::int64_t>(pair[0]);
    summary.maxOverlapPair[1] = static_cast<std::int64_t>(pair[1]);
}


bool Simulation::anyProcess(bool local) const
{
    return domain_ ? domain_->comm().any(local) : local;
}


void Simulation::setContacts(std::vector<KeyedContact> contacts)
{
    std::sort(contacts.begin(), contacts.end());
    for (std::size_t k = 0; k < contacts.size(); ++k)
    {
        const KeyedContact& c = contacts[k];
        if (c.lo >= c.hi || (k > 0 && !(contacts[k - 1] < c)))
        {
            std::ostringstream msg;
            msg << "Simulation: the contact (" << c.lo << ", " << c.hi << ") "
                << (c.lo >= c.hi ? "is not keyed lower id first" : "is given twice");
            throw std::invalid_argument(msg.str());
        }
    }
    given_ = std::move(contacts);
}


void Simulation::rebuildLists()
{
    if (!domain_ && given_.empty())
    {
        search_.rebuild(particles_, box_, pairs_);
        return;
    }
    std::vector<KeyedContact> contacts =
        given_.empty() ? NeighbourSearch::contacts(particles_, pairs_) : std::move(given_);
    given_.clear();
    if (domain_)
    {
        domain_->distribute(particles_, contacts, search_.searchRange(radii_.second));
    }
    search_.rebuild(particles_, box_, pairs_, contacts, radii_.second);
    if (domain_)
    {
        domain_->index(particles_);
    }
}


void Simulation::updateLists()
{
    if (!domain_)
    {
        search_.update(particles_, box_, pairs_);
        return;
    }
    // Every process rebuilds when one needs to; else the ghosts follow
    if (anyProcess(!search_.built(particles_, box_, pairs_) || search_.needsRebuild()))
    {
        rebuildLists();
    }
    else
    {
        domain_->refresh(particles_);
    }
}


void Simulation::start
(
    double t,
    bool forcesGiven,
    const std::optional<Shear>& shear
)
{
    time_ = t;
    if (shear)
    {
        strain_ = shear->strain;
    }
    box_.setShearRate(shear ? shear->rate : flow_.shearRate(t));
    box_.setStrain(strain_);

    // A state of another rate than a constant programme's (a restart after
    // the rate was changed): its first step changes the rate, which the
    // implicit integrator must be able to do
    if
    (
        implicit_ && !implicit_->resistance().rateChanges()
     && box_.shearRate() != flow_.shearRate(t)
    )
    {
        makeImplicit(implicitNormalContact_, true);
    }
    for (std::size_t i = 0; i < particles_.size(); ++i)
    {
        if (!box_.contains(particles_.x[i]))
        {
            std::ostringstream msg;
            msg << "Simulation: particle " << particles_.id[i] << " at "
                << particles_.x[i].transpose() << " is outside the box [0, L),"
                << " L = " << box_.L().transpose()
                << " (positions are wrapped into it: LeesEdwardsBox::wrap)";
            throw std::invalid_argument(msg.str());
        }
    }
    rebuildLists();
    if (!forcesGiven)
    {
        evaluateForces(0);
    }
    else if (implicit_)
    {
        // Summary (stress, contacts) and linearised contacts of the given
        // state; F and T as given
        ForceField::Output out;
        out.contacts = &contacts_;
        summary_ = forces_.evaluate
        (
            particles_, box_, flow_, pairs_, search_.far(), out,
            ForceField::Forces::nonHydrodynamic
        );
        ScopedTime timer(times_.hydrodynamics);
        implicit_->evaluate
        (
            particles_, box_, forces_.ambient(), pairs_, contacts_, summary_
        );
        reduce(summary_);
    }
    else
    {
        summary_ = forces_.evaluate
        (
            particles_, box_, flow_, pairs_, search_.far(), ForceField::Output()
        );
        reduce(summary_);
    }
    check();
}


void Simulation::redistribute()
{
    if (domain_)
    {
        const ForceSummary stepSummary = summary_;
        start(time_, true, shear());
        summary_ = stepSummary;
    }
}


void Simulation::flowChanged()
{
    // Chosen again as for a run started in this flow
    const bool normal =
        suspension::implicitNormalContact(forces_.models(), radii_, flow_, params_);
    if (implicit_ && normal != implicitNormalContact_)
    {
        makeImplicit(normal, flow_.shearRateChanges() || flow_.stressControlled());
    }
    implicitNormalContact_ = normal;
    limits_ = makeLimits
    (
        forces_.models(), radii_, flow_, params_, normal, flow_.maxShearRate()
    );
    dtMax_ = params_.deltaT > 0 ? params_.deltaT : limits_.deltaT();
    if (!(params_.deltaT > 0))
    {
        stepLimitCounts_[0].name = limits_.binding().name;
    }
    start(time_, true, shear());
}


namespace
{
    //- The slots of a near list and their contact history, what a rebuild
    //  carries over (NeighbourSearch::rebuild); not the transposed index
    void copySlots(const PairList& from, PairList& to)
    {
        to.offset = from.offset;
        to.j = from.j;
        to.contactOf = from.contactOf;
        to.contacts = from.contacts;
    }
}


void Simulation::checkpoint(Checkpoint& c) const
{
    c.particles = particles_;
    copySlots(pairs_, c.pairs);
    c.time = time_;
    c.shear = shear();
    c.steps = steps_;
}


void Simulation::restore(const Checkpoint& c)
{
    particles_ = c.particles;
    copySlots(c.pairs, pairs_);
    steps_ = c.steps;
    start(c.time, true, c.shear);
}


void Simulation::step(double dt)
{
    std::string failure;
    try
    {
        failure = takeStep(dt);
    }
    catch (const std::exception& err)
    {
        // Anything but a SimulationError may be this process's alone in a
        // decomposed run: it propagates as it is (Description)
        if (domain_ && !dynamic_cast<const SimulationError*>(&err))
        {
            throw;
        }
        failure = stepName(dt) + ": " + err.what();
    }
    if (!failure.empty())
    {
        throw SimulationError(failure);
    }
    time_ += dt;
    ++steps_;
    check();
}


std::string Simulation::takeStep(double dt)
{
    // The step's mean rate (the programme's, or under stress control the
    // one that gives the target stress) and the velocities u^(n+1) of an
    // implicit step; the ambient samples are those of the last evaluation,
    // at the rate of the last step
    const std::vector<FlowSample>& ambient = forces_.ambient();
    const double sampledRate = box_.shearRate();
    double rate;
    auto stressControl = [&](double target)
    {
        const std::vector<bool>& hydrodynamic = hydrodynamicContributions();
        double fixed = 0;
        for (std::size_t c = 0; c < hydrodynamic.size(); ++c)
        {
            fixed += hydrodynamic[c] ? 0 : summary_.stresslet[c](0, 1);
        }
        return ImplicitEuler::StressControl
        {
            target, forces_.models().drag().params().eta, box_.volume(),
            sampledRate, fixed,
            summary_.stresslet[contributionIndex("stokes")](0, 1)
        };
    };
    if (flow_.stressControlled())
    {
        ScopedTime timer(times_.hydrodynamics);
        const ImplicitEuler::StressControl control =
            stressControl(flow_.shearStress(time_ + dt));
        double shift;
        if (!implicit_->solveForStress(particles_, ambient, control, dt, shift))
        {
            return solveFailure(dt);
        }
        rate = sampledRate + shift;
        box_.setShearRate(rate);
    }
    else
    {
        rate = flow_.meanShearRate(time_, time_ + dt);
        box_.setShearRate(rate);
        carry(rate - sampledRate);
        if (implicit_)
        {
            // The step's stress as stress control would find it, where the
            // resistance keeps what it needs (a rate that changes)
            ScopedTime timer(times_.hydrodynamics);
            const bool keeps = implicit_->resistance().rateChanges();
            const ImplicitEuler::StressControl stress =
                keeps ? stressControl(0) : ImplicitEuler::StressControl{};
            if
            (
                !implicit_->solve
                (
                    particles_, ambient, rate - sampledRate, dt,
                    keeps ? &stress : nullptr
                )
            )
            {
                return solveFailure(dt);
            }
        }
    }
    const double maxRate = flow_.stressControlled()
      ? std::max(std::abs(rate), std::abs(sampledRate))
      : std::max
        ({
            std::abs(rate), std::abs(flow_.shearRate(time_)),
            std::abs(flow_.shearRate(time_ + dt))
        });

    // Path of each particle relative to the flow at the step's rate, for
    // the list's skin (u^n carried with the rate, or u^(n+1) at x^n)
    const double shift = rate - sampledRate;
    Uinf_.resize(particles_.size());
    for (std::size_t i = 0; i < Uinf_.size(); ++i)
    {
        Uinf_[i] = ambient[i].U;
        Uinf_[i].x() += shift*particles_.x[i].y();
    }
    {
        ScopedTime timer(times_.search);
        search_.accumulate
        (
            particles_, Uinf_, dt, flow_.maxVelocityGradient(maxRate)
        );
    }

    strain_ += rate*dt;
    box_.setStrain(strain_);
    std::size_t unwrapped;
    {
        ScopedTime timer(times_.integration);
        unwrapped = implicit_
          ? ImplicitEuler::move(particles_, box_, dt)
          : VelocityVerlet::predict(particles_, box_, dt);
    }
    if (anyProcess(unwrapped < particles_.size()))
    {
        return unwrapped < particles_.size()
          ? moveFailure(unwrapped, dt)
          : "a particle of another process cannot be wrapped into the box at "
          + stepName(dt);
    }
    {
        ScopedTime timer(times_.search);
        updateLists();
    }
    evaluateForces(dt);
    if (!implicit_)
    {
        ScopedTime timer(times_.integration);
        VelocityVerlet::correct(particles_, dt);
    }
    return {};
}


void Simulation::carry(double shift)
{
    // A change of rate changes the ambient flow by shift (y, 0, 0) and its
    // rotation by shift (0, 0, -1/2): the particles keep their velocities
    // relative to it (Description), so that the velocity of a particle
    // wrapped earlier stays that of its image at the new rate
    if (shift == 0)
    {
        return;
    }
    Particles& p = particles_;
    #pragma omp parallel for schedule(static) if(threaded(p.size()))
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        p.u[i].x() += shift*p.x[i].y();
        p.omega[i].z() -= 0.5*shift;
    }
}


void Simulation::followStressControlledRate()
{
    // The lubricationGap limit follows |gammaDot|: twice the rate now, or
    // the flow's bound while the rate is not yet known (0 at a first
    // start); a function of the state, as a restart needs
    if (!flow_.stressControlled() || params_.deltaT > 0)
    {
        return;
    }
    const double bound = box_.shearRate() != 0
      ? 2*std::abs(box_.shearRate())
      : flow_.maxShearRate();
    limits_ = makeLimits
    (
        forces_.models(), radii_, flow_, params_, implicitNormalContact_,
        bound
    );
    dtMax_ = limits_.deltaT();
    stepLimitCounts_[0].name = limits_.binding().name;
}


std::string Simulation::stepName(double dt) const
{
    std::ostringstream name;
    name.precision(10);
    name << "step " << steps_ + 1 << " (t = " << time_ << " to " << time_ + dt
         << ")";
    return name.str();
}


std::string Simulation::solveFailure(double dt) const
{
    using Outcome = ConjugateGradient::Outcome;
    const ConjugateGradient::Result& cg = implicit_->statistics();
    std::ostringstream msg;
    if (cg.outcome == Outcome::maxIterations)
    {
        msg << "the implicit velocity solve did not converge at "
            << stepName(dt) << ": |r|/|b| = " << cg.residual << " after "
            << cg.iterations << " CG iterations (tolerance "
            << params_.solver.tolerance << ", maxIterations "
            << params_.solver.maxIterations << ")";
        return msg.str();
    }
    msg << "the implicit velocity solve failed at " << stepName(dt) << ": ";
    if (cg.outcome == Outcome::notPositiveDefinite)
    {
        msg << "the operator is not positive definite (p.A p <= 0 at CG"
               " iteration " << cg.iterations + 1 << ")";
        return msg.str();
    }
    const bool rhs = cg.outcome == Outcome::nonFiniteRightHandSide;
    if (rhs)
    {
        msg << "non-finite right-hand side";
    }
    else
    {
        msg << "non-finite residual after " << cg.iterations
            << " CG iterations";
    }
    const Particles& p = particles_;
    const std::size_t i = implicit_->nonFiniteParticle();
    if (i == p.size())
    {
        msg << ", every entry of the right-hand side and of the unknowns"
               " finite: a non-finite operator product";
        return msg.str();
    }
    msg << ", first at particle " << p.id[i] << " (";
    if (rhs)
    {
        msg << "F = " << p.F[i].transpose() << ", T = "
            << p.T[i].transpose() << ", ";
    }
    msg << "u = " << p.u[i].transpose() << ", omega = "
        << p.omega[i].transpose() << ")";
    return msg.str();
}


std::string Simulation::moveFailure(std::size_t i, double dt) const
{
    const Particles& p = particles_;
    std::ostringstream msg;
    msg << "particle " << p.id[i] << " cannot be wrapped into the box at "
        << stepName(dt) << ": its new position is ";
    if (p.x[i].allFinite())
    {
        msg << "beyond 2^" << std::ilogb(LeesEdwardsBox::maxWrapLengths)
            << " box lengths";
    }
    else
    {
        msg << "not finite";
    }
    msg << ", x = " << p.x[i].transpose() << ", u = " << p.u[i].transpose();
    if (!implicit_)
    {
        msg << ", F = " << p.F[i].transpose();
    }
    return msg.str();
}


void Simulation::advance(double interval)
{
    if (!(interval > 0))
    {
        return;
    }
    if (adaptive() || flow_.stressControlled())
    {
        const double end = time_ + interval;
        for (;;)
        {
            followStressControlledRate();
            const double remaining = end - time_;
            const auto [bound, limit] = stepBound();
            const double n =
                std::max(1.0, std::ceil(remaining/bound*(1 - 1e-12)));
            governedStep(remaining/n);
            ++stepLimitCounts_[limit].steps;
            if (n == 1)
            {
                time_ = end;
                restoreThreads();
                return;
            }
        }
    }
    // n - 1 steps of dtMax and the rest
    const std::uint64_t n = stepsIn(interval);
    stepLimitCounts_[0].steps += n;
    const double t0 = time_;
    for (std::uint64_t k = 1; k < n; ++k)
    {
        governedStep(dtMax_);
        time_ = t0 + k*dtMax_;  // no round-off drift over many steps
    }
    governedStep(t0 + interval - time_);
    time_ = t0 + interval;
    restoreThreads();
}


void Simulation::restoreThreads() const
{
    if (governor_)
    {
        omp_set_num_threads(governor_->maxThreads());
    }
}


void Simulation::governedStep(double dt)
{
    if (!governor_)
    {
        step(dt);
        return;
    }
    omp_set_num_threads(governor_->threads());
    const auto start = std::chrono::steady_clock::now();
    step(dt);
    governor_->record
    (
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
    );
}


int Simulation::threads() const
{
    if (governor_)
    {
        return governor_->inUse();
    }
    return threaded(particles_.size()) ? omp_get_max_threads() : 1;
}


std::uint64_t Simulation::stepsIn(double interval) const
{
    // The (1 - 1e-12) keeps an interval of a whole number of steps from a
    // last step of round-off size
    return std::max<std::uint64_t>
    (
        1, static_cast<std::uint64_t>(std::ceil(interval/dtMax_*(1 - 1e-12)))
    );
}


std::pair<double, std::size_t> Simulation::stepBound() const
{
    std::pair<double, std::size_t> bound{dtMax_, 0};
    auto tighten = [&](double value, std::size_t limit)
    {
        if (value < bound.first)
        {
            bound = {value, limit};
        }
    };
    if (params_.maxDisplacement > 0)
    {
        const std::vector<FlowSample>& ambient = forces_.ambient();
        double uMax = 0;
        for (std::size_t i = 0; i < particles_.size(); ++i)
        {
            if (!particles_.isGhost(i))
            {
                uMax = std::max(uMax, (particles_.u[i] - ambient[i].U).norm());
            }
        }
        if (domain_)
        {
            domain_->comm().max(&uMax, 1);
        }
        if (uMax > 0)
        {
            tighten(params_.maxDisplacement*radii_.first/uMax, 1);
        }
    }
    return bound;
}


void Simulation::particleStresslets(std::vector<Mat3>& S)
{
    // The ghosts as their owners are now: a step ends with the owned
    // particles' last update, after the ghosts' refresh
    if (domain_)
    {
        domain_->refresh(particles_);
    }
    ForceField::Output out;
    out.S = &S;
    forces_.evaluate(particles_, box_, flow_, pairs_, search_.far(), out);
}


Rheology Simulation::rheology() const
{
    return Rheology
    (
        summary_, box_.volume(), forces_.models().drag().params().eta,
        box_.shearRate()
    );
}


KernelTimes Simulation::kernelTimes() const
{
    KernelTimes t = times_;
    const KernelTimes& f = forces_.times();
    t.flowSampling = f.flowSampling;
    t.pairLoop = f.pairLoop;
    t.particleTerms = f.particleTerms;
    return t;
}


void Simulation::resetKernelTimes()
{
    times_ = KernelTimes();
    forces_.resetTimes();
}


double Simulation::velocityFluctuation() const
{
    const Particles& p = particles_;
    double sum[2] = {0, 0};
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (!p.isGhost(i))
        {
            sum[0] += (p.u[i] - flow_.sample(p.x[i], box_.shearRate()).U).squaredNorm();
            sum[1] += 1;
        }
    }
    flow_.sampled(p);
    if (domain_)
    {
        domain_->comm().sum(sum, 2);
    }
    return sum[1] > 0 ? sum[0]/sum[1] : 0;
}


void Simulation::check() const
{
    const Particles& p = particles_;
    std::ostringstream msg;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if
        (
            !p.isGhost(i)
         && (
                !p.x[i].allFinite() || !p.F[i].allFinite()
             || !p.T[i].allFinite() || !p.u[i].allFinite()
             || !p.omega[i].allFinite()
            )
        )
        {
            msg << "non-finite state of particle " << p.id[i]
                << " at step " << steps_ << " (t = " << time_ << "): x = "
                << p.x[i].transpose() << ", u = " << p.u[i].transpose()
                << ", F = " << p.F[i].transpose() << ", T = "
                << p.T[i].transpose();
            break;
        }
    }
    const bool here = !msg.str().empty();
    if (anyProcess(here))
    {
        throw SimulationError
        (
            here ? msg.str()
          : "non-finite state on another process at step "
          + std::to_string(steps_)
        );
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
