// The pair loop, the integrator and the bulk stress together
#include "dynamics/Simulation.H"
#include "modelTestTools.H"
#include "core/Parallel.H"
#include "flow/ShearFlow.H"
#include "forces/ElectroChemicalScales.H"

#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <cmath>
#include <iostream>
#include <random>

using namespace suspension;

namespace
{
    const double rho = 1e-3;        // St (eq. 11)

    using test::allModels;

    //- Random spheres at volume fraction phi, small overlaps allowed
    Particles randomParticles(const Vec3& L, int n, double a2, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> u(0, 1);
        Particles p;
        for (int i = 0; i < n; ++i)
        {
            const double a = (i % 2) ? a2 : 1.0;
            p.add(Vec3(u(gen)*L.x(), u(gen)*L.y(), u(gen)*L.z()), a, rho, i);
            p.u.back() = Vec3(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5);
            p.omega.back() = Vec3(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5);
        }
        return p;
    }

    Simulation::Params simParams()
    {
        Simulation::Params s;
        s.rho = rho;
        s.maxOverlap = 10;   // random boxes overlap: no runaway check here
        return s;
    }
}


TEST(Simulation, PairForcesCancelSoTotalForceIsTheDrag)
{
    const Vec3 L(12, 12, 12);
    LeesEdwardsBox box(L, 1.0);
    const ShearFlow flow(1.0, 2.0, 1.0, L.y());
    Simulation sim(randomParticles(L, 300, 1.4, 1), box, flow, allModels(), simParams());
    sim.start(0.37);
    ASSERT_GT(sim.summary().nContacts, 0u);

    const Particles& p = sim.particles();
    const StokesDrag drag;
    Vec3 F = Vec3::Zero();
    Vec3 Fdrag = Vec3::Zero();
    double scale = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        F += p.F[i];
        Fdrag += drag.eval(p.a[i], p.u[i], p.omega[i], flow.sample(p.x[i])).F;
        scale += p.F[i].norm();
    }
    EXPECT_LT((F - Fdrag).norm(), 1e-12*scale);
}


TEST(Simulation, ForcesAndStressBitwiseIndependentOfThreadCount)
{
    // Every loop threaded however small the system (core/Parallel.H), and
    // the results bitwise the same for 1 to 4 threads
    const Vec3 L(12, 12, 12);
    LeesEdwardsBox box(L, 1.0);
    const ShearFlow flow(1.0);
    const Particles start = randomParticles(L, 300, 1.4, 2);

    const std::size_t threshold = setParallelMinParticles(0);
    const int threads = omp_get_max_threads();
    std::vector<Particles> result;
    std::vector<Rheology> stress;
    for (int nt : {1, 2, 3, 4})
    {
        omp_set_num_threads(nt);
        Simulation sim(start, box, flow, allModels(), simParams());
        sim.start(0.1);
        for (int s = 0; s < 5; ++s) sim.step(1e-7);
        result.push_back(sim.particles());
        stress.push_back(sim.rheology());
    }
    omp_set_num_threads(threads);
    setParallelMinParticles(threshold);

    for (std::size_t r = 1; r < result.size(); ++r)
    {
        EXPECT_EQ(result[0].id, result[r].id) << r + 1 << " threads";
        EXPECT_EQ(result[0].x, result[r].x) << r + 1 << " threads";
        EXPECT_EQ(result[0].u, result[r].u) << r + 1 << " threads";
        EXPECT_EQ(result[0].F, result[r].F) << r + 1 << " threads";
        EXPECT_EQ(result[0].T, result[r].T) << r + 1 << " threads";
        EXPECT_EQ(result[0].omega, result[r].omega) << r + 1 << " threads";
        EXPECT_EQ(stress[0].Sigma, stress[r].Sigma) << r + 1 << " threads";
    }
}


namespace
{
    //- Shear flow that counts its samples since the engine last called
    //  sampled(), and records that count at each call
    class CountingFlow
    :
        public ShearFlow
    {
    public:

        using ShearFlow::ShearFlow;

        mutable std::atomic<std::size_t> samples{0};
        mutable std::vector<std::size_t> perCheck;

        FlowSample sample(const Vec3& x, double gammaDot) const override
        {
            ++samples;
            return ShearFlow::sample(x, gammaDot);
        }

        void sampled(const Particles&) const override
        {
            perCheck.push_back(samples.exchange(0));
        }
    };
}


TEST(Simulation, FlowIsCheckedAfterEverySamplingLoop)
{
    // A flow known on part of space only (a mesh) cannot stop the run from
    // the threads that sample it: the engine calls sampled() after every
    // loop over the particles, each of which sampled all of them once
    const Vec3 L(12, 12, 12);
    LeesEdwardsBox box(L, 1.0);
    const CountingFlow flow(1.0, 2.0, 1.0, L.y());
    const std::size_t threshold = setParallelMinParticles(0);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(2);
    {
        Simulation sim
        (
            randomParticles(L, 300, 1.4, 3), box, flow, allModels(), simParams()
        );
        sim.start(0.1);
        for (int s = 0; s < 3; ++s) sim.step(1e-7);
        sim.velocityFluctuation();
    }
    omp_set_num_threads(threads);
    setParallelMinParticles(threshold);

    EXPECT_GE(flow.perCheck.size(), 5u);
    for (std::size_t k = 0; k < flow.perCheck.size(); ++k)
    {
        EXPECT_EQ(flow.perCheck[k], 300u) << "check " << k;
    }
    EXPECT_EQ(flow.samples, 0u) << "samples left unchecked";
}


TEST(Simulation, PairAcrossShearedBoundaryFeelsTheSameAsUnwrapped)
{
    const Vec3 L(10, 10, 10);
    const ShearFlow flow(1.0);
    const ForceModels models = allModels();

    // The same pair twice: once inside the box, once straddling y = 0
    // with a Lees-Edwards offset. Relative position (0.3, 2.15, 0.2),
    // relative velocity beyond the affine flow (0.1, -0.2, 0.05).
    auto pairForce = [&](const Vec3& xi, double t)
    {
        LeesEdwardsBox box(L, 1.0);
        box.setStrain(box.shearRate()*(t));
        Vec3 xj = xi + Vec3(0.3, 2.15, 0.2);
        Vec3 uj = Vec3(xj.y(), 0, 0) + Vec3(0.1, -0.2, 0.05);
        Particles p;
        p.add(xi, 1.0, rho, 0);
        p.add(xj, 1.1, rho, 1);
        p.u[0] = Vec3(xi.y(), 0, 0);
        p.u[1] = uj;
        box.wrap(p.x[1], p.u[1]);
        Simulation sim(p, box, flow, models, simParams());
        sim.start(t, false, Simulation::Shear{t, 1.0});
        const Particles& q = sim.particles();
        const std::size_t i = q.id[0] == 0 ? 0 : 1;
        return std::make_pair(q.F[i], q.T[i]);
    };

    const auto inside = pairForce(Vec3(5, 4, 5), 0.37);
    const auto across = pairForce(Vec3(5, 8.5, 5), 0.37);
    // Drag differs only through U_inf - u, which is the same
    EXPECT_LT((inside.first - across.first).norm(), 1e-9*inside.first.norm());
    EXPECT_LT((inside.second - across.second).norm(), 1e-9*(1 + inside.second.norm()));
}


TEST(Simulation, LoneSphereInWavyFlowMovesWithFaxenVelocity)
{
    const Vec3 L(8, 8, 8);
    LeesEdwardsBox box(L, 1.0);
    const ShearFlow flow(1.0, 3.0, 1.0, L.y());
    Particles p;
    const double a = 1.2;
    p.add(Vec3(2, 3.1, 4), a, rho, 0);
    ForceModels models;
    models.set(FrictionalContact(FrictionalContact::fromGroups(4e5, 2.0/7.0, 1e-7, 1.0)));
    Simulation sim(p, box, flow, models, simParams());
    sim.start(0);
    sim.advance(0.02);     // ~ 60 drag relaxation times
    const Vec3 x = sim.particles().x[0];
    const FlowSample f = flow.sample(x);
    // Force-free: u = U + a^2/6 lap U (Faxen), omega = Omega
    const Vec3 expected = f.U + a*a/6*f.laplacianU;
    EXPECT_LT((sim.particles().u[0] - expected).norm(), 1e-6*expected.norm());
    EXPECT_LT((sim.particles().omega[0] - f.Omega()).norm(), 1e-6);
    // and the Faxen correction is not negligible here
    EXPECT_GT((a*a/6*f.laplacianU).norm(), 0.1);
    // The velocity fluctuation is the Faxen slip |a^2/6 lap U|^2
    const double slip2 = (a*a/6*f.laplacianU).squaredNorm();
    EXPECT_NEAR(sim.velocityFluctuation(), slip2, 1e-5*slip2);
}


TEST(Simulation, DiluteSuspensionGivesEinsteinViscosity)
{
    const Vec3 L(30, 30, 30);
    LeesEdwardsBox box(L, 1.0);
    const ShearFlow flow(1.0);
    // phi ~ 0.02 without overlaps: spheres on a jittered lattice
    Particles p;
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> jitter(-1, 1);
    const int n = 5;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                p.add(Vec3(6*i + 3 + jitter(gen), 6*j + 3 + jitter(gen), 6*k + 3 + jitter(gen)), 1.0, rho, p.size());
    p.add(Vec3(1, 1, 1), 0.5, rho, 999);
    const double phi = p.solidVolume()/box.volume();
    ForceModels models;
    models.set(FrictionalContact(FrictionalContact::fromGroups(4e5, 2.0/7.0, 1e-7, 1.0)));
    Simulation sim(p, box, flow, models, simParams());
    sim.start(0);
    sim.advance(0.01);
    EXPECT_NEAR(sim.rheology().etaR, 1 + 2.5*phi, 0.01*(1 + 2.5*phi));
    EXPECT_GT(phi, 0.018);
}


TEST(Simulation, ContactStressIsTheVirialOfTheContactForce)
{
    const Vec3 L(10, 10, 10);
    LeesEdwardsBox box(L, 0.0);
    const ShearFlow flow(0.0);
    ForceModels models;
    const FrictionalContact::Params c = FrictionalContact::fromGroups(1e3, 2.0/7.0, 0.0, 1.0);
    models.set(FrictionalContact(c));
    Particles p;
    p.add(Vec3(4, 5, 5), 1.0, rho, 0);
    p.add(Vec3(5.6, 5.8, 5.3), 1.0, rho, 1);       // |r| = 1.8136, overlap 0.186
    Simulation sim(p, box, flow, models, simParams());
    sim.start(0);

    // By hand: F on i = kn h n with h = |r| - 2, r_ij = x_i - x_j
    const Vec3 rji = Vec3(1.6, 0.8, 0.3);
    const double h = rji.norm() - 2;
    const Vec3 Fi = c.kn*h*rji/rji.norm();
    const Mat3 expected = -(-rji)*Fi.transpose()/box.volume();
    const Mat3 Sc = sim.summary().stresslet[contributionIndex("contact")]/box.volume();
    EXPECT_LT((Sc - expected).norm(), 1e-12*expected.norm());
    // A repulsive contact gives a positive pressure
    EXPECT_GT(-Sc.trace()/3, 0);
}


TEST(Simulation, SqueezeStepLimitIsTheStabilityEdge)
{
    // Two touching spheres, lubrication only: the explicit scheme is
    // stable just below the computed limit and unstable just above it
    ForceModels models;
    models.set(Lubrication(test::lubrication(1e-2, 0.5)));
    const TimeStepLimits limits(models, 1.0, 1.0, rho, 1.0);
    EXPECT_EQ(limits.binding().name, "lubrication");

    auto maxSpeed = [&](double factor)
    {
        const Vec3 L(20, 20, 20);
        LeesEdwardsBox box(L, 0.0);
        const ShearFlow flow(0.0);
        Particles p;
        p.add(Vec3(10, 10, 10), 1.0, rho, 0);
        p.add(Vec3(12.0, 10, 10), 1.0, rho, 1);
        p.u[0] = Vec3(1e-3, 0, 0);
        p.u[1] = Vec3(-1e-3, 0, 0);
        Simulation::Params s = simParams();
        s.deltaT = factor*limits.binding().value;
        Simulation sim(p, box, flow, models, s);
        sim.start(0);
        // An unstable squeeze grows until the gap it opens weakens it:
        // look at the largest relative speed on the way
        double maxSpeed = 0;
        for (int k = 0; k < 100; ++k)
        {
            sim.step(s.deltaT);
            maxSpeed = std::max(maxSpeed, (sim.particles().u[1] - sim.particles().u[0]).norm());
        }
        return maxSpeed;
    };
    EXPECT_LT(maxSpeed(0.9), 2e-3);
    EXPECT_GT(maxSpeed(1.1), 1e-2);
}


TEST(Simulation, AdvanceTakesFullStepsAndAShorterLastOne)
{
    // An interval of 2.1 steps is two steps of deltaT() and one of 0.1
    // deltaT(), bitwise the same as taking them one by one, and lands on the
    // end of the interval exactly
    const Vec3 L(12, 12, 12);
    LeesEdwardsBox box(L, 1.0);
    const ShearFlow flow(1.0);
    const Particles p = randomParticles(L, 60, 1.4, 11);
    Simulation::Params params = simParams();
    params.deltaT = 1e-4;
    Simulation a(p, box, flow, allModels(), params);
    Simulation b(p, box, flow, allModels(), params);
    a.start(0);
    b.start(0);
    const double dt = a.deltaT();
    ASSERT_EQ(dt, 1e-4);
    // The interval rounded once, as the caller hands it to advance(): the
    // last step is then interval - 2 dt with 2 dt exact, however the
    // compiler contracts the products (FMA)
    const double interval = 2.1*dt;
    a.advance(interval);
    b.step(dt);
    b.step(dt);
    b.step(interval - 2*dt);
    EXPECT_EQ(a.steps(), 3u);
    EXPECT_EQ(a.time(), interval);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        EXPECT_EQ(a.particles().x[i], b.particles().x[i]) << "particle " << i;
        EXPECT_EQ(a.particles().u[i], b.particles().u[i]) << "particle " << i;
    }
    // A whole number of steps takes no extra step of round-off size
    a.advance(3*dt);
    EXPECT_EQ(a.steps(), 6u);
}


namespace
{
    //- A flow a coupled solver updates between outer steps: a wave of
    //  amplitude that can be changed (ShearFlow, eq. 17)
    class ChangingFlow
    :
        public test::ForwardingFlow
    {
        double gammaDot_;
        double Ly_;
        ShearFlow flow_;

        const AmbientFlow& base() const override { return flow_; }

    public:

        ChangingFlow(double gammaDot, double Ly)
        :
            gammaDot_(gammaDot), Ly_(Ly), flow_(gammaDot)
        {}

        void setAmplitude(double A) { flow_ = ShearFlow(gammaDot_, A, 1, Ly_); }
    };
}


TEST(Simulation, ChangedFlowContinuesAsARestartInTheNewFlow)
{
    // A run whose flow changes at t continues as a run started at t in
    // the new flow from the same state: bitwise, for the explicit and the
    // implicit integrator (the implicit operator holds ambient forces).
    // Without flowChanged() the implicit engine goes on with samples of
    // the old flow (the two then differ); the step limits follow the
    // flow's new bound on |grad U|. Frictionless with stiff springs
    // (k_hat 5e6), the implicit integrator's automatic choice of implicit
    // normal springs flips in the wave: their limit is below half of
    // lubricationGap = 25 epsilon/max|grad U| in uniform shear, not in the
    // wave; the run continues with the integrator a run started there has
    const Vec3 L(12, 12, 12);
    const ForceModels stiffFrictionless = test::lubricatedContacts(0.25, 5e6, 0);
    const std::pair<Integrator, bool> cases[] =
    {
        {Integrator::velocityVerlet, false},
        {Integrator::implicitEuler, false},
        {Integrator::implicitEuler, true}
    };
    for (const auto& [integrator, flips] : cases)
    {
        const std::string name =
            (integrator == Integrator::velocityVerlet ? "velocityVerlet" : "implicitEuler")
          + std::string(flips ? ", stiff frictionless" : "");
        const ForceModels models = flips ? stiffFrictionless : allModels();
        Simulation::Params params = simParams();
        params.integrator = integrator;
        // random spheres overlap: the explicit step resolves their contacts
        params.deltaT = integrator == Integrator::velocityVerlet ? 1e-7 : 1e-5;
        const double interval = 20*params.deltaT;

        // The state at t, reached in uniform shear
        ChangingFlow uniform(1.0, L.y());
        Simulation first
        (
            randomParticles(L, 200, 1.4, 7), LeesEdwardsBox(L, 1.0), uniform,
            models, params
        );
        first.start(0);
        first.advance(interval);
        Simulation::Checkpoint at;
        first.checkpoint(at);
        const std::vector<TimeStepLimit> before = first.limits().all();

        // Two runs on from t whose flow becomes a wave there: told, not told
        ChangingFlow toldFlow(1.0, L.y());
        ChangingFlow notToldFlow(1.0, L.y());
        Simulation told(at.particles, LeesEdwardsBox(L, 1.0), toldFlow, models, params);
        Simulation notTold(at.particles, LeesEdwardsBox(L, 1.0), notToldFlow, models, params);
        told.restore(at);
        notTold.restore(at);
        toldFlow.setAmplitude(40);
        notToldFlow.setAmplitude(40);
        told.flowChanged();
        told.advance(interval);
        notTold.advance(interval);

        // A run started at t in the wave
        ChangingFlow wave(1.0, L.y());
        wave.setAmplitude(40);
        Simulation fresh(at.particles, LeesEdwardsBox(L, 1.0), wave, models, params);
        fresh.restore(at);
        fresh.advance(interval);

        EXPECT_EQ(told.particles().x, fresh.particles().x) << name;
        EXPECT_EQ(told.particles().u, fresh.particles().u) << name;
        EXPECT_EQ(told.steps(), fresh.steps()) << name;
        EXPECT_EQ(told.implicitNormalContact(), fresh.implicitNormalContact()) << name;
        if (flips)
        {
            EXPECT_NE(told.implicitNormalContact(), first.implicitNormalContact())
                << name << ": the automatic choice does not flip in the wave";
        }
        if (integrator == Integrator::implicitEuler && !flips)
        {
            // Its first solve used the old flow's samples (velocity Verlet
            // moves first with the forces it carries, as told and fresh do)
            EXPECT_NE(notTold.particles().x, fresh.particles().x) << name;
        }

        ASSERT_EQ(told.limits().all().size(), fresh.limits().all().size()) << name;
        for (std::size_t l = 0; l < told.limits().all().size(); ++l)
        {
            const TimeStepLimit& c = told.limits().all()[l];
            EXPECT_EQ(c.name, fresh.limits().all()[l].name) << name;
            EXPECT_EQ(c.value, fresh.limits().all()[l].value) << name << ' ' << c.name;
            for (const TimeStepLimit& b : before)
            {
                if (c.name == "lubricationGap" && b.name == c.name)
                {
                    EXPECT_LT(c.value, b.value)
                        << "the accuracy limit of the faster flow is shorter";
                }
            }
        }
    }
}
