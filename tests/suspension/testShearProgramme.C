// A mean shear rate that changes in time (a rheometer's programme): the
// strain, the Lees-Edwards offset and the images follow its integral, the
// implicit step at another rate than its samples', restarts
#include "dynamics/Simulation.H"
#include "modelTestTools.H"
#include "flow/ShearFlow.H"
#include "packing/RandomPacking.H"
#include "packing/SizeDistribution.H"
#include "stressControlledShear.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <tuple>

using namespace suspension;

namespace
{
    const double rho = 1;           // St (eq. 11): explicit steps of 1e-4

    //- Simple shear at the rate g0 + g1 sin(w t), with its exact mean
    class ProgrammedShear
    :
        public ShearFlow
    {
        double g0_, g1_, w_;

    public:

        ProgrammedShear(double g0, double g1, double w)
        :
            ShearFlow(g0), g0_(g0), g1_(g1), w_(w)
        {}

        double shearRate(double t) const override
        {
            return g0_ + g1_*std::sin(w_*t);
        }
        double meanShearRate(double t0, double t1) const override
        {
            return g0_ + g1_*(std::cos(w_*t0) - std::cos(w_*t1))/(w_*(t1 - t0));
        }
        double maxShearRate() const override
        {
            return std::abs(g0_) + std::abs(g1_);
        }
        bool shearRateChanges() const override { return true; }

        //- int_0^t gammaDot dt
        double strainAt(double t) const
        {
            return g0_*t + g1_*(1 - std::cos(w_*t))/w_;
        }
    };

    //- Simple shear at the rate r0 up to t = 0 and r1 after it
    class RateStep
    :
        public ShearFlow
    {
        double r0_, r1_;

    public:

        RateStep(double r0, double r1) : ShearFlow(r0), r0_(r0), r1_(r1) {}

        double shearRate(double t) const override { return t > 0 ? r1_ : r0_; }
        double meanShearRate(double, double t1) const override
        {
            return t1 > 0 ? r1_ : r0_;
        }
        double maxShearRate() const override
        {
            return std::max(std::abs(r0_), std::abs(r1_));
        }
        bool shearRateChanges() const override { return true; }
    };

    //- Table 1 FR with rolling springs, and 60 spheres packed at 0.5
    ForceModels frictional() { return test::frictionalWithRolling(); }

    RandomPacking::Result packing(const ForceModels& m)
    {
        return test::packing(m, rho);
    }

    //- A run of `models` in simple shear at the rate 1 to t = 0 from the
    //  packing, with contacts
    Simulation sheared
    (
        const ForceModels& models,
        const RandomPacking::Result& packed,
        const ShearFlow& steady,
        const Simulation::Params& pp
    )
    {
        Simulation sim
        (
            packed.particles, LeesEdwardsBox(packed.box.L(), 1.0), steady,
            models, pp
        );
        sim.start(-0.1);
        sim.advance(0.1);
        return sim;
    }

    Simulation::Params params(Integrator integrator)
    {
        Simulation::Params p;
        p.rho = rho;
        p.integrator = integrator;
        return p;
    }

    const Integrator integrators[] =
    {
        Integrator::velocityVerlet, Integrator::implicitEuler,
        Integrator::overdamped
    };
}


TEST(ShearProgramme, StrainAndOffsetAreTheIntegralOfTheRate)
{
    // A rate that reverses twice per period (0.3 + sin 15t): the strain is
    // the sum of each step's mean rate times its length, which is the
    // exact integral; the offset is Ly times it, the rate of the rheology
    // the last step's
    const ForceModels models = frictional();
    const RandomPacking::Result packed = packing(models);
    const ProgrammedShear flow(0.3, 1.0, 15.0);
    for (const Integrator integrator : integrators)
    {
        Simulation sim
        (
            packed.particles, LeesEdwardsBox(packed.box.L(), 1.0), flow,
            models, params(integrator)
        );
        sim.start(0);
        EXPECT_EQ(sim.shearRate(), flow.shearRate(0));
        const std::uint64_t n = sim.stepsIn(0.5);
        sim.advance(0.5);
        const double gamma = flow.strainAt(0.5);
        EXPECT_NEAR(sim.strain(), gamma, 1e-13);
        const LeesEdwardsBox& box = sim.box();
        const double expected =
            std::fmod(gamma*box.L().y(), box.L().x());
        EXPECT_NEAR(box.offset(), expected, 1e-12*box.L().x());
        const double tLast = (n - 1)*sim.deltaT();
        EXPECT_EQ(sim.shearRate(), flow.meanShearRate(tLast, tLast + (0.5 - tLast)));
        EXPECT_EQ(box.imageVelocity(), sim.shearRate()*box.L().y());
        const Rheology r = sim.rheology();
        EXPECT_DOUBLE_EQ(r.etaR, r.sigma/sim.shearRate());
    }
}


TEST(ShearProgramme, PairAcrossTheBoundaryMovesAsTheUnwrappedPair)
{
    // A touching pair, once inside the box and once straddling y = 0,
    // sheared at a rate that reverses (0.3 + sin 15t): the offset and the
    // images' velocity follow the strain, so both move alike, with every
    // integrator (the implicit ones take each step at its own rate from
    // samples at the last step's: ImplicitEuler's shift)
    const Vec3 L(10, 10, 10);
    const ProgrammedShear flow(0.3, 1.0, 15.0);
    const ForceModels models = frictional();
    for (const Integrator integrator : integrators)
    {
        SCOPED_TRACE(static_cast<int>(integrator));
        auto run = [&](const Vec3& xi)
        {
            Particles p;
            p.add(xi, 1.0, rho, 0);
            p.add(xi + Vec3(0.3, 2.0, 0.2), 1.1, rho, 1);
            for (std::size_t s = 0; s < 2; ++s)
            {
                p.u[s] = flow.sample(p.x[s], flow.shearRate(0)).U;
            }
            LeesEdwardsBox box(L, flow.shearRate(0));
            box.wrap(p.x[1], p.u[1]);
            Simulation::Params pp = params(integrator);
            pp.maxOverlap = 10;
            pp.solver.tolerance = 1e-13;
            pp.solver.maxIterations = 10000;
            Simulation sim(p, box, flow, models, pp);
            sim.start(0);
            std::size_t contacts = 0;
            for (int k = 0; k < 8; ++k)
            {
                sim.advance(0.05);
                contacts = std::max(contacts, sim.summary().nContacts);
            }
            EXPECT_GT(contacts, 0u);
            const Particles& q = sim.particles();
            const std::size_t i = q.id[0] == 0 ? 0 : 1;
            const std::size_t j = 1 - i;
            Vec3 r = q.x[j] - q.x[i];
            sim.box().minimumImage(r);
            return std::make_tuple
            (
                r, Vec3(q.u[i] - flow.sample(q.x[i], sim.shearRate()).U),
                q.omega[i], q.F[i], q.T[i]
            );
        };
        const auto inside = run(Vec3(5, 4, 5));
        const auto across = run(Vec3(5, 9, 5));
        auto expectNear = [](const Vec3& a, const Vec3& b, const char* what)
        {
            EXPECT_LT((a - b).norm(), 1e-8*(1 + a.norm())) << what;
        };
        expectNear(std::get<0>(inside), std::get<0>(across), "separation");
        expectNear(std::get<1>(inside), std::get<1>(across), "u - U_inf");
        expectNear(std::get<2>(inside), std::get<2>(across), "omega");
        expectNear(std::get<3>(inside), std::get<3>(across), "F");
        expectNear(std::get<4>(inside), std::get<4>(across), "T");
    }
}


TEST(ShearProgramme, ImplicitStepAtAnotherRateIsTheStepOfThatFlow)
{
    // From the same sheared state, a step at the rate 1.7 taken from
    // samples at the rate 1 (shifted: U_inf, Omega_inf, the ambient
    // forces, the contacts' ambient motion; the velocities kept relative
    // to the flow) equals the step of a run started at 1.7 from that state
    // (velocities carried by the change, u_x += 0.7 y, omega_z -= 0.35),
    // to the solver's tolerance. Frictionless with the normal springs in
    // the operator: which springs a step linearises (sticking or sliding)
    // is decided on the velocities at the end of the last step, before the
    // change of rate carries them, which is not the test's business
    const ForceModels models = test::lubricatedContacts(0.05, 4e5, 0.0);
    const RandomPacking::Result packed = packing(models);
    for (const Integrator integrator :
        {Integrator::implicitEuler, Integrator::overdamped})
    {
        SCOPED_TRACE(static_cast<int>(integrator));
        Simulation::Params pp = params(integrator);
        pp.implicitNormalContact = true;
        pp.solver.tolerance = 1e-12;
        pp.solver.maxIterations = 10000;
        const ShearFlow steady(1.0);
        const Simulation sheared = ::sheared(models, packed, steady, pp);
        ASSERT_GT(sheared.summary().nContacts, 0u);
        const Simulation::Shear at1 = sheared.shear();

        const RateStep step(1.0, 1.7);
        Simulation shifted
        (
            sheared.particles(), sheared.box(), step, models, pp
        );
        shifted.pairs() = sheared.pairs();
        shifted.start(0, true, at1);
        shifted.step(1e-3);

        const ShearFlow fast(1.7);
        Particles carried = sheared.particles();
        for (std::size_t i = 0; i < carried.size(); ++i)
        {
            carried.u[i].x() += 0.7*carried.x[i].y();
            carried.omega[i].z() -= 0.35;
        }
        Simulation direct(carried, sheared.box(), fast, models, pp);
        direct.pairs() = sheared.pairs();
        direct.start(0, true, Simulation::Shear{at1.strain, 1.7});
        direct.step(1e-3);

        EXPECT_EQ(shifted.shearRate(), 1.7);
        EXPECT_EQ(shifted.strain(), direct.strain());
        const Particles& a = shifted.particles();
        const Particles& b = direct.particles();
        ASSERT_EQ(a.id, b.id);
        double du = 0, uScale = 0;
        for (std::size_t i = 0; i < a.size(); ++i)
        {
            du = std::max(du, (a.u[i] - b.u[i]).norm() + (a.omega[i] - b.omega[i]).norm());
            uScale = std::max(uScale, (b.u[i] - fast.sample(b.x[i]).U).norm());
        }
        EXPECT_LT(du, 1e-8*uScale);
        EXPECT_GT(uScale, 0.01);
        EXPECT_GT(shifted.implicit()->resistance().nContacts(), 0u);
    }
}


TEST(ShearProgramme, RestartIsBitwise)
{
    // Written and restarted at t = 0.25 (a new engine given the particles,
    // the contact history and the shear: strain and last rate) under a
    // reversing rate, the run continues bitwise as the uninterrupted one,
    // which restarts itself at the same time as the cloud does after a
    // write
    const ForceModels models = frictional();
    const RandomPacking::Result packed = packing(models);
    const ProgrammedShear flow(0.3, 1.0, 15.0);
    for (const Integrator integrator : integrators)
    {
        SCOPED_TRACE(static_cast<int>(integrator));
        Simulation a
        (
            packed.particles, LeesEdwardsBox(packed.box.L(), 1.0), flow,
            models, params(integrator)
        );
        a.start(0);
        a.advance(0.25);
        Simulation b
        (
            a.particles(), a.box(), flow, models, params(integrator)
        );
        b.pairs() = a.pairs();
        b.start(a.time(), true, a.shear());
        a.start(a.time(), true, a.shear());
        a.advance(0.3);
        b.advance(0.3);
        ASSERT_EQ(a.particles().id, b.particles().id);
        EXPECT_EQ(a.particles().x, b.particles().x);
        EXPECT_EQ(a.particles().u, b.particles().u);
        EXPECT_EQ(a.particles().F, b.particles().F);
        EXPECT_EQ(a.strain(), b.strain());
        EXPECT_EQ(a.box().offset(), b.box().offset());
        EXPECT_EQ(a.rheology().sigma, b.rheology().sigma);
    }
}


namespace
{
    using StressControlled = test::StressControlledShear;

    //- Volume fraction of the particles in the box
    double volumeFraction(const Particles& p, const LeesEdwardsBox& box)
    {
        double v = 0;
        for (const double a : p.a)
        {
            v += 4*pi*a*a*a/3;
        }
        return v/box.volume();
    }
}


TEST(StressControl, DiluteRateIsTheStressOverTheEinsteinViscosity)
{
    // Stokes drag alone: the particles follow the flow and the stress is
    // eta0 (1 + 2.5 phi) gammaDot (the Stokes stresslets, eq. 9a), so the
    // rate the control finds is sigma/(eta0 (1 + 2.5 phi)), at every step,
    // for a stress that changes too; the viscosity of the rheology is that
    const ForceModels drag;
    const RandomPacking::Result packed = packing(frictional());
    const StressControlled flow(2.0, 3.0);
    for (const Integrator integrator :
        {Integrator::implicitEuler, Integrator::overdamped})
    {
        SCOPED_TRACE(static_cast<int>(integrator));
        Simulation::Params pp = params(integrator);
        pp.deltaT = 1e-3;
        pp.maxOverlap = 10;
        Simulation sim
        (
            packed.particles, LeesEdwardsBox(packed.box.L(), 0.0), flow,
            drag, pp
        );
        sim.start(0);
        const double einstein = 1 + 2.5*volumeFraction(sim.particles(), sim.box());
        sim.advance(0.005);
        for (int k = 0; k < 3; ++k)
        {
            sim.advance(0.01);
            const double sigma = flow.shearStress(sim.time());
            EXPECT_NEAR(sim.shearRate(), sigma/einstein, 1e-9*sigma);
            EXPECT_NEAR(sim.implicit()->stepShearStress(), sigma, 1e-9*sigma);
            EXPECT_NEAR(sim.rheology().etaR, einstein, 1e-6);
        }
    }
}


TEST(StressControl, FoundRateImposedGivesTheSameStep)
{
    // A dense frictional state (Table 1 FR, phi = 0.5): the step that the
    // control takes for the target stress, and the step taken at the rate
    // it found as a rate-controlled one from the same state, have the same
    // velocities to the solver's tolerance, and the stress of the latter,
    // computed from its own velocities, is the target to that tolerance;
    // the explicit integrator is refused
    const ForceModels models = frictional();
    const RandomPacking::Result packed = packing(models);
    for (const Integrator integrator :
        {Integrator::implicitEuler, Integrator::overdamped})
    {
        SCOPED_TRACE(static_cast<int>(integrator));
        Simulation::Params pp = params(integrator);
        pp.solver.tolerance = 1e-12;
        pp.solver.maxIterations = 10000;
        const ShearFlow steady(1.0);
        const Simulation sheared = ::sheared(models, packed, steady, pp);
        ASSERT_GT(sheared.summary().nContacts, 0u);

        const double target = 40;
        const StressControlled control(target, 0);
        Simulation a(sheared.particles(), sheared.box(), control, models, pp);
        a.pairs() = sheared.pairs();
        a.start(0, true, sheared.shear());
        a.step(1e-3);
        const double found = a.shearRate();
        EXPECT_NEAR(a.implicit()->stepShearStress(), target, 1e-10*target);
        EXPECT_GT(std::abs(found - 1.0), 1e-3);     // not the old rate

        const RateStep imposed(1.0, found);
        Simulation b(sheared.particles(), sheared.box(), imposed, models, pp);
        b.pairs() = sheared.pairs();
        b.start(0, true, sheared.shear());
        b.step(1e-3);
        EXPECT_EQ(b.shearRate(), found);
        EXPECT_NEAR(b.implicit()->stepShearStress(), target, 1e-8*target);
        double du = 0, scale = 0;
        for (std::size_t i = 0; i < a.particles().size(); ++i)
        {
            du = std::max(du, (a.particles().u[i] - b.particles().u[i]).norm());
            scale = std::max(scale, b.particles().u[i].norm());
        }
        EXPECT_LT(du, 1e-8*scale);
    }
    const StressControlled control(40, 0);
    EXPECT_THROW
    (
        Simulation
        (
            packed.particles, LeesEdwardsBox(packed.box.L(), 1.0), control,
            models, params(Integrator::velocityVerlet)
        ),
        std::invalid_argument
    );
}


TEST(StressControl, RestartIsBitwise)
{
    // Under stress control the rate is state (the box's, restored with
    // the shear): a restart continues bitwise
    const ForceModels models = frictional();
    const RandomPacking::Result packed = packing(models);
    const StressControlled flow(30, 20);
    Simulation a
    (
        packed.particles, LeesEdwardsBox(packed.box.L(), 0.0), flow, models,
        params(Integrator::implicitEuler)
    );
    a.start(0);
    a.advance(0.1);
    Simulation b(a.particles(), a.box(), flow, models, params(Integrator::implicitEuler));
    b.pairs() = a.pairs();
    b.start(a.time(), true, a.shear());
    a.start(a.time(), true, a.shear());
    const std::uint64_t before = a.steps();
    a.advance(0.1);
    b.advance(0.1);
    EXPECT_EQ(a.steps() - before, b.steps());
    EXPECT_EQ(a.particles().x, b.particles().x);
    EXPECT_EQ(a.particles().u, b.particles().u);
    EXPECT_EQ(a.shearRate(), b.shearRate());
    EXPECT_EQ(a.strain(), b.strain());
}


TEST(StressControl, StepStressIsTheStressAfterTheStep)
{
    // What stress control holds at the target, the stress of a step (its
    // new velocities at its old positions, the contact forces there), and
    // the bulk stress of the state after the step (what rate-controlled
    // rows report) differ only by the step's motion: in a dense frictional
    // shear with contacts (Table 1 FR, St = 1e-3, the automatic step) by
    // about 1.4e-3 of the stress on average over half a strain unit
    const ForceModels models = test::lubricatedContacts(0.05, 4e5, 1.0);
    const RandomPacking::Result packed = test::packing(models, 1e-3);
    Simulation::Params pp = params(Integrator::implicitEuler);
    pp.rho = 1e-3;
    const RateStep unit(1.0, 1.0);      // a programme: the step's stress is kept
    Simulation sim
    (
        packed.particles, LeesEdwardsBox(packed.box.L(), 0.0), unit, models, pp
    );
    sim.start(0);
    sim.advance(0.5);
    double sumDiff = 0, sumSigma = 0, largest = 0;
    std::size_t contacts = 0;
    for (int k = 0; k < 50; ++k)
    {
        sim.advance(0.01);
        const double step = sim.implicit()->stepShearStress();
        const double state = sim.rheology().sigma;
        sumDiff += std::abs(step - state);
        sumSigma += std::abs(state);
        largest = std::max(largest, std::abs(step - state)/std::abs(state));
        contacts += sim.summary().nContacts;
    }
    ASSERT_GT(contacts, 0u);
    std::printf
    (
        "step against reported stress: mean %.3g, largest %.3g (relative)\n",
        sumDiff/sumSigma, largest
    );
    EXPECT_LT(sumDiff/sumSigma, 2e-3);
    EXPECT_LT(largest, 2e-2);
}
