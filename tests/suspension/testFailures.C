// Every failure of a step arrives as a SimulationError naming the cause,
// the particle (its id) and the step: a NaN injected between steps into a
// position, a velocity, a force (the implicit right-hand side), a radius or
// a mass (a diagonal block of the implicit operator), a position too far
// out to wrap, an exception of the flow inside a step; a particle outside
// the box at the start is a set-up error naming the particle
#include "dynamics/Simulation.H"
#include "modelTestTools.H"
#include "flow/ShearFlow.H"
#include "packing/RandomPacking.H"
#include "packing/SizeDistribution.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <regex>
#include <stdexcept>
#include <string>

using namespace suspension;

namespace
{
    const double rho = 1e-3;        // St (eq. 11)
    const double NaN = std::numeric_limits<double>::quiet_NaN();

    //- First id of the particles: no id is also an index
    const std::int64_t firstId = 1000;

    //- Lubrication and frictional contacts (Table 1 FR groups)
    ForceModels models()
    {
        return test::lubricatedContacts(0.05, 4e5, 1.0);
    }

    //- 60 spheres of radii 1 and 1.4 at phi = 0.45, ids from firstId
    const RandomPacking::Result& packing()
    {
        static const RandomPacking::Result packed = []
        {
            RandomPacking::Params pp;
            pp.phi = 0.45;
            pp.seed = 3;
            pp.reach = models().interactionGap() + Simulation::Params().skin;
            RandomPacking::Result r = RandomPacking(pp).pack
            (
                SizeDistribution::bidisperse(1.0, 1.4, 1.0).radii(60), rho
            );
            for (std::int64_t& id : r.particles.id)
            {
                id += firstId;
            }
            return r;
        }();
        return packed;
    }

    Simulation::Params params(Integrator integrator)
    {
        Simulation::Params s;
        s.rho = rho;
        s.integrator = integrator;
        return s;
    }

    //- The packing sheared for three steps by `integrator` in `flow`
    Simulation sheared(Integrator integrator, const AmbientFlow& flow)
    {
        Simulation sim
        (
            packing().particles, LeesEdwardsBox(packing().box.L(), 1.0), flow,
            models(), params(integrator)
        );
        sim.start(0);
        for (int k = 0; k < 3; ++k)
        {
            sim.step(sim.deltaT());
        }
        return sim;
    }

    const ShearFlow shear(1.0);

    const Integrator integrators[] =
        {Integrator::velocityVerlet, Integrator::implicitEuler, Integrator::overdamped};

    const char* name(Integrator integrator)
    {
        return integrator == Integrator::velocityVerlet ? "velocityVerlet"
             : integrator == Integrator::implicitEuler ? "implicitEuler"
             : "overdamped";
    }

    //- The message of the SimulationError the next step throws; a test
    //  failure when it throws nothing or anything else
    std::string stepError(Simulation& sim)
    {
        try
        {
            sim.step(sim.deltaT());
        }
        catch (const SimulationError& err)
        {
            return err.what();
        }
        catch (const std::exception& err)
        {
            ADD_FAILURE() << "not a SimulationError: " << err.what();
            return {};
        }
        ADD_FAILURE() << "the step went on";
        return {};
    }

    //- Whether msg names particle `id`
    bool namesParticle(const std::string& msg, std::int64_t id)
    {
        return std::regex_search(msg, std::regex("particle " + std::to_string(id) + "\\b"));
    }

    //- Whether msg names the step the failure was in, the one after
    //  `steps` taken, and its start time t
    bool namesStep(const std::string& msg, std::uint64_t steps)
    {
        return msg.find("step " + std::to_string(steps + 1) + " (t = ") != std::string::npos;
    }

    bool has(const std::string& msg, const std::string& part)
    {
        return msg.find(part) != std::string::npos;
    }
}


TEST(Failures, PositionThatCannotBeWrappedStopsTheMove)
{
    // A NaN position, and one too far out to wrap, are reported by the
    // move, never wrapped nor handed to the neighbour search
    struct Case { std::size_t k; int axis; double value; const char* why; };
    const Case cases[] =
    {
        {17, 1, NaN, "not finite"},
        {23, 0, 1e30, "beyond 2^40 box lengths"}
    };
    for (const Case& c : cases)
    {
        for (const Integrator integrator : integrators)
        {
            Simulation sim = sheared(integrator, shear);
            const std::int64_t id = sim.particles().id[c.k];
            sim.particles().x[c.k][c.axis] = c.value;
            const std::string msg = stepError(sim);
            EXPECT_TRUE(namesParticle(msg, id)) << name(integrator) << ": " << msg;
            EXPECT_TRUE(namesStep(msg, sim.steps())) << name(integrator) << ": " << msg;
            EXPECT_TRUE(has(msg, "cannot be wrapped") && has(msg, c.why))
                << name(integrator) << ": " << msg;
        }
    }
}


TEST(Failures, NonFiniteVelocity)
{
    // Explicit: the position it moves to is not finite. Implicit: the
    // right-hand side of the solve (M/dt u, and 0 u overdamped) is not, at
    // the particle and at its partners through the contact dashpots: it is
    // put on the first particle, which is the one named
    for (const Integrator integrator : integrators)
    {
        Simulation sim = sheared(integrator, shear);
        const std::int64_t id = sim.particles().id[0];
        sim.particles().u[0].x() = NaN;
        const std::string msg = stepError(sim);
        EXPECT_TRUE(namesParticle(msg, id)) << name(integrator) << ": " << msg;
        EXPECT_TRUE(namesStep(msg, sim.steps())) << name(integrator) << ": " << msg;
        const std::string cause = integrator == Integrator::velocityVerlet
            ? "cannot be wrapped" : "non-finite right-hand side";
        EXPECT_TRUE(has(msg, cause)) << name(integrator) << ": " << msg;
        EXPECT_FALSE(has(msg, "did not converge")) << name(integrator) << ": " << msg;
    }
}


TEST(Failures, NonFiniteForce)
{
    // Explicit: the position it accelerates to is not finite (F named).
    // Implicit: the right-hand side at that particle alone
    for (const Integrator integrator : integrators)
    {
        Simulation sim = sheared(integrator, shear);
        const std::size_t k = 31;
        const std::int64_t id = sim.particles().id[k];
        sim.particles().F[k].z() = NaN;
        const std::string msg = stepError(sim);
        EXPECT_TRUE(namesParticle(msg, id)) << name(integrator) << ": " << msg;
        EXPECT_TRUE(namesStep(msg, sim.steps())) << name(integrator) << ": " << msg;
        const std::string cause = integrator == Integrator::velocityVerlet
            ? "cannot be wrapped" : "non-finite right-hand side";
        EXPECT_TRUE(has(msg, cause) && has(msg, "F = ")) << name(integrator) << ": " << msg;
    }
}


TEST(Failures, DiagonalBlockOfTheImplicitOperator)
{
    // A NaN radius makes the particle's diagonal block non-finite; a
    // negative mass (with inertia: M/dt) makes it indefinite. The
    // preconditioner's factorisation stops the step before the solve
    for (const Integrator integrator : {Integrator::implicitEuler, Integrator::overdamped})
    {
        Simulation sim = sheared(integrator, shear);
        const std::size_t k = 9;
        const std::int64_t id = sim.particles().id[k];
        sim.particles().a[k] = NaN;
        const std::string msg = stepError(sim);
        EXPECT_TRUE(namesParticle(msg, id)) << name(integrator) << ": " << msg;
        EXPECT_TRUE(namesStep(msg, sim.steps())) << name(integrator) << ": " << msg;
        EXPECT_TRUE(has(msg, "diagonal block") && has(msg, "is not finite"))
            << name(integrator) << ": " << msg;
    }

    Simulation sim = sheared(Integrator::implicitEuler, shear);
    const std::size_t k = 44;
    const std::int64_t id = sim.particles().id[k];
    sim.particles().m[k] = -1e3;
    const std::string msg = stepError(sim);
    EXPECT_TRUE(namesParticle(msg, id)) << msg;
    EXPECT_TRUE(namesStep(msg, sim.steps())) << msg;
    EXPECT_TRUE(has(msg, "diagonal block") && has(msg, "not positive definite")) << msg;
}


TEST(Failures, DiagonalBlockThroughTheResistance)
{
    // HydrodynamicResistance::setStep on its own: two lubricated spheres,
    // then a negative mass (indefinite with inertia) or a NaN radius
    const Lubrication lubrication(Lubrication::Params{1, 1e-3, 0.05, LubricationTerms::leading});
    const LeesEdwardsBox box(Vec3(10, 10, 10), 0.0);
    Particles p;
    p.add(Vec3(4, 5, 5), 1.0, rho, 41);
    p.add(Vec3(6.01, 5, 5), 1.0, rho, 42);
    PairList pairs;
    NeighbourSearch search({lubrication.gap(), 0.1});
    search.rebuild(p, box, pairs);
    const std::vector<FlowSample> ambient(2);
    const std::int64_t id1 = p.id[1];
    const std::int64_t id0 = p.id[0];

    ForceModels models;
    models.set(lubrication);
    HydrodynamicResistance R(models);
    R.assemble(p, box, ambient, pairs);
    ASSERT_EQ(R.nPairs(), 1u);
    EXPECT_NO_THROW(R.setStep(p, 1e-3, true));

    Particles q = p;
    q.m[1] = -1e3;
    try
    {
        R.setStep(q, 1e-3, true);
        ADD_FAILURE() << "an indefinite block passed";
    }
    catch (const SimulationError& err)
    {
        EXPECT_TRUE(namesParticle(err.what(), id1)) << err.what();
        EXPECT_TRUE(has(err.what(), "not positive definite")) << err.what();
    }

    q = p;
    q.a[0] = NaN;
    try
    {
        R.setStep(q, 1e-3, false);
        ADD_FAILURE() << "a non-finite block passed";
    }
    catch (const SimulationError& err)
    {
        EXPECT_TRUE(namesParticle(err.what(), id0)) << err.what();
        EXPECT_TRUE(has(err.what(), "is not finite")) << err.what();
    }
}


TEST(Failures, UnconvergedSolveKeepsItsMessage)
{
    // One CG iteration allowed: the outcome maxIterations, with the
    // message a case greps for, before the particles moved
    Simulation::Params s = params(Integrator::implicitEuler);
    s.solver.maxIterations = 1;
    Simulation sim
    (
        packing().particles, LeesEdwardsBox(packing().box.L(), 1.0), shear,
        models(), s
    );
    sim.start(0);
    const std::vector<Vec3> x = sim.particles().x;
    const std::vector<Vec3> u = sim.particles().u;
    const std::string msg = stepError(sim);
    EXPECT_TRUE(has(msg, "the implicit velocity solve did not converge at step 1 (t = 0 to "))
        << msg;
    EXPECT_EQ(sim.implicit()->statistics().outcome, ConjugateGradient::Outcome::maxIterations);
    EXPECT_EQ(sim.particles().x, x);
    EXPECT_EQ(sim.particles().u, u);
}


namespace
{
    //- Shear flow that cannot sample some particle at its n-th check
    //  (AmbientFlow::sampled(), where a flow stops the run)
    class FailingFlow
    :
        public ShearFlow
    {
        mutable std::size_t checks_ = 0;
        std::size_t failAt_;

    public:

        FailingFlow(double gammaDot, std::size_t failAt)
        :
            ShearFlow(gammaDot),
            failAt_(failAt)
        {}

        std::size_t checks() const { return checks_; }

        void sampled(const Particles&) const override
        {
            if (++checks_ == failAt_)
            {
                throw std::runtime_error("FailingFlow: a particle outside the mesh");
            }
        }
    };
}


TEST(Failures, ExceptionInsideAStepBecomesASimulationError)
{
    for (const Integrator integrator : integrators)
    {
        // How many checks three steps take, then a flow failing at the
        // check after those
        FailingFlow counting(1.0, 0);
        sheared(integrator, counting);
        const FailingFlow flow(1.0, counting.checks() + 1);

        Simulation sim = sheared(integrator, flow);
        const std::string msg = stepError(sim);
        EXPECT_EQ(msg.rfind("step 4 (t = ", 0), 0u) << name(integrator) << ": " << msg;
        EXPECT_TRUE(has(msg, "): FailingFlow: a particle outside the mesh"))
            << name(integrator) << ": " << msg;
    }
}


TEST(Failures, ParticleOutsideTheBoxAtStartIsNamed)
{
    Particles p = packing().particles;
    const std::size_t k = 12;
    p.x[k].y() = -0.5;
    Simulation sim
    (
        p, LeesEdwardsBox(packing().box.L(), 1.0), shear, models(),
        params(Integrator::implicitEuler)
    );
    try
    {
        sim.start(0);
        ADD_FAILURE() << "started with a particle outside the box";
    }
    catch (const std::invalid_argument& err)
    {
        EXPECT_TRUE(namesParticle(err.what(), p.id[k])) << err.what();
        EXPECT_TRUE(has(err.what(), "outside the box")) << err.what();
    }
}
