// Neighbour search (paper section 2.1): cell stencils against brute force
// under Lees-Edwards boundaries, the Verlet skin and the contact history
#include "flow/ShearFlow.H"
#include "search/NeighbourSearch.H"
#include "core/Parallel.H"
#include "core/Scratch.H"

#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <utility>

using namespace suspension;

namespace
{
    using IdPair = std::pair<std::int64_t, std::int64_t>;
    using PairSet = std::set<IdPair>;

    IdPair key(std::int64_t a, std::int64_t b)
    {
        return {std::min(a, b), std::max(a, b)};
    }

    //- The pairs of a list as (id_lo, id_hi); fails on self or repeated pairs
    PairSet idPairs(const Particles& p, const PairList& list)
    {
        EXPECT_EQ(list.nParticles(), p.size());
        // A cell search gives no history; the neighbour search's near list
        // one per slot, and a transposed index that holds every slot once
        // under its partner, in slot order
        EXPECT_TRUE(list.contactOf.empty() || list.contactOf.size() == list.nPairs());
        if (!list.slotT.empty())
        {
            EXPECT_EQ(list.slotT.size(), list.nPairs());
            std::vector<int> seen(list.nPairs(), 0);
            for (std::size_t j = 0; j < list.nParticles(); ++j)
            {
                for (std::uint32_t t = list.offsetT[j]; t < list.offsetT[j + 1]; ++t)
                {
                    const std::uint32_t k = list.slotT[t];
                    EXPECT_EQ(list.j[k], j);
                    EXPECT_TRUE(t == list.offsetT[j] || list.slotT[t - 1] < k);
                    ++seen[k];
                }
            }
            EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), long(list.nPairs()));
        }
        PairSet pairs;
        for (std::size_t i = 0; i < list.nParticles(); ++i)
        {
            for (std::size_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
            {
                const std::int64_t a = p.id[i];
                const std::int64_t b = p.id[list.j[k]];
                EXPECT_NE(a, b);
                EXPECT_TRUE(pairs.insert(key(a, b)).second)
                    << "pair (" << a << ", " << b << ") listed twice";
            }
        }
        return pairs;
    }

    //- Pairs within a_i + a_j + gap found by `stencil` (on a copy)
    PairSet pairsBy(Particles p, const LeesEdwardsBox& box, double gap, Stencil stencil)
    {
        PairList list;
        if (stencil == Stencil::bruteForce)
        {
            bruteForcePairs(p, box, gap, list);
        }
        else
        {
            CellList cells(box, 2*p.maxRadius() + gap);
            p.permute(cells.sort(p.x));
            cells.findPairs(p, box, gap, stencil, list);
        }
        return idPairs(p, list);
    }

    //- Pairs within a_i + a_j + gap from every image (m boxes up, kx, kz),
    //  independent of LeesEdwardsBox::minimumImage
    PairSet explicitImages(const Particles& p, const LeesEdwardsBox& box, double gap)
    {
        const Vec3& L = box.L();
        PairSet pairs;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            for (std::size_t j = i + 1; j < p.size(); ++j)
            {
                const double R = p.a[i] + p.a[j] + gap;
                for (int m = -1; m <= 1; ++m)
                for (int kx = -2; kx <= 2; ++kx)
                for (int kz = -1; kz <= 1; ++kz)
                {
                    const Vec3 image = p.x[j]
                      + Vec3(m*box.offset() + kx*L.x(), m*L.y(), kz*L.z());
                    if ((image - p.x[i]).norm() < R)
                    {
                        pairs.insert(key(p.id[i], p.id[j]));
                    }
                }
            }
        }
        return pairs;
    }

    //- Pairs whose in-range image lies across the sheared boundary
    std::size_t crossingPairs(const Particles& p, const PairSet& pairs, const Vec3& L)
    {
        std::map<std::int64_t, double> y;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            y[p.id[i]] = p.x[i].y();
        }
        std::size_t n = 0;
        for (const IdPair& ab : pairs)
        {
            n += std::abs(y[ab.first] - y[ab.second]) > 0.5*L.y();
        }
        return n;
    }

    //- N spheres at random positions in the box, radii from radius()
    template<class Radius>
    Particles randomParticles(const Vec3& L, std::size_t N, Radius radius, std::mt19937& gen)
    {
        std::uniform_real_distribution<double> u(0, 1);
        Particles p;
        for (std::size_t i = 0; i < N; ++i)
        {
            p.add(Vec3(u(gen)*L.x(), u(gen)*L.y(), u(gen)*L.z()), radius(gen), 1.0, 1000 + 7*i);
        }
        return p;
    }

    //- Index of the particle with permanent label id
    std::size_t indexOf(const Particles& p, std::int64_t id)
    {
        return std::find(p.id.begin(), p.id.end(), id) - p.id.begin();
    }

    //- Slot of pair (a, b) and whether it is stored as (a, b); -1 if absent
    std::pair<long, bool> slotOf(const Particles& p, const PairList& list, std::int64_t a, std::int64_t b)
    {
        for (std::size_t i = 0; i < list.nParticles(); ++i)
        {
            for (std::size_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
            {
                if (key(p.id[i], p.id[list.j[k]]) == key(a, b))
                {
                    return {static_cast<long>(k), p.id[i] == a};
                }
            }
        }
        return {-1, false};
    }

    bool equal(const ContactState& s, const ContactState& t)
    {
        return s.xiT == t.xiT && s.xiR == t.xiR;
    }

    ContactState negated(const ContactState& s)
    {
        return ContactState{-s.xiT, -s.xiR};
    }

    const ContactState someStretch{Vec3(0.01, -0.02, 0.03), Vec3(-0.004, 0.005, 0.006)};
}


TEST(CellList, BruteForceMatchesExplicitImages)
{
    std::mt19937 gen(1);
    const Vec3 L(9.1, 8.3, 7.7);
    LeesEdwardsBox box(L, 1.0);
    std::uniform_real_distribution<double> radius(0.5, 1.2);
    const Particles p = randomParticles(L, 250, radius, gen);
    for (double delta : {0.0, 2.9, 6.35, 9.0999})
    {
        box.setOffset(delta);
        const PairSet brute = pairsBy(p, box, 0.3, Stencil::bruteForce);
        EXPECT_EQ(brute, explicitImages(p, box, 0.3)) << "offset " << delta;
        EXPECT_GT(crossingPairs(p, brute, L), 0u);
    }
}


TEST(CellList, StencilsAgreeWithBruteForce)
{
    std::mt19937 gen(2);
    const double gap = 0.3;
    for (double ratio : {1.0, 1.4, 3.0, 10.0})
    {
        const double R = 2*ratio + gap;
        // 3, 4 and 5 cells across, non-cubic
        const Vec3 L(3.2*R, 4.1*R, 5.3*R);
        const std::size_t N = ratio < 5 ? 600 : 1500;
        std::uniform_real_distribution<double> u(0, 1);
        auto bidisperse = [&](std::mt19937& g) { return u(g) < 0.1 ? ratio : 1.0; };
        auto polydisperse = [&](std::mt19937& g) { return 1 + (ratio - 1)*u(g)*u(g); };
        const Particles samples[] =
        {
            randomParticles(L, N, bidisperse, gen),
            randomParticles(L, N, polydisperse, gen)
        };

        CellList lattice(LeesEdwardsBox(L, 1), R);
        const double h = lattice.cellSize().x();
        const double offsets[] =
            {0, h, 2*h, 0.5*h, u(gen)*L.x(), u(gen)*L.x(), u(gen)*L.x(), L.x()*(1 - 1e-12)};

        for (const Particles& p : samples)
        {
            for (double delta : offsets)
            {
                LeesEdwardsBox box(L, 1);
                box.setOffset(delta);
                const PairSet brute = pairsBy(p, box, gap, Stencil::bruteForce);
                EXPECT_GT(crossingPairs(p, brute, L), 0u);
                EXPECT_EQ(pairsBy(p, box, gap, Stencil::half), brute)
                    << "ratio " << ratio << ", offset " << delta;
                EXPECT_EQ(pairsBy(p, box, gap, Stencil::full), brute)
                    << "ratio " << ratio << ", offset " << delta;
            }
        }
    }
}


TEST(CellList, StencilsAgreeAfterManyWraps)
{
    std::mt19937 gen(3);
    const Vec3 L(11.3, 10.1, 9.7);
    const double gammaDot = 1;
    LeesEdwardsBox box(L, gammaDot);
    std::uniform_real_distribution<double> radius(1.0, 1.4);
    Particles p = randomParticles(L, 500, radius, gen);
    std::normal_distribution<double> jitter(0, 1.0);

    const double dt = 0.01;
    int crossings = 0;
    for (int step = 1; step <= 600; ++step)        // 6 strain units
    {
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            p.u[i] = Vec3(gammaDot*p.x[i].y() + jitter(gen), jitter(gen), jitter(gen));
            p.x[i] += dt*p.u[i];
        }
        box.setStrain(box.shearRate()*(step*dt));
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            crossings += std::abs(box.wrap(p.x[i], p.u[i]));
        }
        if (step % 40 == 0)
        {
            const PairSet brute = pairsBy(p, box, 0.2, Stencil::bruteForce);
            EXPECT_EQ(pairsBy(p, box, 0.2, Stencil::half), brute) << "step " << step;
            EXPECT_EQ(pairsBy(p, box, 0.2, Stencil::full), brute) << "step " << step;
        }
    }
    EXPECT_GT(crossings, 50);
}


TEST(CellList, ListIndependentOfThreadCount)
{
    std::mt19937 gen(4);
    const Vec3 L(25, 24, 23);
    LeesEdwardsBox box(L, 1);
    box.setOffset(4.321);
    std::uniform_real_distribution<double> radius(1.0, 1.4);
    Particles p = randomParticles(L, parallelMinParticles() + 400, radius, gen);
    CellList cells(box, 2*1.4 + 0.2);
    p.permute(cells.sort(p.x));

    const int threads = omp_get_max_threads();
    for (Stencil s : {Stencil::half, Stencil::full, Stencil::bruteForce})
    {
        PairList one, many;
        omp_set_num_threads(1);
        cells.findPairs(p, box, 0.2, s, one);
        omp_set_num_threads(4);
        cells.findPairs(p, box, 0.2, s, many);
        EXPECT_EQ(one.offset, many.offset);
        EXPECT_EQ(one.j, many.j);
    }
    omp_set_num_threads(threads);
}


TEST(CellList, SortGroupsParticlesByCell)
{
    std::mt19937 gen(5);
    const Vec3 L(10, 12, 14);
    LeesEdwardsBox box(L, 1);
    std::uniform_real_distribution<double> radius(1.0, 1.0);
    Particles p = randomParticles(L, 400, radius, gen);
    CellList cells(box, 2.5);
    EXPECT_EQ(cells.nCells(), Eigen::Vector3i(3, 4, 5));   // 10/2.5 = 4 is too few: cells exceed R

    const std::vector<std::size_t> order = cells.sort(p.x);
    std::vector<std::size_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::size_t> identity(p.size());
    std::iota(identity.begin(), identity.end(), 0);
    EXPECT_EQ(sorted, identity);

    // unsorted particles are refused
    PairList list;
    EXPECT_THROW(cells.findPairs(p, box, 0.5, Stencil::half, list), std::logic_error);

    // after permuting, each cell is one contiguous run
    p.permute(order);
    std::set<std::array<int, 3>> seen;
    std::array<int, 3> previous{-1, -1, -1};
    for (const Vec3& x : p.x)
    {
        const std::array<int, 3> c
        {
            int(x.x()/cells.cellSize().x()),
            int(x.y()/cells.cellSize().y()),
            int(x.z()/cells.cellSize().z())
        };
        if (c != previous)
        {
            EXPECT_TRUE(seen.insert(c).second) << "cell split into two runs";
            previous = c;
        }
    }
    EXPECT_NO_THROW(cells.findPairs(p, box, 0.5, Stencil::half, list));
}


TEST(CellList, TooSmallBoxThrows)
{
    const double R = 2.3;
    EXPECT_NO_THROW(CellList(LeesEdwardsBox(Vec3(6.91, 6.91, 6.91), 1), R));
    for (const Vec3& L : {Vec3(6.8, 20, 20), Vec3(20, 6.8, 20), Vec3(20, 20, 6.8)})
    {
        try
        {
            CellList(LeesEdwardsBox(L, 1), R);
            ADD_FAILURE() << "no exception";
        }
        catch (const std::invalid_argument& e)
        {
            const std::string what = e.what();
            EXPECT_NE(what.find("box (" + std::to_string(L.x())), std::string::npos) << what;
            EXPECT_NE(what.find("cut-off 2.3"), std::string::npos) << what;
        }
    }

    // through the search: a = 1, gap + skin = 0.3 -> R = 2.3
    Particles p;
    p.add(Vec3(1, 1, 1), 1.0, 1.0, 0);
    PairList list;
    NeighbourSearch search({0.1, 0.2});
    EXPECT_THROW
    (
        search.update(p, LeesEdwardsBox(Vec3(6, 10, 10), 1), list),
        std::invalid_argument
    );
}


TEST(CellList, ParticleOutsideBoxThrows)
{
    LeesEdwardsBox box(Vec3(10, 10, 10), 1);
    CellList cells(box, 3);
    EXPECT_THROW(cells.sort({Vec3(1, 10, 1)}), std::invalid_argument);
    EXPECT_THROW(cells.sort({Vec3(-1e-12, 1, 1)}), std::invalid_argument);
    EXPECT_NO_THROW(cells.sort({Vec3(0, 9.999999, 0)}));
}


TEST(NeighbourSearch, SkinListHoldsEveryPairInRange)
{
    std::mt19937 gen(6);
    const Vec3 L(12.5, 11.5, 10.5);
    const ShearFlow flow(1.0, 0.5, 1, L.y());       // wavy: |grad U| up to 1.27
    const double G = flow.maxVelocityGradient(1.0);
    LeesEdwardsBox box(L, 1.0);
    std::uniform_real_distribution<double> u(0, 1);
    auto radius = [&](std::mt19937& g) { return u(g) < 0.5 ? 1.0 : 1.4; };
    Particles p = randomParticles(L, 250, radius, gen);

    const double gap = 0.1;
    NeighbourSearch search({gap, 0.3});
    PairList list;
    ASSERT_TRUE(search.update(p, box, list));

    // non-affine velocities by permanent id, redrawn every 10 steps, with a
    // drift in y that carries particles across the sheared boundary
    std::normal_distribution<double> noise(0, 0.5);
    std::map<std::int64_t, Vec3> v;
    std::vector<Vec3> Uinf(p.size());

    const double dt = 0.002;
    std::size_t checked = 0;
    int crossings = 0;
    for (int step = 1; step <= 600; ++step)
    {
        if (step % 10 == 1)
        {
            for (std::int64_t id : p.id)
            {
                v[id] = Vec3(noise(gen), 1 + noise(gen), noise(gen));
            }
        }
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            p.u[i] = flow.sample(p.x[i], box.shearRate()).U + v[p.id[i]];
            p.x[i] += dt*p.u[i];
        }
        box.setStrain(box.shearRate()*(step*dt));
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            crossings += std::abs(box.wrap(p.x[i], p.u[i]));
            Uinf[i] = flow.sample(p.x[i], box.shearRate()).U;
        }
        search.accumulate(p, Uinf, dt, G);

        if (!search.needsRebuild())
        {
            // the old list still holds every pair in true range
            const PairSet listed = idPairs(p, list);
            for (const IdPair& ab : pairsBy(p, box, gap, Stencil::bruteForce))
            {
                EXPECT_TRUE(listed.count(ab)) << "step " << step << ": pair ("
                    << ab.first << ", " << ab.second << ") missing";
            }
            ++checked;
        }
        if (search.update(p, box, list))
        {
            // a fresh list is exactly the pairs within range + skin
            EXPECT_EQ(idPairs(p, list), pairsBy(p, box, gap + 0.3, Stencil::bruteForce));
        }
    }
    const std::size_t builds = search.statistics().builds;
    EXPECT_GT(builds, 10u);
    EXPECT_GT(checked, 5*builds);                   // the skin saves rebuilds
    EXPECT_GT(crossings, 10);
}


TEST(NeighbourSearch, CriterionCatchesWorstCaseApproach)
{
    // Two spheres start just outside range + skin and approach as fast as
    // the criterion allows: head-on with opposite non-affine velocities
    // (|r| closes at 2V, the criterion's 2 max l), and in shear along the
    // compressional axis across the sheared boundary (|r| closes at
    // gammaDot |r|/2, half the criterion's G R). The pair must be listed
    // whenever it is within a_1 + a_2 + gap and no rebuild is due.
    const Vec3 L(12, 12, 12);
    const double gap = 0.1, skin = 0.2, start = 2 + gap + skin + 1e-3;
    struct Case { double gammaDot; Vec3 xA; Vec3 r; Vec3 vA; };
    const Case cases[] =
    {
        {0, Vec3(6, 6, 6), Vec3(start, 0, 0), Vec3(1, 0, 0)},
        {1, Vec3(6, 11.2, 6), start/std::sqrt(2.0)*Vec3(-1, 1, 0), Vec3::Zero()}
    };
    for (const Case& c : cases)
    {
        LeesEdwardsBox box(L, c.gammaDot);
        const ShearFlow flow(c.gammaDot);
        Particles p;
        p.add(c.xA, 1.0, 1.0, 1);
        p.add(c.xA + c.r, 1.0, 1.0, 2);
        box.wrap(p.x[1], p.u[1]);
        NeighbourSearch search({gap, skin});
        PairList list;
        search.update(p, box, list);

        const double dt = 1e-3;
        std::vector<Vec3> Uinf(2);
        int inRange = 0;
        for (int step = 1; step <= 1000; ++step)
        {
            for (std::size_t i = 0; i < 2; ++i)
            {
                const Vec3 v = p.id[i] == 1 ? c.vA : Vec3(-c.vA);
                p.u[i] = flow.sample(p.x[i], box.shearRate()).U + v;
                p.x[i] += dt*p.u[i];
            }
            box.setStrain(box.shearRate()*(step*dt));
            for (std::size_t i = 0; i < 2; ++i)
            {
                box.wrap(p.x[i], p.u[i]);
                Uinf[i] = flow.sample(p.x[i], box.shearRate()).U;
            }
            search.accumulate(p, Uinf, dt, c.gammaDot);
            Vec3 r = p.x[1] - p.x[0];
            box.minimumImage(r);
            if (r.norm() < 2 + gap && !search.needsRebuild())
            {
                EXPECT_GE(slotOf(p, list, 1, 2).first, 0) << "step " << step;
                ++inRange;
            }
            search.update(p, box, list);
        }
        EXPECT_GT(inRange, 100);
    }
}


TEST(NeighbourSearch, RebuildCriterion)
{
    Particles p;
    p.add(Vec3(1, 1, 1), 1.0, 1.0, 0);
    p.add(Vec3(5, 5, 5), 1.0, 1.0, 1);
    const LeesEdwardsBox box(Vec3(10, 10, 10), 1);
    NeighbourSearch search({0.1, 0.2});           // R = 2.3
    PairList list;
    EXPECT_TRUE(search.needsRebuild());
    EXPECT_TRUE(search.update(p, box, list));
    EXPECT_DOUBLE_EQ(search.range(), 2.3);
    EXPECT_FALSE(search.update(p, box, list));

    // affine motion only: G R t = 0.2 at t = 0.2/2.3 for G = 1, reached
    // in two steps of G = 2 and 0.5 (a rate that changes)
    const std::vector<Vec3> U = p.u;
    search.accumulate(p, U, 0.99*0.1/2.3, 2.0);     // 0.198
    EXPECT_FALSE(search.update(p, box, list));
    search.accumulate(p, U, 0.01*0.2/2.3, 0.5);     // 0.199
    EXPECT_FALSE(search.update(p, box, list));
    search.accumulate(p, U, 0.02*0.2/2.3, 0.5);     // 0.201
    EXPECT_TRUE(search.update(p, box, list));
    EXPECT_EQ(search.timeSinceBuild(), 0);

    // non-affine path: 2 l = 0.2 at l = 0.1, accumulated in two legs
    p.u[1] = Vec3(0, 0, 1);
    search.accumulate(p, U, 0.06, 0.0);
    EXPECT_DOUBLE_EQ(search.maxPath(), 0.06);
    EXPECT_FALSE(search.update(p, box, list));
    p.u[1] = Vec3(0, -1, 0);                        // turning back still counts
    search.accumulate(p, U, 0.05, 0.0);
    EXPECT_TRUE(search.update(p, box, list));
    EXPECT_EQ(search.statistics().builds, 3u);

    // a list of other particles is refused; a cleared one is rebuilt
    p.add(Vec3(8, 8, 8), 1.0, 1.0, 2);
    EXPECT_THROW(search.update(p, box, list), std::invalid_argument);
    EXPECT_THROW(search.accumulate(p, p.u, 0.01, -1.0), std::invalid_argument);
    list = PairList();
    EXPECT_TRUE(search.update(p, box, list));
    EXPECT_EQ(list.nParticles(), 3u);
}


TEST(NeighbourSearch, HistoryFollowsIdsThroughResort)
{
    const Vec3 L(12, 12, 12);
    for (Stencil stencil : {Stencil::half, Stencil::full})
    {
        std::mt19937 gen(7);
        LeesEdwardsBox box(L, 1);
        box.setOffset(5.1);
        std::uniform_real_distribution<double> radius(1.0, 1.0);
        Particles p = randomParticles(L, 400, radius, gen);
        NeighbourSearch search({0.1, 0.3, stencil});
        PairList list;
        search.rebuild(p, box, list);

        // a random stretch on half of the slots; expected state from lo to hi
        std::normal_distribution<double> n(0, 1);
        std::map<IdPair, ContactState> expected;
        std::map<IdPair, bool> fromLo;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            for (std::size_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
            {
                const std::int64_t a = p.id[i], b = p.id[list.j[k]];
                fromLo[key(a, b)] = a < b;
                if (k % 2 == 0)
                {
                    list.setHistory(k, ContactState{Vec3(n(gen), n(gen), n(gen)), Vec3(n(gen), n(gen), n(gen))});
                    expected[key(a, b)] = a < b ? list.history(k) : negated(list.history(k));
                }
            }
        }

        // small moves (many change cells) and a new offset, then a rebuild
        std::uniform_real_distribution<double> d(-0.4, 0.4);
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            p.x[i] += Vec3(d(gen), d(gen), d(gen));
            box.wrap(p.x[i], p.u[i]);
        }
        box.setOffset(7.3);
        search.rebuild(p, box, list);

        std::size_t carried = 0, flipped = 0;
        const PairSet pairs = idPairs(p, list);
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            for (std::size_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
            {
                const std::int64_t a = p.id[i], b = p.id[list.j[k]];
                const auto it = expected.find(key(a, b));
                if (it == expected.end())
                {
                    EXPECT_TRUE(equal(list.history(k), ContactState()));
                    continue;
                }
                ++carried;
                flipped += fromLo[key(a, b)] != (a < b);
                EXPECT_TRUE(equal(list.history(k), a < b ? it->second : negated(it->second)))
                    << "pair (" << a << ", " << b << ")";
            }
        }
        std::size_t dropped = 0;
        for (const auto& e : expected)
        {
            dropped += !pairs.count(e.first);
        }
        EXPECT_EQ(search.statistics().carried, carried);
        EXPECT_EQ(search.statistics().dropped, dropped);
        EXPECT_EQ(carried + dropped, expected.size());
        EXPECT_GT(carried, 100u);
        EXPECT_GT(flipped, 0u);
    }
}


TEST(NeighbourSearch, ContactAcrossShearedBoundaryKeepsStretch)
{
    // A near the top, B touching it through the sheared boundary (B's image
    // above is at A + r); the pair is then carried around the box
    const Vec3 L(12, 12, 12);
    const Vec3 r(0.3, 1.9, -0.2);                   // B - A, |r| < 2
    std::mt19937 gen(8);
    std::uniform_real_distribution<double> radius(1.0, 1.0);
    Particles p = randomParticles(L, 60, radius, gen);
    p.add(Vec3::Zero(), 1.0, 1.0, 1);               // A
    p.add(Vec3::Zero(), 1.0, 1.0, 2);               // B

    LeesEdwardsBox box(L, 1);
    auto place = [&](const Vec3& A)
    {
        Vec3 xA = A, xB = A + r, uA = Vec3::Zero(), uB = Vec3::Zero();
        box.wrap(xA, uA);
        box.wrap(xB, uB);
        p.x[indexOf(p, 1)] = xA;
        p.x[indexOf(p, 2)] = xB;
    };

    box.setOffset(3.7);
    place(Vec3(6, 11.5, 6));
    ASSERT_GT(p.x[indexOf(p, 2)].y(), 0);
    ASSERT_LT(p.x[indexOf(p, 2)].y(), 1.5);         // B wrapped to the bottom

    NeighbourSearch search({0.1, 0.2});
    PairList list;
    search.rebuild(p, box, list);
    auto [slot, fromA] = slotOf(p, list, 1, 2);
    ASSERT_GE(slot, 0);
    list.setHistory(slot, fromA ? someStretch : negated(someStretch));

    // offsets and pair positions, across y = 0 and x = 0 and back inside
    const std::pair<double, Vec3> moves[] =
    {
        {3.7, Vec3(6, 11.5, 6)},        // re-sort in place
        {8.15, Vec3(0.2, 11.0, 11.9)},  // other offset, across x and z too
        {8.15, Vec3(6, 5, 6)},          // inside
        {1.234, Vec3(11.9, -1.0, 0.1)}, // A below the bottom: B inside
        {11.99, Vec3(3, 10.4, 3)}       // offset close to Lx
    };
    for (const auto& [delta, A] : moves)
    {
        box.setOffset(delta);
        place(A);
        search.rebuild(p, box, list);
        std::tie(slot, fromA) = slotOf(p, list, 1, 2);
        ASSERT_GE(slot, 0) << "offset " << delta;
        EXPECT_TRUE(equal(list.history(slot), fromA ? someStretch : negated(someStretch)));
        EXPECT_EQ(search.statistics().carried, 1u);
        EXPECT_EQ(search.statistics().dropped, 0u);

        // geometry: the listed pair's minimum image is r
        Vec3 d = p.x[indexOf(p, 2)] - p.x[indexOf(p, 1)];
        box.minimumImage(d);
        EXPECT_NEAR((d - r).norm(), 0, 1e-12);
    }
}


TEST(NeighbourSearch, StretchFlipsWhenPairComesBackReversed)
{
    // A below B in the next cell row: the half stencil lists (A, B) from A's
    // layer above; with A and B swapped it lists (B, A)
    const LeesEdwardsBox box(Vec3(12, 12, 12), 1);   // cells of 2.4
    Particles p;
    p.add(Vec3(6, 4.5, 6), 1.0, 1.0, 1);             // A, row 1
    p.add(Vec3(6.2, 6.4, 6), 1.0, 1.0, 2);           // B, row 2
    p.add(Vec3(1, 1, 1), 1.0, 1.0, 3);

    NeighbourSearch search({0.1, 0.2});
    PairList list;
    search.rebuild(p, box, list);
    auto [slot, fromA] = slotOf(p, list, 1, 2);
    ASSERT_GE(slot, 0);
    ASSERT_TRUE(fromA);
    list.setHistory(slot, someStretch);

    std::swap(p.x[indexOf(p, 1)], p.x[indexOf(p, 2)]);
    search.rebuild(p, box, list);
    std::tie(slot, fromA) = slotOf(p, list, 1, 2);
    ASSERT_GE(slot, 0);
    ASSERT_FALSE(fromA);
    EXPECT_TRUE(equal(list.history(slot), negated(someStretch)));

    // and back
    std::swap(p.x[indexOf(p, 1)], p.x[indexOf(p, 2)]);
    search.rebuild(p, box, list);
    std::tie(slot, fromA) = slotOf(p, list, 1, 2);
    ASSERT_TRUE(fromA);
    EXPECT_TRUE(equal(list.history(slot), someStretch));
}


TEST(NeighbourSearch, SeparatedPairLosesHistory)
{
    const LeesEdwardsBox box(Vec3(12, 12, 12), 1);
    Particles p;
    p.add(Vec3(6, 6, 6), 1.0, 1.0, 1);
    p.add(Vec3(7.95, 6, 6), 1.0, 1.0, 2);
    NeighbourSearch search({0.1, 0.2});
    PairList list;
    search.rebuild(p, box, list);
    list.setHistory(slotOf(p, list, 1, 2).first, someStretch);

    // still within range + skin: kept
    p.x[indexOf(p, 2)] = Vec3(8.25, 6, 6);
    search.rebuild(p, box, list);
    ASSERT_GE(slotOf(p, list, 1, 2).first, 0);
    EXPECT_EQ(search.statistics().carried, 1u);

    // beyond a_1 + a_2 + gap + skin = 2.3: dropped and counted
    p.x[indexOf(p, 2)] = Vec3(8.31, 6, 6);
    search.rebuild(p, box, list);
    EXPECT_LT(slotOf(p, list, 1, 2).first, 0);
    EXPECT_EQ(search.statistics().dropped, 1u);
    EXPECT_EQ(search.statistics().totalDropped, 1u);

    // back in contact: a fresh contact
    p.x[indexOf(p, 2)] = Vec3(7.95, 6, 6);
    search.rebuild(p, box, list);
    const long slot = slotOf(p, list, 1, 2).first;
    ASSERT_GE(slot, 0);
    EXPECT_TRUE(equal(list.history(slot), ContactState()));
    EXPECT_EQ(search.statistics().carried, 0u);
}


TEST(NeighbourSearch, HistoryMemoryFollowsContactsNotSlots)
{
    // 300 spheres, a list of ~1000 slots with 3 contacts: the list costs
    // 8 bytes per particle (offsets), 12 per slot (partner, transposed
    // slot, contact index) and 48 per contact (PairList.H), not 48 per slot
    std::mt19937 gen(9);
    const Vec3 L(12, 12, 12);
    std::uniform_real_distribution<double> radius(1.0, 1.0);
    Particles p = randomParticles(L, 300, radius, gen);
    NeighbourSearch search({0.1, 0.2});
    PairList list;
    search.rebuild(p, LeesEdwardsBox(L, 1), list);
    ASSERT_GT(list.nPairs(), 500u);
    for (std::size_t k : {0ul, list.nPairs()/2, list.nPairs() - 1})
    {
        list.setHistory(k, ContactState{Vec3(1e-3, 0, 0), Vec3::Zero()});
    }
    EXPECT_EQ(list.nContacts(), 3u);
    const std::size_t slotBytes = 3*sizeof(std::uint32_t);
    const std::size_t expected =
        2*(p.size() + 1)*sizeof(std::uint32_t) + list.nPairs()*slotBytes
      + list.contacts.capacity()*sizeof(ContactState);
    EXPECT_EQ(list.bytes(), expected);
    EXPECT_LE(list.contacts.capacity(), 4u);
    EXPECT_LT(list.bytes(), list.nPairs()*sizeof(ContactState));

    // The search: cell offsets and a path length per particle
    EXPECT_GE(search.bytes(), p.size()*sizeof(double));
}


TEST(Scratch, GrowsByAnEighthWithoutCopyingAndNeverDoubles)
{
    // A first array is taken to size; one that grows past its capacity
    // takes an eighth more room (std::vector::resize would double it, and
    // copy the old elements while both are held); within the capacity the
    // storage stays where it is
    std::vector<double> v;
    resizeScratch(v, 1000);
    EXPECT_EQ(v.size(), 1000u);
    EXPECT_EQ(v.capacity(), 1000u);

    resizeScratch(v, 1010);
    EXPECT_EQ(v.size(), 1010u);
    EXPECT_EQ(v.capacity(), 1010u + 1010u/8);

    const double* storage = v.data();
    resizeScratch(v, 1100);
    resizeScratch(v, 500);
    EXPECT_EQ(v.data(), storage);
    EXPECT_EQ(v.size(), 500u);
    EXPECT_EQ(v.capacity(), 1010u + 1010u/8);
}
