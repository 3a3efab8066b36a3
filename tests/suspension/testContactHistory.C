// Contact history (Luding's stretches, eqs. 5 and B.1) through the
// neighbour-list rebuilds of a sheared run: the engine's own steps
// (velocity Verlet, eq. 15; Lees-Edwards wraps, eq. 16; NeighbourSearch;
// ForceField::advance) with a small skin, and at every rebuild the active
// contacts, keyed by the permanent ids of their pairs, before and after
#include "dynamics/VelocityVerlet.H"
#include "flow/ShearFlow.H"
#include "forces/ForceField.H"
#include "packing/RandomPacking.H"
#include "packing/SizeDistribution.H"
#include "search/NeighbourSearch.H"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <utility>

using namespace suspension;

namespace
{
    using IdPair = std::pair<std::int64_t, std::int64_t>;

    //- A contact of the list: its state oriented from the lower id, and
    //  whether the slot runs from the lower id
    struct Contact
    {
        ContactState state;
        bool fromLo;
    };

    //- The slots with a contact history, keyed by (lower id, higher id);
    //  fails when a pair holds two slots
    std::map<IdPair, Contact> activeContacts(const Particles& p, const PairList& list)
    {
        std::map<IdPair, Contact> contacts;
        for (std::size_t i = 0; i < list.nParticles(); ++i)
        {
            for (std::size_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
            {
                const ContactState& s = list.history(k);
                if (!s.active())
                {
                    continue;
                }
                const std::int64_t a = p.id[i];
                const std::int64_t b = p.id[list.j[k]];
                const IdPair key{std::min(a, b), std::max(a, b)};
                const Contact c{a < b ? s : ContactState{-s.xiT, -s.xiR}, a < b};
                EXPECT_TRUE(contacts.emplace(key, c).second)
                    << "pair (" << key.first << ", " << key.second << ") holds two histories";
            }
        }
        return contacts;
    }

    //- Every slot appears once: no pair listed twice, whatever its history
    void expectPairsOnce(const Particles& p, const PairList& list)
    {
        std::map<IdPair, int> count;
        for (std::size_t i = 0; i < list.nParticles(); ++i)
        {
            for (std::size_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
            {
                const std::int64_t a = p.id[i];
                const std::int64_t b = p.id[list.j[k]];
                const IdPair key{std::min(a, b), std::max(a, b)};
                EXPECT_EQ(++count[key], 1)
                    << "pair (" << a << ", " << b << ") listed twice";
            }
        }
    }
}


TEST(ContactHistory, CarriedThroughEveryRebuildOfAShearedRun)
{
    // 150 spheres (radii 1.0 and 1.4) packed at phi = 0.45, then sheared
    // with random non-affine velocities (rho = 3: they persist for about a
    // time unit, m/(6 pi eta a), so spheres cross the sheared boundary).
    // Frictional contacts with rolling resistance, stiff enough to keep
    // the overlaps small (up to ~0.1 a); skin 0.1, so the list is rebuilt
    // every few steps. At every rebuild: the same (id pair -> stretch) of the active
    // contacts before and after, bit for bit (reversed slots carry the
    // negated state, checked by orienting from the lower id), nothing
    // dropped, no pair twice. After every advance() a contact history
    // belongs to a pair that overlaps (eq. 5: none out of contact).
    const double rho = 3;
    const std::vector<double> radii = SizeDistribution::bidisperse(1, 1.4, 1).radii(150);
    RandomPacking::Params pack;
    pack.phi = 0.45;
    pack.seed = 4;
    pack.reach = 0.1;       // the run's: contacts only (gap 0), skin 0.1
    RandomPacking::Result packed = RandomPacking(pack).pack(radii, rho);
    Particles& p = packed.particles;
    LeesEdwardsBox box(packed.box.L(), 1.0);
    const ShearFlow flow(1.0);

    std::mt19937 gen(12);
    std::normal_distribution<double> noise(0, 0.5);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        p.u[i] = flow.sample(p.x[i], box.shearRate()).U + Vec3(noise(gen), noise(gen), noise(gen));
        p.omega[i] = Vec3(noise(gen), noise(gen), noise(gen));
    }

    FrictionalContact::Params c = FrictionalContact::fromGroups(5e4, 2.0/7.0, 1e-3, 0.5);
    c.kr = 0.1*c.kn;
    c.muR = 0.3;
    ForceModels models;
    models.set(FrictionalContact(c));
    ForceField field(models, p.a);
    NeighbourSearch search({field.nearGap(), 0.1});
    PairList near;

    // dt: 1/30 of the shortest contact time of the smaller spheres
    const double m = p.m[0];
    const double dt = FrictionalContact::contactTimeScale(c, m, 1.0, m, 1.0)/30;
    const int nSteps = 1500;

    search.rebuild(p, box, near);
    field.advance(p, box, flow, near, search.far(), 0);

    std::size_t rebuilds = 0, carried = 0, reversed = 0, acrossSheared = 0;
    std::size_t maxContacts = 0;
    int crossings = 0;
    std::vector<Vec3> Uinf(p.size());
    for (int step = 1; step <= nSteps; ++step)
    {
        // Simulation::step of velocity Verlet, with a look at the list
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            Uinf[i] = field.ambient()[i].U;
        }
        search.accumulate(p, Uinf, dt, flow.maxVelocityGradient(box.shearRate()));
        box.setStrain(box.shearRate()*(step*dt));
        std::vector<double> y(p.size());
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            y[i] = p.x[i].y();
        }
        VelocityVerlet::predict(p, box, dt);
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            crossings += std::abs(p.x[i].y() - y[i]) > box.L().y()/2;
        }

        const std::map<IdPair, Contact> before = activeContacts(p, near);
        if (search.update(p, box, near))
        {
            ++rebuilds;
            expectPairsOnce(p, near);
            const std::map<IdPair, Contact> after = activeContacts(p, near);
            EXPECT_EQ(after.size(), before.size()) << "step " << step;
            EXPECT_EQ(search.statistics().dropped, 0u) << "step " << step;
            EXPECT_EQ(search.statistics().carried, before.size()) << "step " << step;
            for (const auto& [ids, b] : before)
            {
                const auto it = after.find(ids);
                if (it == after.end())
                {
                    ADD_FAILURE() << "step " << step << ": contact (" << ids.first
                        << ", " << ids.second << ") lost by the rebuild";
                    continue;
                }
                const ContactState& a = it->second.state;
                EXPECT_TRUE(a.xiT == b.state.xiT && a.xiR == b.state.xiR)
                    << "step " << step << ": contact (" << ids.first << ", "
                    << ids.second << ") xiT " << b.state.xiT.transpose() << " -> "
                    << a.xiT.transpose() << ", xiR " << b.state.xiR.transpose()
                    << " -> " << a.xiR.transpose();
                reversed += it->second.fromLo != b.fromLo;
            }
            carried += before.size();
        }

        field.advance(p, box, flow, near, search.far(), dt);
        VelocityVerlet::correct(p, dt);

        // Every history belongs to an overlapping pair
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            for (std::size_t k = near.offset[i]; k < near.offset[i + 1]; ++k)
            {
                if (near.history(k).active())
                {
                    Vec3 r = p.x[near.j[k]] - p.x[i];
                    const int image = box.minimumImage(r);
                    EXPECT_LT(r.norm(), p.a[i] + p.a[near.j[k]])
                        << "step " << step << ": history of a separated pair ("
                        << p.id[i] << ", " << p.id[near.j[k]] << ")";
                    acrossSheared += image != 0;
                }
            }
        }
        maxContacts = std::max(maxContacts, activeContacts(p, near).size());
    }

    // The run did what the test needs
    EXPECT_EQ(search.statistics().builds, rebuilds + 1);
    EXPECT_GT(rebuilds, 100u);
    EXPECT_EQ(search.statistics().totalDropped, 0u);
    EXPECT_GT(maxContacts, 20u);
    EXPECT_GT(carried, 1000u);
    EXPECT_GT(reversed, 0u);            // slots that came back from the other side
    EXPECT_GT(acrossSheared, 0u);       // contacts through the sheared boundary
    EXPECT_GT(crossings, 10);           // wraps across y = 0 and y = Ly
}
