// Runs decomposed over P ranks (decomposition/Domain.H), threads standing
// in for processes (ThreadCommunicator.H), against the serial run
#include "decompositionTestTools.H"
#include "stressControlledShear.H"
#include "ThreadCommunicator.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <limits>
#include <mutex>
#include <random>

using namespace suspension;


namespace
{
    //- The run on each layout, over threads, against the serial run: the
    //  state of every rank, and ghosts on every rank of P > 1
    void expectSerialOn
    (
        std::initializer_list<Domain::Layout> layouts,
        const Particles& start,
        const Vec3& L,
        const test::RankOutcome& serial,
        const test::RunCase& run = {}
    )
    {
        for (const Domain::Layout& layout : layouts)
        {
            SCOPED_TRACE("layout " + std::to_string(layout.ny) + " x " + std::to_string(layout.nz));
            test::onRanks(layout.ny*layout.nz, [&](const Communicator& comm)
            {
                const test::RankOutcome mine = test::decomposedRun(start, L, &comm, layout, run);
                double ghosts = double(mine.ghosts);
                comm.sum(&ghosts, 1);
                EXPECT_EQ(ghosts > 0, comm.size() > 1);
                test::expectSerial(serial, mine, comm, 1e-9);
            });
        }
    }
}


TEST(Decomposition, SlabsOwnEveryPointOnce)
{
    test::onRanks(6, [](const Communicator& comm)
    {
        const Vec3 L(5, 7, 3);
        const Domain d(comm, {3, 2}, L);
        std::mt19937 gen(1);
        std::uniform_real_distribution<double> u(0, 1);
        for (int k = 0; k < 1000; ++k)
        {
            const Vec3 x(u(gen)*L.x(), u(gen)*L.y(), u(gen)*L.z());
            const int q = d.owner(x);
            EXPECT_EQ(q % 3, std::min(2, int(x.y()/L.y()*3)));
            EXPECT_EQ(q/3, std::min(1, int(x.z()/L.z()*2)));
        }
        // The edges belong to the slab above
        EXPECT_EQ(d.owner(Vec3(0, 7.0/3, 0)), 1);
        EXPECT_EQ(d.owner(Vec3(0, 0, 1.5)), 3);
    });
    EXPECT_THROW
    (
        test::onRanks(2, [](const Communicator& c) { Domain(c, {3, 1}, Vec3(1, 1, 1)); }),
        std::invalid_argument
    );
}


TEST(Decomposition, ExplicitRunsGiveTheSerialTrajectory)
{
    // 100 explicit steps of a sheared Lees-Edwards box with every force
    // model, the list rebuilt (and particles migrated) within the run, on 1
    // to 4 ranks in y slabs, 2 x 2 in y and z and 3 in z; at P = 4 the
    // slabs (Ly/4 = 3) are thinner than the ghost depth
    const Vec3 L(12, 12, 12);
    const Particles start = test::decompositionParticles(L, 300, 7);
    const test::RankOutcome serial = test::decomposedRun(start, L, nullptr, {});
    ASSERT_GT(serial.nContacts, 10u);
    ASSERT_GT(serial.builds, 2u);
    expectSerialOn({{1, 1}, {2, 1}, {3, 1}, {4, 1}, {2, 2}, {1, 3}}, start, L, serial);
}


TEST(Decomposition, TheFarPassGivesTheSerialTrajectory)
{
    // The attraction to 4 a0 runs in the far pass (ForceField.H), whose
    // rows each process sums for its own particles only: 2 and 2 x 2 ranks,
    // the ghosts as deep as the far range
    const Vec3 L(21, 21, 21);
    const Particles start = test::decompositionParticles(L, 1500, 9);
    const test::RunCase far{60, 4.0};
    const test::RankOutcome serial = test::decomposedRun(start, L, nullptr, {}, far);
    ASSERT_GT(serial.nContacts, 10u);
    expectSerialOn({{2, 1}, {2, 2}}, start, L, serial, far);
}


TEST(Decomposition, ImplicitRunsGiveTheSerialTrajectory)
{
    // 20 steps of implicitEuler and of overdamped (the solve's halo and
    // sums), and 20 stress-controlled implicitEuler steps (the rate from
    // stresslets summed over the processes), on the layouts of the
    // explicit test
    const Vec3 L(12, 12, 12);
    const Particles start = test::decompositionParticles(L, 300, 7);
    const test::StressControlledShear stress(20.0, 0.0);
    const test::RunCase cases[] =
    {
        {20, 0.5, Integrator::implicitEuler, nullptr},
        {20, 0.5, Integrator::overdamped, nullptr},
        {20, 0.5, Integrator::implicitEuler, &stress}
    };
    for (const test::RunCase& run : cases)
    {
        SCOPED_TRACE
        (
            std::string(run.flow ? "stress-controlled " : "")
          + (run.integrator == Integrator::overdamped ? "overdamped" : "implicitEuler")
        );
        const test::RankOutcome serial = test::decomposedRun(start, L, nullptr, {}, run);
        ASSERT_GT(serial.nContacts, 10u);
        ASSERT_GT(serial.builds, 1u);
        expectSerialOn({{2, 1}, {3, 1}, {4, 1}, {2, 2}, {1, 3}}, start, L, serial, run);
    }
}


namespace
{
    //- Simple shear carrying the particles up at a uniform speed (a
    //  constant U_y is periodic): they cross the slabs' boundaries, and the
    //  sheared one, all the time
    class DriftingShear final : public test::ForwardingFlow
    {
        const ShearFlow shear_;

        const AmbientFlow& base() const override { return shear_; }

    public:
        static constexpr double drift = 0.5;

        DriftingShear() : shear_(1.0) {}

        FlowSample sample(const Vec3& x, double gammaDot) const override
        {
            FlowSample s = shear_.sample(x, gammaDot);
            s.U.y() += drift;
            return s;
        }
    };

    //- DriftingShear as one rank knows it: on its slab only (NaN beyond),
    //  as a flow on a decomposed mesh knows its processor's cells
    class SlabFlow final : public test::ForwardingFlow
    {
        const DriftingShear flow_;
        double lo_[2], hi_[2], L_[2];

        const AmbientFlow& base() const override { return flow_; }

        //- Periodic distance of c from [lo, hi] on a circle of length L
        static double away(double c, double lo, double hi, double L)
        {
            const double d = c < lo ? lo - c : c > hi ? c - hi : 0;
            return std::min(d, L - (hi - lo) - d);
        }

        bool known(const Vec3& x) const
        {
            for (int k = 0; k < 2; ++k)
            {
                if (away(x[k + 1], lo_[k], hi_[k], L_[k]) > 0)
                {
                    return false;
                }
            }
            return true;
        }

    public:
        SlabFlow(int rank, const Domain::Layout& layout, const Vec3& L)
        {
            const int q[2] = {rank % layout.ny, rank/layout.ny};
            const int n[2] = {layout.ny, layout.nz};
            for (int k = 0; k < 2; ++k)
            {
                L_[k] = L[k + 1];
                lo_[k] = q[k]*L_[k]/n[k];
                hi_[k] = (q[k] + 1)*L_[k]/n[k];
            }
        }

        FlowSample sample(const Vec3& x, double gammaDot) const override
        {
            if (!known(x))
            {
                FlowSample nan;
                nan.U.setConstant(std::numeric_limits<double>::quiet_NaN());
                nan.gradU.setConstant(std::numeric_limits<double>::quiet_NaN());
                return nan;
            }
            return flow_.sample(x, gammaDot);
        }
        bool sampleHere(const Vec3& x, double gammaDot, FlowSample& s) const override
        {
            s = sample(x, gammaDot);
            return known(x);
        }
        bool sampledAnywhere() const override { return false; }
    };

    //- Two spheres in contact near the top of a box L, thrown up in y
    //  together: the upper one crosses y = L (the Lees-Edwards boundary)
    //  into the bottom slab within a few steps, before a rebuild
    Particles crossingPair(const Vec3& L)
    {
        Particles p;
        p.add(Vec3(6, L.y() - 0.004, 6), 1.0, test::decompositionRho, 0);
        p.add(Vec3(6.2, L.y() - 0.004 - 1.985, 6), 1.0, test::decompositionRho, 1);
        for (Vec3& u : p.u)
        {
            u = Vec3(0, 500, 0);
        }
        return p;
    }
}


TEST(Decomposition, AFlowKnownOnEachSlabOnlyGivesTheSerialTrajectory)
{
    // Each rank samples the particles on its slab, owned or ghost; an
    // owned particle that left the slab since the last rebuild (the flow
    // carries them across, and the skin lets them go a quarter radius) is
    // sampled by the rank it moved to (its ghost there), and its ghosts
    // take its sample: explicit and implicit steps, 2 and 2 x 2 ranks;
    // then two spheres in a box twice as long in z, on 2 x 2 ranks of
    // which two hold nothing, not even ghosts (they take part in the
    // exchanges all the same)
    const Vec3 L(12, 12, 12);
    const Particles start = test::decompositionParticles(L, 300, 7);
    const DriftingShear drifting;
    {
        const Vec3 Lz(12, 12, 24);
        const test::RunCase serialRun{100, 0.5, Integrator::velocityVerlet, &drifting, 0.5};
        const test::RankOutcome serial = test::decomposedRun(crossingPair(Lz), Lz, nullptr, {}, serialRun);
        test::onRanks(4, [&](const Communicator& comm)
        {
            const SlabFlow flow(comm.rank(), {2, 2}, Lz);
            const test::RunCase run{100, 0.5, Integrator::velocityVerlet, &flow, 0.5};
            const test::RankOutcome mine = test::decomposedRun(crossingPair(Lz), Lz, &comm, {2, 2}, run);
            if (comm.rank() >= 2)
            {
                EXPECT_TRUE(mine.state.empty());
                EXPECT_EQ(mine.ghosts, 0u);
            }
            test::expectSerial(serial, mine, comm, 1e-9);
        });
    }
    for (const Integrator integrator : {Integrator::velocityVerlet, Integrator::implicitEuler})
    {
        SCOPED_TRACE(integrator == Integrator::velocityVerlet ? "velocityVerlet" : "implicitEuler");
        const test::RunCase serialRun{20, 0.5, integrator, &drifting, 0.5};
        const test::RankOutcome serial = test::decomposedRun(start, L, nullptr, {}, serialRun);
        for (const Domain::Layout layout : {Domain::Layout{2, 1}, Domain::Layout{2, 2}})
        {
            test::onRanks(layout.ny*layout.nz, [&](const Communicator& comm)
            {
                const SlabFlow flow(comm.rank(), layout, L);
                const test::RunCase run{20, 0.5, integrator, &flow, 0.5};
                test::expectSerial(serial, test::decomposedRun(start, L, &comm, layout, run), comm, 1e-9);
            });
        }
    }
}


TEST(Decomposition, AContactCrossingAProcessAndTheShearedBoundaryKeepsItsHistory)
{
    // Two spheres in contact, thrown up in y together: the upper one
    // crosses y = L (the Lees-Edwards boundary) into the slab of the other
    // process while the lower one stays, so the contact ends between two
    // processes and across the sheared boundary; its stretch, carried by
    // the lower id, is the serial run's, held once
    const Vec3 L(12, 12, 12);
    const Particles start = crossingPair(L);
    const test::RunCase run{100, 0.5, Integrator::velocityVerlet, nullptr};
    const test::RankOutcome serial = test::decomposedRun(start, L, nullptr, {}, run);
    ASSERT_EQ(serial.nContacts, 1u);
    ASSERT_EQ(serial.contacts.size(), 1u);
    EXPECT_GT(serial.contacts.begin()->second.xiT.norm(), 0);
    ASSERT_LT(serial.state.at(0)[0].y(), 1.0) << "the upper sphere wrapped";
    ASSERT_GT(serial.state.at(1)[0].y(), L.y()/2) << "the lower one did not";
    test::onRanks(2, [&](const Communicator& comm)
    {
        const test::RankOutcome mine = test::decomposedRun(start, L, &comm, {2, 1}, run);
        // Sphere 0 ends on process 0, sphere 1 on process 1
        EXPECT_EQ(mine.state.count(comm.rank() == 0 ? 0 : 1), 1u);
        test::expectSerial(serial, mine, comm, 1e-9);
    });
}


TEST(Decomposition, AFailureOnOneProcessStopsEveryProcess)
{
    // One particle's velocity not finite, in the middle of the slab of
    // process 0 (farther than the ghost depth from the other's): only
    // process 0 sees it, and every process stops with a SimulationError
    // at the start (the check is collective), none runs on into a
    // collective alone
    const Vec3 L(12, 24, 12);
    Particles start = test::decompositionParticles(L, 600, 7);
    start.x[5] = Vec3(6, 6, 6);
    start.u[5].y() = std::numeric_limits<double>::quiet_NaN();
    std::vector<int> stopped(2, 0);
    test::onRanks(2, [&](const Communicator& comm)
    {
        Particles mine;
        for (std::size_t i = comm.rank(); i < start.size(); i += 2)
        {
            mine.add(start.x[i], start.a[i], test::decompositionRho, start.id[i]);
            mine.u.back() = start.u[i];
        }
        Simulation::Params params;
        params.rho = test::decompositionRho;
        params.maxOverlap = 10;
        const ShearFlow flow(1.0);
        Simulation sim
        (
            mine, LeesEdwardsBox(L, 1.0), flow, test::allModels(), params,
            Decomposition{&comm, {2, 1}}
        );
        try
        {
            sim.start(0);
        }
        catch (const SimulationError&)
        {
            stopped[comm.rank()] = 1;
        }
    });
    EXPECT_EQ(stopped, std::vector<int>({1, 1}));
}


TEST(Decomposition, SameLayoutTwiceIsBitwiseTheSame)
{
    const Vec3 L(12, 12, 12);
    const Particles start = test::decompositionParticles(L, 300, 8);
    std::vector<test::RankOutcome> a(3), b(3);
    test::onRanks(3, [&](const Communicator& comm)
    {
        a[comm.rank()] = test::decomposedRun(start, L, &comm, {3, 1}, {60});
    });
    test::onRanks(3, [&](const Communicator& comm)
    {
        b[comm.rank()] = test::decomposedRun(start, L, &comm, {3, 1}, {60});
    });
    for (int r = 0; r < 3; ++r)
    {
        ASSERT_EQ(a[r].state.size(), b[r].state.size());
        for (const auto& [id, s] : a[r].state)
        {
            const auto& t = b[r].state.at(id);
            EXPECT_TRUE(s[0] == t[0] && s[1] == t[1] && s[2] == t[2]) << id;
        }
        EXPECT_TRUE(a[r].stress == b[r].stress);
    }
}
