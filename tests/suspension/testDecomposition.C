// Runs decomposed over P ranks (decomposition/Domain.H, threads standing in
// for processes: ThreadCommunicator.H) against the serial run
#include "dynamics/Simulation.H"
#include "ThreadCommunicator.H"
#include "modelTestTools.H"
#include "flow/ShearFlow.H"
#include "forces/ElectroChemicalScales.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <random>

using namespace suspension;

namespace
{
    const double rho = 1e-3;

    ForceModels allModels()
    {
        ForceModels m;
        m.set(Lubrication(test::lubrication(1e-3, 0.25)));
        FrictionalContact::Params c =
            FrictionalContact::fromGroups(4e5, 2.0/7.0, 1e-7, 1.0);
        c.kr = 0.1*c.kn;
        m.set(FrictionalContact(c));
        const ElectroChemicalScales scales({1.0, 19.0, 0.01});
        m.set(ElectrostaticRepulsion(scales.repulsion(0.02)));
        VanDerWaalsAttraction::Params att = scales.attraction();
        att.cutoffGap = 0.5;
        m.set(VanDerWaalsAttraction(att));
        return m;
    }

    //- Random spheres, small overlaps allowed, with random velocities
    Particles randomParticles(const Vec3& L, int n, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> u(0, 1);
        Particles p;
        for (int i = 0; i < n; ++i)
        {
            p.add(Vec3(u(gen)*L.x(), u(gen)*L.y(), u(gen)*L.z()), (i % 2) ? 1.4 : 1.0, rho, i);
            p.u.back() = Vec3(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5);
            p.omega.back() = Vec3(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5);
        }
        return p;
    }

    Simulation::Params params()
    {
        Simulation::Params s;
        s.rho = rho;
        s.maxOverlap = 10;      // random boxes overlap
        s.skin = 1e-4;          // rebuilds (and migrations) within the run
        return s;
    }

    //- What a run leaves: the particles by id, the contacts, the stress
    struct Outcome
    {
        std::map<std::int64_t, std::array<Vec3, 3>> state;  // x, u, omega
        std::map<std::pair<std::int64_t, std::int64_t>, ContactState> contacts;
        Mat3 stress = Mat3::Zero();
        std::size_t nContacts = 0;
        std::size_t builds = 0;
        std::size_t ghosts = 0;
    };

    void collect(const Simulation& sim, Outcome& out, std::mutex& m)
    {
        const Particles& p = sim.particles();
        const std::vector<KeyedContact> c = NeighbourSearch::contacts(p, sim.pairs());
        std::lock_guard<std::mutex> lock(m);
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            if (!p.isGhost(i))
            {
                const bool fresh =
                    out.state.emplace(p.id[i], std::array<Vec3, 3>{p.x[i], p.u[i], p.omega[i]}).second;
                EXPECT_TRUE(fresh) << "particle " << p.id[i] << " owned twice";
            }
        }
        for (const KeyedContact& k : c)
        {
            const bool fresh = out.contacts.emplace(std::make_pair(k.lo, k.hi), k.state).second;
            EXPECT_TRUE(fresh) << "contact " << k.lo << "-" << k.hi << " carried twice";
        }
        out.stress = sim.rheology().Sigma;
        out.nContacts = sim.summary().nContacts;
        out.builds = sim.search().statistics().builds;
        out.ghosts += sim.domain() ? sim.domain()->nGhosts() : 0;
    }

    //- Run `steps` automatic steps from `start` on a layout (none: serial);
    //  each rank starts from every P-th particle, so the start migrates
    Outcome run
    (
        const Particles& start,
        const Vec3& L,
        const Domain::Layout& layout,
        int steps,
        bool serial
    )
    {
        Outcome out;
        std::mutex m;
        const ShearFlow flow(1.0);
        auto body = [&](const Communicator* comm)
        {
            Particles mine;
            const int P = comm ? comm->size() : 1;
            const int r = comm ? comm->rank() : 0;
            for (std::size_t i = r; i < start.size(); i += P)
            {
                mine.add(start.x[i], start.a[i], rho, start.id[i]);
                mine.u.back() = start.u[i];
                mine.omega.back() = start.omega[i];
            }
            const LeesEdwardsBox box(L, 1.0);
            Simulation sim
            (
                mine, box, flow, allModels(), params(),
                comm ? Decomposition{comm, layout} : Decomposition{}
            );
            sim.start(0);
            sim.advance(steps*sim.deltaT());
            collect(sim, out, m);
        };
        if (serial)
        {
            body(nullptr);
        }
        else
        {
            test::onRanks(layout.ny*layout.nz, [&](const Communicator& c) { body(&c); });
        }
        return out;
    }

    void expectSame(const Outcome& serial, const Outcome& run, double tol)
    {
        ASSERT_EQ(run.state.size(), serial.state.size());
        double scale = 0;
        for (const auto& [id, s] : serial.state)
        {
            scale = std::max(scale, s[1].norm());
        }
        for (const auto& [id, s] : serial.state)
        {
            const auto& d = run.state.at(id);
            EXPECT_LT((d[0] - s[0]).norm(), tol) << "x of " << id;
            EXPECT_LT((d[1] - s[1]).norm(), tol*scale) << "u of " << id;
            EXPECT_LT((d[2] - s[2]).norm(), tol*scale) << "omega of " << id;
        }
        ASSERT_EQ(run.contacts.size(), serial.contacts.size());
        for (const auto& [pair, c] : serial.contacts)
        {
            const ContactState& d = run.contacts.at(pair);
            EXPECT_LT((d.xiT - c.xiT).norm(), tol*(1 + c.xiT.norm()));
            EXPECT_LT((d.xiR - c.xiR).norm(), tol*(1 + c.xiR.norm()));
        }
        EXPECT_EQ(run.nContacts, serial.nContacts);
        EXPECT_EQ(run.builds, serial.builds);
        EXPECT_LT((run.stress - serial.stress).norm(), tol*serial.stress.norm());
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
    // 100 explicit steps of a Lees-Edwards box with every force model, the
    // list rebuilt (and particles migrated) within the run, on 1 to 4 ranks
    // in y slabs and on 2 x 2 in y and z; slabs thinner than the ghost depth
    // at P = 4 (Ly/4 = 3 < R)
    const Vec3 L(12, 12, 12);
    const Particles start = randomParticles(L, 300, 7);
    const Outcome serial = run(start, L, {}, 100, true);
    ASSERT_GT(serial.nContacts, 10u);
    ASSERT_GT(serial.builds, 2u);
    for (const Domain::Layout layout : {Domain::Layout{1, 1}, {2, 1}, {3, 1}, {4, 1}, {2, 2}, {1, 3}})
    {
        SCOPED_TRACE("layout " + std::to_string(layout.ny) + " x " + std::to_string(layout.nz));
        const Outcome decomposed = run(start, L, layout, 100, false);
        if (layout.ny*layout.nz > 1)
        {
            EXPECT_GT(decomposed.ghosts, 0u);
        }
        expectSame(serial, decomposed, 1e-9);
    }
}


TEST(Decomposition, SameLayoutTwiceIsBitwiseTheSame)
{
    const Vec3 L(12, 12, 12);
    const Particles start = randomParticles(L, 300, 8);
    const Outcome a = run(start, L, {3, 1}, 60, false);
    const Outcome b = run(start, L, {3, 1}, 60, false);
    ASSERT_EQ(a.state.size(), b.state.size());
    for (const auto& [id, s] : a.state)
    {
        const auto& t = b.state.at(id);
        EXPECT_TRUE(s[0] == t[0] && s[1] == t[1] && s[2] == t[2]) << id;
    }
    EXPECT_TRUE(a.stress == b.stress);
}
