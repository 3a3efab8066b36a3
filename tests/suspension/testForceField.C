// The pair loop (ForceField, eqs. 2-9): stored forces of a fixed
// configuration for every combination of pair models that can be on
// together, the same against a brute-force double loop over the kernels,
// the half and full stencils, 1-4 threads bitwise, a write-read round trip
// of the state, per-particle stresslets against the bulk (eq. 8), and
// evaluate() read only
#include "core/Parallel.H"
#include "flow/ShearFlow.H"
#include "forces/ForceField.H"
#include "search/NeighbourSearch.H"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

using namespace suspension;

namespace
{
    const double rho = 1.0;         // masses play no part in the forces
    const double skin = 0.2;        // Verlet skin of every list here

    // * * * * * * * * * * * * * * * The models * * * * * * * * * * * * * * //

    enum class Contact { none, frictional, criticalLoad };
    enum class Attraction { none, near, far };

    //- Parameters chosen so that every model's forces on the fixture lie
    //  within ~1e3 of the largest: a tolerance relative to the largest
    //  force then sees each of them
    FrictionalContact::Params springs()
    {
        FrictionalContact::Params c;
        c.kn = 100;
        c.kt = 30;
        c.gammaN = 2;
        c.muC = 0.5;
        c.kr = 10;
        c.muR = 0.3;
        return c;
    }

    //- A set of pair models that can be on together (contact models are
    //  alternatives); the attraction is cut at 0.5 (near pass) or at 1.5
    //  (> farPassMinGap and every other gap: far pass)
    struct Combination
    {
        bool lubrication;
        Contact contact;
        bool repulsion;
        Attraction attraction;

        std::string name() const
        {
            std::string s = "stokesDrag";
            if (lubrication) s += std::string("+") + Lubrication::typeName;
            if (contact == Contact::frictional) s += std::string("+") + FrictionalContact::typeName;
            if (contact == Contact::criticalLoad) s += std::string("+") + CriticalLoadContact::typeName;
            if (repulsion) s += std::string("+") + ElectrostaticRepulsion::typeName;
            if (attraction == Attraction::near) s += std::string("+") + VanDerWaalsAttraction::typeName + "(near)";
            if (attraction == Attraction::far) s += std::string("+") + VanDerWaalsAttraction::typeName + "(far)";
            return s;
        }

        ForceModels models() const
        {
            ForceModels m;
            if (lubrication)
            {
                Lubrication::Params lub;
                lub.epsilon = 1e-2;
                lub.deltaLub = 0.25;
                m.set(Lubrication(lub));
            }
            if (contact == Contact::frictional)
            {
                m.set(FrictionalContact(springs()));
            }
            if (contact == Contact::criticalLoad)
            {
                m.set(CriticalLoadContact({springs(), 1.5}));
            }
            if (repulsion)
            {
                m.set(ElectrostaticRepulsion({2.0, 0.05, 8}));      // gap 0.4
            }
            if (attraction != Attraction::none)
            {
                const double cutoff = attraction == Attraction::far ? 1.5 : 0.5;
                m.set(VanDerWaalsAttraction({0.5, 0.1, cutoff}));
            }
            return m;
        }
    };

    //- Every combination: 2 x 3 x 2 x 3 = 36
    std::vector<Combination> combinations()
    {
        std::vector<Combination> all;
        for (const bool lub : {false, true})
            for (const Contact c : {Contact::none, Contact::frictional, Contact::criticalLoad})
                for (const bool rep : {false, true})
                    for (const Attraction att : {Attraction::none, Attraction::near, Attraction::far})
                        all.push_back({lub, c, rep, att});
        return all;
    }

    //- Index of model M in the registry (PairModels)
    template<class M>
    std::size_t registryIndex()
    {
        std::size_t k = 0;
        std::size_t index = 0;
        forEachPairModelType([&](auto tag)
        {
            if (std::is_same_v<typename decltype(tag)::type, M>) index = k;
            ++k;
        });
        return index;
    }

    //- Every model on, the contact frictional, the attraction as given
    Combination everyModel(Attraction attraction)
    {
        return {true, Contact::frictional, true, attraction};
    }


    // * * * * * * * * * * * * * * * The fixture * * * * * * * * * * * * * * //

    using IdPair = std::pair<std::int64_t, std::int64_t>;

    //- A number in [-0.5, 0.5) from an integer: the fractional part of k
    //  times the golden ratio. Exact IEEE arithmetic, so the fixture is the
    //  same with every compiler and standard library (the distributions of
    //  <random> are not)
    double wobble(int k)
    {
        const double t = 0.6180339887498949*k;
        return t - std::floor(t) - 0.5;
    }

    ContactState negated(const ContactState& s)
    {
        return ContactState{-s.xiT, -s.xiR};
    }

    //- 17 spheres of radii 1.0 and 1.4 in a Lees-Edwards box with offset
    //  5.3, in wavy shear (E differs between the spheres of a pair). The
    //  gaps h of the pairs cover every range of the models: contacts above
    //  and below the critical load, h = 0, lubrication, repulsion only,
    //  attraction in the near and in the far range, and pairs listed but
    //  out of range; pairs across the sheared boundary (contact,
    //  lubrication, far attraction) and across x and z. Velocities and
    //  spins differ from the flow; the contacts carry stretches of about
    //  the size of their Coulomb caps (some capped, some not).
    struct Fixture
    {
        LeesEdwardsBox box;
        ShearFlow flow;
        Particles particles;                        // ids not in order
        std::map<IdPair, ContactState> stretch;     // (lo, hi), from lo
    };

    Fixture makeFixture()
    {
        const Vec3 L(14.5, 13.8, 14.2);
        Fixture fx{LeesEdwardsBox(L, 1.0), ShearFlow(1.0, 0.3, 1, L.y()), {}, {}};
        fx.box.setOffset(5.3);

        // Unwrapped centres; `next` places a sphere at gap h from `ref`
        struct Sphere { std::int64_t id; double a; Vec3 x; };
        std::vector<Sphere> s;
        auto at = [&](std::int64_t id, double a, const Vec3& x)
        {
            s.push_back({id, a, x});
        };
        auto next = [&](std::int64_t id, double a, std::int64_t ref, const Vec3& d, double h)
        {
            const auto r = std::find_if(s.begin(), s.end(), [&](const Sphere& q) { return q.id == ref; });
            at(id, a, r->x + (r->a + a + h)*d.normalized());
        };
        // Across the sheared boundary y = Ly (19, 31, 22 wrap to the bottom)
        at(7, 1.0, Vec3(7.0, 12.9, 7.0));
        next(19, 1.4, 7, Vec3(-0.6, 1, 0.3), -0.05);    // contact through y = Ly
        next(4, 1.0, 7, Vec3(1, 0, 0.2), 0.1);          // lubrication
        next(31, 1.4, 19, Vec3(-1, 0.4, -0.2), -0.02);  // contact through x = 0
        next(22, 1.0, 4, Vec3(0.2, 1, 0.1), 0.2);       // lubrication through y = Ly
        // Inside; 19-4 (1.38), 7-22 (1.35) far attraction through y = Ly
        at(10, 1.0, Vec3(3.0, 6.0, 4.0));
        at(13, 1.0, Vec3(5.0, 6.0, 4.0));               // h = 0 exactly
        next(1, 1.4, 10, Vec3(0, 1, 0), -0.005);        // contact below F_CL
        next(16, 1.4, 13, Vec3(0.3, -1, 0.4), 0.3);     // repulsion only
        next(25, 1.0, 16, Vec3(1, 0.2, -0.3), 0.45);    // near attraction only
        next(28, 1.0, 1, Vec3(-0.5, 0.6, -0.8), 0.8);   // far attraction
        // Across x = 0 and z = 0
        at(34, 1.4, Vec3(0.6, 3.5, 13.9));
        next(37, 1.0, 34, Vec3(-1, 0.3, 0.2), -0.03);   // contact through x and z
        next(40, 1.0, 34, Vec3(0.1, 0.2, 1), 1.2);      // far attraction through z
        next(43, 1.4, 34, Vec3(0.4, -1, -0.3), 1.6);    // far list only, through y
        next(46, 1.0, 40, Vec3(0.2, -1, -0.3), 0.15);   // lubrication
        next(49, 1.4, 25, Vec3(0.3, 1, 0.5), 0.6);      // listed at 0.5 + skin only

        int k = 0;
        for (const Sphere& q : s)
        {
            Particles& p = fx.particles;
            p.add(q.x, q.a, rho, q.id);
            p.u.back() = fx.flow.sample(q.x).U + Vec3(wobble(k), wobble(k + 1), wobble(k + 2));
            p.omega.back() = Vec3(wobble(k + 3), wobble(k + 4), wobble(k + 5));
            fx.box.wrap(p.x.back(), p.u.back());
            k += 6;
        }

        // A stretch on every contact, oriented from the lower id
        const Particles& p = fx.particles;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            for (std::size_t j = i + 1; j < p.size(); ++j)
            {
                Vec3 r = p.x[j] - p.x[i];
                fx.box.minimumImage(r);
                if (r.norm() < p.a[i] + p.a[j])
                {
                    const int lo = int(std::min(p.id[i], p.id[j]));
                    const int hi = int(std::max(p.id[i], p.id[j]));
                    fx.stretch[{lo, hi}] = ContactState
                    {
                        0.1*Vec3(wobble(lo), wobble(hi), wobble(lo + hi)),
                        0.1*Vec3(wobble(lo + 1), wobble(hi + 1), wobble(lo + hi + 1))
                    };
                }
            }
        }
        return fx;
    }

    //- The fixture's stretch of the pair (a, b), oriented from a
    ContactState stretchOf(const Fixture& fx, std::int64_t a, std::int64_t b)
    {
        const auto it = fx.stretch.find({std::min(a, b), std::max(a, b)});
        if (it == fx.stretch.end())
        {
            return ContactState();
        }
        return a < b ? it->second : negated(it->second);
    }


    // * * * * * * * * * * * * * * * Evaluations  * * * * * * * * * * * * * //

    //- What an evaluation gives, per particle
    struct Forces
    {
        std::vector<Vec3> F;
        std::vector<Vec3> T;
        std::vector<Mat3> S;
        ForceSummary summary;
    };

    //- The rows of `f` (particles with ids `from`) in the order of `to`
    Forces reordered
    (
        const Forces& f,
        const std::vector<std::int64_t>& from,
        const std::vector<std::int64_t>& to
    )
    {
        std::unordered_map<std::int64_t, std::size_t> index;
        for (std::size_t i = 0; i < from.size(); ++i)
        {
            index[from[i]] = i;
        }
        Forces r;
        r.summary = f.summary;
        for (const std::int64_t id : to)
        {
            const std::size_t i = index.at(id);
            r.F.push_back(f.F[i]);
            r.T.push_back(f.T[i]);
            r.S.push_back(f.S[i]);
        }
        return r;
    }

    //- ForceField::evaluate into a Forces
    Forces evaluateAll
    (
        ForceField& field,
        const Particles& p,
        const LeesEdwardsBox& box,
        const AmbientFlow& flow,
        const PairList& near,
        const PairRows& far
    )
    {
        Forces f;
        ForceField::Output out;
        out.F = &f.F;
        out.T = &f.T;
        out.S = &f.S;
        f.summary = field.evaluate(p, box, flow, near, far, out);
        return f;
    }

    //- Contact histories by (lower id, higher id), oriented from the lower
    using Histories = std::map<IdPair, ContactState>;

    //- The pair loop on the fixture: its particles sorted by the list, the
    //  near list's contacts carrying the fixture's stretches
    struct FixtureLoop
    {
        const Fixture& fx;
        Particles p;
        ForceField field;
        NeighbourSearch search;
        PairList near;

        FixtureLoop
        (
            const Fixture& fixture,
            const Combination& c,
            Stencil stencil,
            ForceField::PairPasses passes = ForceField::PairPasses::specialised
        )
        :
            fx(fixture),
            p(fixture.particles),
            field(c.models(), p.a, nullptr, passes),
            search({field.nearGap(), skin, stencil, field.farGap()}),
            near()
        {
            search.rebuild(p, fx.box, near);
            for (std::size_t i = 0; i < p.size(); ++i)
            {
                for (std::size_t k = near.offset[i]; k < near.offset[i + 1]; ++k)
                {
                    near.setHistory(k, stretchOf(fx, p.id[i], p.id[near.j[k]]));
                }
            }
        }

        //- evaluate(), rows in the fixture's order
        Forces evaluate()
        {
            const Forces f = evaluateAll(field, p, fx.box, fx.flow, near, search.far());
            return reordered(f, p.id, fx.particles.id);
        }

        //- evaluate() of the non-hydrodynamic forces (an implicit
        //  integrator's): their forces, and the linearised contacts
        Forces evaluateLinearised(std::vector<LinearisedContact>& contacts)
        {
            Forces f;
            ForceField::Output out;
            out.F = &f.F;
            out.T = &f.T;
            out.contacts = &contacts;
            f.summary = field.evaluate
            (
                p, fx.box, fx.flow, near, search.far(), out,
                ForceField::Forces::nonHydrodynamic
            );
            f.S.assign(p.size(), Mat3::Zero());
            return f;
        }

        //- advance() by dt: F and T (S zero) in the fixture's order, and
        //  the histories it keeps
        Forces advance(double dt, Histories& kept)
        {
            Forces f;
            f.summary = field.advance(p, fx.box, fx.flow, near, search.far(), dt);
            f.F = p.F;
            f.T = p.T;
            f.S.assign(p.size(), Mat3::Zero());
            for (std::size_t i = 0; i < p.size(); ++i)
            {
                for (std::size_t k = near.offset[i]; k < near.offset[i + 1]; ++k)
                {
                    const std::int64_t a = p.id[i];
                    const std::int64_t b = p.id[near.j[k]];
                    if (near.history(k).active())
                    {
                        kept[{std::min(a, b), std::max(a, b)}] =
                            a < b ? near.history(k) : negated(near.history(k));
                    }
                }
            }
            return reordered(f, p.id, fx.particles.id);
        }
    };

    //- ForceField::evaluate on the fixture, rows in the fixture's order
    Forces evaluateFixture(const Fixture& fx, const Combination& c, Stencil stencil)
    {
        return FixtureLoop(fx, c, stencil).evaluate();
    }

    //- The same without the pair loop: every pair (i, j) by a double loop
    //  with LeesEdwardsBox::minimumImage, each model's kernel called as
    //  forces/PairModel.H says while h < gap() (unprepared models: the
    //  lubrication factors computed per pair), the kinematics as eq. (3)
    //  defines them, Stokes drag per particle (A.1, 9a); the history read
    //  and advanced by dt (0: evaluate()), the active states after the
    //  step into `kept` when given
    Forces bruteForce
    (
        const Fixture& fx,
        const ForceModels& models,
        double dt = 0,
        Histories* kept = nullptr
    )
    {
        const Particles& p = fx.particles;
        const std::size_t N = p.size();
        Forces f;
        f.F.assign(N, Vec3::Zero());
        f.T.assign(N, Vec3::Zero());
        f.S.assign(N, Mat3::Zero());
        std::vector<FlowSample> U(N);
        for (std::size_t i = 0; i < N; ++i)
        {
            U[i] = fx.flow.sample(p.x[i]);
            const StokesDrag::Result d = models.drag().eval(p.a[i], p.u[i], p.omega[i], U[i]);
            f.F[i] += d.F;
            f.T[i] += d.T;
            f.S[i] += d.S;
            f.summary.stresslet[contributionIndex("stokes")] += d.S;
        }
        for (std::size_t i = 0; i < N; ++i)
        {
            for (std::size_t j = i + 1; j < N; ++j)
            {
                Vec3 r = p.x[j] - p.x[i];
                const int m = fx.box.minimumImage(r);
                const PairGeometry g = PairGeometry::make(r, p.a[i], p.a[j]);
                if (g.h < 0)
                {
                    ++f.summary.nContacts;
                    const double overlap = -g.h/std::min(g.ai, g.aj);
                    if (overlap > f.summary.maxOverlap)
                    {
                        f.summary.maxOverlap = overlap;
                        f.summary.maxOverlapPair[0] = p.id[i];
                        f.summary.maxOverlapPair[1] = p.id[j];
                    }
                }
                // The image m boxes up moves faster by m gammaDot Ly (eq. 16)
                const PairKinematics kin
                {
                    p.u[i] - U[i].U, p.u[j] - U[j].U,
                    p.omega[i] - U[i].Omega(), p.omega[j] - U[j].Omega(),
                    p.u[j] + m*fx.box.imageVelocity()*Vec3::UnitX() - p.u[i],
                    p.omega[i], p.omega[j], U[i].E(), U[j].E()
                };
                const ContactState old = stretchOf(fx, p.id[i], p.id[j]);
                models.forEach([&](const auto& model)
                {
                    using M = std::decay_t<decltype(model)>;
                    if (!(g.h < model.gap()))
                    {
                        return;
                    }
                    PairForce pf;
                    if constexpr (M::hasHistory)
                    {
                        ContactState next;
                        pf = model.eval(g, kin, old, next, dt);
                        const std::int64_t a = p.id[i];
                        const std::int64_t b = p.id[j];
                        if (kept && next.active())
                        {
                            (*kept)[{std::min(a, b), std::max(a, b)}] =
                                a < b ? next : negated(next);
                        }
                    }
                    else if constexpr (M::usesVelocities)
                    {
                        pf = model.eval(g, kin);
                    }
                    else
                    {
                        pf = model.eval(g);
                    }
                    f.F[i] += pf.F;
                    f.F[j] -= pf.F;
                    f.T[i] += pf.Ti;
                    f.T[j] += pf.Tj;
                    f.S[i] += 0.5*pf.S;
                    f.S[j] += 0.5*pf.S;
                    f.summary.stresslet[contributionIndex(M::contribution)] += pf.S;
                });
            }
        }
        return f;
    }


    // * * * * * * * * * * * * * * * Comparisons  * * * * * * * * * * * * * //

    std::string str(const Vec3& v)
    {
        std::ostringstream os;
        os.precision(17);
        os << "(" << v.x() << " " << v.y() << " " << v.z() << ")";
        return os.str();
    }

    std::string str(const Mat3& m)
    {
        return "(" + str(Vec3(m.row(0))) + " " + str(Vec3(m.row(1))) + " "
            + str(Vec3(m.row(2))) + ")";
    }

    template<class T>
    double largest(const std::vector<T>& v)
    {
        double m = 0;
        for (const T& x : v)
        {
            m = std::max(m, x.norm());
        }
        return m;
    }

    //- actual[i] within tol times the largest |expected| of expected[i]
    template<class T>
    void expectClose
    (
        const std::vector<T>& actual,
        const std::vector<T>& expected,
        double tol,
        const std::vector<std::int64_t>& ids,
        const std::string& what
    )
    {
        ASSERT_EQ(actual.size(), expected.size()) << what;
        const double bound = tol*largest(expected);
        for (std::size_t i = 0; i < actual.size(); ++i)
        {
            EXPECT_LE((actual[i] - expected[i]).norm(), bound)
                << what << " of particle " << ids[i] << ": " << str(actual[i])
                << ", expected " << str(expected[i]) << " (tolerance " << bound << ")";
        }
    }

    //- F, T and S per particle within tol of the largest of each
    void expectClose
    (
        const Forces& actual,
        const Forces& expected,
        double tol,
        const std::vector<std::int64_t>& ids,
        const std::string& what
    )
    {
        expectClose(actual.F, expected.F, tol, ids, what + ": F");
        expectClose(actual.T, expected.T, tol, ids, what + ": T");
        expectClose(actual.S, expected.S, tol, ids, what + ": S");
    }

    //- Bitwise the same forces, stresslets and summary
    void expectBitwise(const Forces& a, const Forces& b, const std::string& what)
    {
        EXPECT_EQ(a.F, b.F) << what;
        EXPECT_EQ(a.T, b.T) << what;
        EXPECT_EQ(a.S, b.S) << what;
        EXPECT_EQ(a.summary.stresslet, b.summary.stresslet) << what;
        EXPECT_EQ(a.summary.nContacts, b.summary.nContacts) << what;
        EXPECT_EQ(a.summary.maxOverlap, b.summary.maxOverlap) << what;
    }

    //- The contact state of every slot of a list
    std::vector<ContactState> histories(const PairList& list)
    {
        std::vector<ContactState> h(list.nPairs());
        for (std::size_t k = 0; k < h.size(); ++k)
        {
            h[k] = list.history(k);
        }
        return h;
    }

    bool sameState(const ContactState& a, const ContactState& b)
    {
        return a.xiT == b.xiT && a.xiR == b.xiR;
    }


    // * * * * * * * * * * * * * * * Golden file  * * * * * * * * * * * * * //

    const std::string goldenFile = std::string(WSF_TEST_DATA) + "/forceFieldGolden.txt";

    //- Per combination name: the rows (id, F, T, S) in the fixture's order
    using Golden = std::map<std::string, std::vector<std::vector<double>>>;

    std::vector<double> row(std::int64_t id, const Vec3& F, const Vec3& T, const Mat3& S)
    {
        std::vector<double> r{double(id)};
        r.insert(r.end(), F.data(), F.data() + 3);
        r.insert(r.end(), T.data(), T.data() + 3);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                r.push_back(S(a, b));
        return r;
    }

    void writeGolden(const Golden& golden)
    {
        std::FILE* f = std::fopen(goldenFile.c_str(), "w");
        ASSERT_NE(f, nullptr) << "cannot write " << goldenFile;
        std::fprintf
        (
            f,
            "# ForceField::evaluate on the fixture of tests/suspension/testForceField.C\n"
            "# for every combination of pair models. Regenerate (after checking that\n"
            "# the change of the forces is intended) with WSF_REGENERATE_GOLDEN=1.\n"
            "# Per combination, one row per particle in the fixture's order:\n"
            "# id Fx Fy Fz Tx Ty Tz Sxx Sxy Sxz Syx Syy Syz Szx Szy Szz\n"
        );
        for (const auto& [name, rows] : golden)
        {
            std::fprintf(f, "combination %s\n", name.c_str());
            for (const std::vector<double>& r : rows)
            {
                std::fprintf(f, "%d", int(r[0]));
                for (std::size_t k = 1; k < r.size(); ++k)
                {
                    std::fprintf(f, " %.17g", r[k]);
                }
                std::fprintf(f, "\n");
            }
        }
        std::fclose(f);
    }

    //- The stored values; empty when the file is missing
    Golden readGolden()
    {
        Golden golden;
        std::ifstream in(goldenFile);
        std::string line;
        std::vector<std::vector<double>>* rows = nullptr;
        while (std::getline(in, line))
        {
            if (line.empty() || line[0] == '#')
            {
                continue;
            }
            std::istringstream is(line);
            if (line.rfind("combination ", 0) == 0)
            {
                std::string word;
                std::string name;
                is >> word >> name;
                rows = &golden[name];
                continue;
            }
            std::vector<double> r;
            double v;
            while (is >> v)
            {
                r.push_back(v);
            }
            if (rows)
            {
                rows->push_back(r);
            }
        }
        return golden;
    }


    // * * * * * * * * * * * * * * * A larger system  * * * * * * * * * * * //

    //- n random spheres of radii 1.0 and 1.4 (alternating), random
    //  velocities about the flow and spins; overlaps allowed
    Particles randomParticles(const Vec3& L, int n, const ShearFlow& flow, unsigned seed)
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> u(0, 1);
        Particles p;
        for (int i = 0; i < n; ++i)
        {
            const Vec3 x(u(gen)*L.x(), u(gen)*L.y(), u(gen)*L.z());
            p.add(x, (i % 2) ? 1.4 : 1.0, rho, 1000 + 3*i);
            p.u.back() = flow.sample(x).U + Vec3(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5);
            p.omega.back() = Vec3(u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5);
        }
        return p;
    }

    //- A sheared system of 600 spheres at phi ~ 0.5 (three reduction
    //  blocks of core/Parallel.H, so the ordered sums have several terms),
    //  its list built and its contact history grown by two steps of
    //  advance() at fixed positions
    struct System
    {
        LeesEdwardsBox box;
        ShearFlow flow;
        Particles particles;
        ForceField field;
        NeighbourSearch search;
        PairList near;

        System(const Combination& c, Stencil stencil)
        :
            box(Vec3(21, 20, 22), 1.0),
            flow(1.0, 0.3, 1, 20),
            particles(randomParticles(box.L(), 600, flow, 3)),
            field(c.models(), particles.a),
            search({field.nearGap(), skin, stencil, field.farGap()}),
            near()
        {
            box.setStrain(box.shearRate()*(0.61));
            search.rebuild(particles, box, near);
            for (int step = 0; step < 2; ++step)
            {
                field.advance(particles, box, flow, near, search.far(), 1e-3);
            }
        }

        Forces evaluate()
        {
            return evaluateAll(field, particles, box, flow, near, search.far());
        }

        //- Number of slots with a contact history
        std::size_t activeContacts() const
        {
            return near.nContacts();
        }
    };

    //- Threads for every loop however small the system (core/Parallel.H);
    //  the threshold and the thread count are restored on destruction
    class ThreadSetting
    {
        std::size_t minParticles_;
        int threads_;

    public:

        ThreadSetting()
        :
            minParticles_(setParallelMinParticles(0)),
            threads_(omp_get_max_threads())
        {}

        ~ThreadSetting()
        {
            omp_set_num_threads(threads_);
            setParallelMinParticles(minParticles_);
        }

        //- Ask for n threads; returns how many a parallel region gets
        int set(int n) const
        {
            omp_set_num_threads(n);
            int team = 0;
            #pragma omp parallel
            {
                #pragma omp single
                team = omp_get_num_threads();
            }
            return team;
        }
    };
}


TEST(ForceField, FixtureCoversTheRangesOfTheModels)
{
    // The golden and brute-force tests below are only as good as the
    // fixture: every range of every model, and the periodic boundaries
    const Fixture fx = makeFixture();
    const Particles& p = fx.particles;
    const LeesEdwardsBox& box = fx.box;
    int contactsAbove = 0, contactsBelow = 0, atContact = 0, lub = 0, repOnly = 0,
        attNearOnly = 0, attFar = 0, listedOnly = 0, acrossSheared = 0,
        contactsAcrossSheared = 0, acrossX = 0, acrossZ = 0;
    const double FCL = 1.5;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        EXPECT_GE(p.x[i].minCoeff(), 0);
        EXPECT_LT(p.x[i].x(), box.L().x());
        EXPECT_LT(p.x[i].y(), box.L().y());
        EXPECT_LT(p.x[i].z(), box.L().z());
        for (std::size_t j = i + 1; j < p.size(); ++j)
        {
            Vec3 r = p.x[j] - p.x[i];
            const Vec3 direct = r;
            const int m = box.minimumImage(r);
            const double h = r.norm() - p.a[i] - p.a[j];
            if (h >= 1.7)
            {
                continue;
            }
            EXPECT_GT(h, -0.06) << "pairs overlap by at most 0.05";
            contactsAbove += h < 0 && springs().kn*(-h) > FCL;
            contactsBelow += h < 0 && springs().kn*(-h) < FCL;
            atContact += h == 0;
            lub += h > 0 && h < 0.25;
            repOnly += h > 0.25 && h < 0.4;
            attNearOnly += h > 0.4 && h < 0.5;
            attFar += h > 0.5 && h < 1.5;
            listedOnly += h > 1.5 && h < 1.5 + skin;
            acrossSheared += m != 0;
            // along the image velocity jump too, so that the dashpot sees it
            contactsAcrossSheared += m != 0 && h < 0 && std::abs(r.x()) > 0.3*r.norm();
            acrossX += m == 0 && std::abs(direct.x()) > box.L().x()/2;
            acrossZ += std::abs(direct.z()) > box.L().z()/2;
        }
    }
    EXPECT_GE(contactsAbove, 3);
    EXPECT_GE(contactsBelow, 1);
    EXPECT_EQ(atContact, 1);
    EXPECT_GE(lub, 3);
    EXPECT_GE(repOnly, 1);
    EXPECT_GE(attNearOnly, 1);
    EXPECT_GE(attFar, 4);
    EXPECT_GE(listedOnly, 1);
    EXPECT_GE(acrossSheared, 4);
    EXPECT_GE(contactsAcrossSheared, 1);
    EXPECT_GE(acrossX, 2);
    EXPECT_GE(acrossZ, 2);
    EXPECT_EQ(fx.stretch.size(), std::size_t(contactsAbove + contactsBelow));

    // The attraction runs in the far pass at 1.5 and in the near pass at 0.5
    const std::size_t att = registryIndex<VanDerWaalsAttraction>();
    for (const Combination& c : combinations())
    {
        const ForceField field(c.models(), p.a);
        EXPECT_EQ(field.farModel(att), c.attraction == Attraction::far) << c.name();
        EXPECT_EQ(field.farGap() > 0, c.attraction == Attraction::far) << c.name();
    }
}


TEST(ForceField, EveryCombinationEqualsBruteForceOverTheKernels)
{
    // The loop (near pass: half list, slot buffers, transposed second pass;
    // far pass: half list, one scalar per slot, transposed second pass)
    // against a double loop over all pairs that calls
    // the kernels itself: forces, torques, per-particle stresslets, the
    // stresslet sums per contribution (eq. 8) and the contact statistics
    const Fixture fx = makeFixture();
    const double tol = 1e-12;
    for (const Combination& c : combinations())
    {
        const Forces loop = evaluateFixture(fx, c, Stencil::half);
        const Forces brute = bruteForce(fx, c.models());
        expectClose(loop, brute, tol, fx.particles.id, c.name());

        const std::vector<Mat3>& S = loop.summary.stresslet;
        const std::vector<Mat3>& Sb = brute.summary.stresslet;
        ASSERT_EQ(S.size(), contributionNames().size());
        const double bound = tol*largest(Sb);
        for (std::size_t k = 0; k < S.size(); ++k)
        {
            EXPECT_LE((S[k] - Sb[k]).norm(), bound)
                << c.name() << ": stresslet sum of " << contributionNames()[k] << " "
                << str(S[k]) << ", expected " << str(Sb[k]);
            // A model that is off contributes exactly nothing
            if (Sb[k] == Mat3::Zero())
            {
                EXPECT_EQ(S[k], Mat3::Zero()) << c.name() << ": " << contributionNames()[k];
            }
        }

        // Contacts are counted whichever models are on
        EXPECT_EQ(loop.summary.nContacts, brute.summary.nContacts) << c.name();
        EXPECT_NEAR(loop.summary.maxOverlap, brute.summary.maxOverlap, 1e-15) << c.name();
        EXPECT_EQ
        (
            std::minmax(loop.summary.maxOverlapPair[0], loop.summary.maxOverlapPair[1]),
            std::minmax(brute.summary.maxOverlapPair[0], brute.summary.maxOverlapPair[1])
        ) << c.name();

        // advance() by dt: the stretches move with the tangential and
        // rolling velocities of the contacts (eq. 5, B.1), through the
        // sheared boundary with the image velocity jump
        const double dt = 1e-3;
        Histories keptLoop, keptBrute;
        const Forces stepLoop = FixtureLoop(fx, c, Stencil::half).advance(dt, keptLoop);
        const Forces stepBrute = bruteForce(fx, c.models(), dt, &keptBrute);
        expectClose(stepLoop.F, stepBrute.F, tol, fx.particles.id, c.name() + ", advance: F");
        expectClose(stepLoop.T, stepBrute.T, tol, fx.particles.id, c.name() + ", advance: T");
        if (c.contact == Contact::none)
        {
            continue;       // no model touches the history
        }
        // every contact keeps a stretch, but the one below F_CL
        EXPECT_EQ(keptBrute.size(), c.contact == Contact::frictional ? 4u : 3u) << c.name();
        ASSERT_EQ(keptLoop.size(), keptBrute.size()) << c.name() << ", advance: contact histories";
        for (const auto& [ids, s] : keptBrute)
        {
            const ContactState& l = keptLoop[ids];
            const double scale = s.xiT.norm() + s.xiR.norm();
            EXPECT_LE((l.xiT - s.xiT).norm() + (l.xiR - s.xiR).norm(), tol*scale)
                << c.name() << ", advance: history of (" << ids.first << ", " << ids.second
                << "): xiT " << str(l.xiT) << ", expected " << str(s.xiT);
        }
    }
}


TEST(ForceField, GoldenForcesOfEveryCombination)
{
    // Stored values (tests/suspension/data/forceFieldGolden.txt, %.17g) of
    // the fixture for every combination: a change of the loop or of a
    // kernel that changes any force, torque or stresslet by more than
    // 1e-12 of the largest of its kind fails here. WSF_REGENERATE_GOLDEN=1
    // writes the file instead, from the loop that the brute-force test
    // above checks independently
    const Fixture fx = makeFixture();
    Golden computed;
    std::map<std::string, Forces> forces;
    for (const Combination& c : combinations())
    {
        const Forces f = evaluateFixture(fx, c, Stencil::half);
        std::vector<std::vector<double>>& rows = computed[c.name()];
        for (std::size_t i = 0; i < fx.particles.size(); ++i)
        {
            rows.push_back(row(fx.particles.id[i], f.F[i], f.T[i], f.S[i]));
        }
        forces[c.name()] = f;
    }

    const char* regenerate = std::getenv("WSF_REGENERATE_GOLDEN");
    if (regenerate && std::string(regenerate) == "1")
    {
        writeGolden(computed);
        GTEST_SKIP() << "wrote " << goldenFile;
    }

    const Golden stored = readGolden();
    ASSERT_FALSE(stored.empty())
        << "no reference values in " << goldenFile
        << "; generate them with WSF_REGENERATE_GOLDEN=1";
    ASSERT_EQ(stored.size(), computed.size()) << "combinations in " << goldenFile;
    const double tol = 1e-12;
    for (const auto& [name, f] : forces)
    {
        const auto it = stored.find(name);
        ASSERT_NE(it, stored.end()) << name << " missing in " << goldenFile;
        ASSERT_EQ(it->second.size(), fx.particles.size()) << name;
        Forces ref;
        for (std::size_t i = 0; i < fx.particles.size(); ++i)
        {
            const std::vector<double>& r = it->second[i];
            ASSERT_EQ(r.size(), 16u) << name << ", row " << i;
            ASSERT_EQ(r[0], double(fx.particles.id[i])) << name << ", row " << i;
            ref.F.emplace_back(r[1], r[2], r[3]);
            ref.T.emplace_back(r[4], r[5], r[6]);
            Mat3 S;
            S << r[7], r[8], r[9], r[10], r[11], r[12], r[13], r[14], r[15];
            ref.S.push_back(S);
        }
        expectClose(f, ref, tol, fx.particles.id, name);
    }
}


namespace
{
    //- Whether the models of mask are one of the sets
    template<class... Ms>
    unsigned maskOfSet(ModelList<Ms...>)
    {
        return ((1u << registryIndex<Ms>()) | ... | 0u);
    }

    template<class... Sets>
    bool isSpecialised(unsigned mask, std::tuple<Sets...>)
    {
        return ((mask == maskOfSet(Sets())) || ...);
    }

    bool sameLinearised(const LinearisedContact& a, const LinearisedContact& b)
    {
        return a.i == b.i && a.j == b.j && a.n == b.n && a.ai == b.ai
            && a.aj == b.aj && a.dUinf == b.dUinf && a.dy == b.dy
            && a.k.kn == b.k.kn && a.k.gammaN == b.k.gammaN
            && a.k.kt == b.k.kt && a.k.kr == b.k.kr;
    }
}


TEST(ForceField, GenericPassesGiveTheSpecialisedBits)
{
    // A set of models with a pass of its own (SpecialisedNearSets,
    // SpecialisedFarSets) runs it; any other runs the generic pass, which
    // skips the models that are off. Both sum in registry order, so every
    // combination, forced through the generic passes, gives the same bits:
    // forces, torques, stresslets, their sums, contact statistics, the
    // histories advance() keeps, and an implicit integrator's linearised
    // contacts. The golden test above holds both paths to its values.
    const Fixture fx = makeFixture();
    const std::size_t lub = registryIndex<Lubrication>();
    std::set<unsigned> specialisedNear, specialisedFar;
    int generic = 0;
    for (const Combination& c : combinations())
    {
        FixtureLoop own(fx, c, Stencil::half);
        FixtureLoop gen(fx, c, Stencil::half, ForceField::PairPasses::generic);

        unsigned farMask = 0;
        for (std::size_t k = 0; k < PairModels::size; ++k)
        {
            farMask |= own.field.farModel(k) ? 1u << k : 0u;
        }
        const unsigned mask = c.models().activeMask();
        for (const unsigned m : {mask, mask & ~(1u << lub)})
        {
            if (isSpecialised(m & ~farMask, SpecialisedNearSets()))
            {
                specialisedNear.insert(m & ~farMask);
            }
            else
            {
                generic += (m & ~farMask) != 0;
            }
            if (isSpecialised(m & farMask, SpecialisedFarSets()))
            {
                specialisedFar.insert(m & farMask);
            }
        }

        expectBitwise(own.evaluate(), gen.evaluate(), c.name() + ": evaluate");

        const double dt = 1e-3;
        Histories keptOwn, keptGen;
        const Forces a = own.advance(dt, keptOwn);
        const Forces b = gen.advance(dt, keptGen);
        expectBitwise(a, b, c.name() + ": advance");
        ASSERT_EQ(keptOwn.size(), keptGen.size()) << c.name();
        for (const auto& [ids, s] : keptOwn)
        {
            EXPECT_TRUE(sameState(s, keptGen[ids]))
                << c.name() << ": history of (" << ids.first << ", " << ids.second << ")";
        }

        std::vector<LinearisedContact> la, lb;
        expectBitwise
        (
            own.evaluateLinearised(la), gen.evaluateLinearised(lb),
            c.name() + ": non-hydrodynamic"
        );
        ASSERT_EQ(la.size(), lb.size()) << c.name();
        for (std::size_t k = 0; k < la.size(); ++k)
        {
            EXPECT_TRUE(sameLinearised(la[k], lb[k]))
                << c.name() << ": linearised contact " << k;
        }
    }
    // Both kinds of pass are compared: the fixture's combinations, with and
    // without the lubrication (an implicit integrator's forces), include
    // every specialised set and others
    EXPECT_EQ(specialisedNear.size(), std::tuple_size_v<SpecialisedNearSets>);
    EXPECT_EQ(specialisedFar.size(), std::tuple_size_v<SpecialisedFarSets>);
    EXPECT_GT(generic, 0);
}


TEST(ForceField, HalfAndFullStencilGiveTheSameForces)
{
    // The stencils list the pairs in other orders and orientations (j gets
    // -F of the kernel evaluated from i): the same forces to round-off
    const Fixture fx = makeFixture();
    for (const Combination& c : combinations())
    {
        expectClose
        (
            evaluateFixture(fx, c, Stencil::full),
            evaluateFixture(fx, c, Stencil::half),
            1e-12, fx.particles.id, c.name()
        );
    }
    for (const Attraction att : {Attraction::near, Attraction::far})
    {
        System half(everyModel(att), Stencil::half);
        System full(everyModel(att), Stencil::full);
        ASSERT_GT(half.activeContacts(), 100u);
        const Forces h = half.evaluate();
        const Forces f = reordered(full.evaluate(), full.particles.id, half.particles.id);
        expectClose(f, h, 1e-12, half.particles.id, everyModel(att).name() + ", 600 spheres");
    }
}


TEST(ForceField, BitwiseAcrossThreadCounts)
{
    // Every sum in a fixed order (core/Parallel.H): the same bits for 1 to
    // 4 threads, and when OpenMP gives fewer threads than asked (ctest runs
    // this test again under OMP_THREAD_LIMIT=2). The history advanced by
    // advance() and the forces it wrote count as well.
    const ThreadSetting threads;
    const Combination cases[] =
    {
        everyModel(Attraction::far),
        {true, Contact::criticalLoad, true, Attraction::near},
        {false, Contact::frictional, false, Attraction::none},
        {false, Contact::none, false, Attraction::far}
    };
    bool fewer = false;
    for (const Combination& c : cases)
    {
        for (const Stencil stencil : {Stencil::half, Stencil::full})
        {
            std::vector<Forces> results;
            std::vector<System> systems;
            systems.reserve(4);
            for (int nt = 1; nt <= 4; ++nt)
            {
                const int team = threads.set(nt);
                EXPECT_LE(team, nt);
                EXPECT_LE(team, omp_get_thread_limit());
                fewer = fewer || team < nt;
                systems.emplace_back(c, stencil);
                results.push_back(systems.back().evaluate());
            }
            for (std::size_t r = 1; r < results.size(); ++r)
            {
                const std::string what = c.name() + ", " + std::to_string(r + 1)
                    + " threads asked, stencil " + (stencil == Stencil::half ? "half" : "full");
                const System& a = systems[0];
                const System& b = systems[r];
                EXPECT_EQ(a.particles.id, b.particles.id) << what;
                EXPECT_EQ(a.particles.F, b.particles.F) << what << " (advance)";
                EXPECT_EQ(a.particles.T, b.particles.T) << what << " (advance)";
                ASSERT_EQ(a.near.nPairs(), b.near.nPairs()) << what;
                for (std::size_t k = 0; k < a.near.nPairs(); ++k)
                {
                    EXPECT_TRUE(sameState(a.near.history(k), b.near.history(k)))
                        << what << ": history of slot " << k;
                }
                expectBitwise(results[0], results[r], what);
            }
        }
    }
    // Under a thread limit below 4 the premise of the ctest entry holds
    if (omp_get_thread_limit() < 4)
    {
        EXPECT_TRUE(fewer) << "OMP_THREAD_LIMIT " << omp_get_thread_limit();
    }
}


TEST(ForceField, WriteReadRoundTripIsBitwise)
{
    // A restart: the state written as text (%.17g) in the particle order,
    // the contacts as (id_i, id_j, xi_T, xi_R) of the slots with history,
    // read into fresh particles, a contacts-only list carried into a fresh
    // neighbour search by ids (as src/suspensionFoam reads a restart) and a
    // fresh ForceField: the same list, history and forces, bit for bit
    System a(everyModel(Attraction::far), Stencil::half);
    ASSERT_GT(a.activeContacts(), 100u);
    const Forces before = a.evaluate();

    std::ostringstream os;
    char buf[64];
    auto put = [&](double v) { std::snprintf(buf, sizeof buf, " %.17g", v); os << buf; };
    auto putVec = [&](const Vec3& v) { put(v.x()); put(v.y()); put(v.z()); };
    const Particles& p = a.particles;
    os << p.size();
    put(a.box.offset());
    os << "\n";
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        os << p.id[i];
        put(p.a[i]);
        putVec(p.x[i]);
        putVec(p.u[i]);
        putVec(p.omega[i]);
        os << "\n";
    }
    os << a.activeContacts() << "\n";
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        for (std::size_t k = a.near.offset[i]; k < a.near.offset[i + 1]; ++k)
        {
            const ContactState& s = a.near.history(k);
            if (s.active())
            {
                os << p.id[i] << " " << p.id[a.near.j[k]];
                putVec(s.xiT);
                putVec(s.xiR);
                os << "\n";
            }
        }
    }

    std::istringstream is(os.str());
    auto getVec = [&]() { Vec3 v; is >> v.x() >> v.y() >> v.z(); return v; };
    std::size_t N;
    double offset;
    is >> N >> offset;
    LeesEdwardsBox box(a.box.L(), a.box.shearRate());
    box.setOffset(offset);
    Particles q;
    std::unordered_map<std::int64_t, std::uint32_t> index;
    for (std::size_t i = 0; i < N; ++i)
    {
        std::int64_t id;
        double radius;
        is >> id >> radius;
        q.add(getVec(), radius, rho, id);
        q.u.back() = getVec();
        q.omega.back() = getVec();
        index[id] = std::uint32_t(i);
    }
    std::size_t nContacts;
    is >> nContacts;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ij(nContacts);
    std::vector<ContactState> states(nContacts);
    PairList contacts;
    contacts.offset.assign(N + 1, 0);
    for (std::size_t c = 0; c < nContacts; ++c)
    {
        std::int64_t idI, idJ;
        is >> idI >> idJ;
        ij[c] = {index.at(idI), index.at(idJ)};
        states[c].xiT = getVec();
        states[c].xiR = getVec();
        ++contacts.offset[ij[c].first + 1];
    }
    ASSERT_FALSE(is.fail());
    for (std::size_t i = 0; i < N; ++i)
    {
        contacts.offset[i + 1] += contacts.offset[i];
    }
    contacts.j.resize(nContacts);
    contacts.contactOf.assign(nContacts, PairList::noContact);
    std::vector<std::uint32_t> next(contacts.offset.begin(), contacts.offset.end() - 1);
    for (std::size_t c = 0; c < nContacts; ++c)
    {
        const std::uint32_t slot = next[ij[c].first]++;
        contacts.j[slot] = ij[c].second;
        contacts.setHistory(slot, states[c]);
    }

    ForceField field(everyModel(Attraction::far).models(), q.a);
    NeighbourSearch search({field.nearGap(), skin, Stencil::half, field.farGap()});
    search.rebuild(q, box, contacts);
    EXPECT_EQ(search.statistics().carried, nContacts);
    EXPECT_EQ(search.statistics().dropped, 0u);

    EXPECT_EQ(q.id, p.id);
    EXPECT_EQ(q.x, p.x);
    EXPECT_EQ(contacts.offset, a.near.offset);
    EXPECT_EQ(contacts.j, a.near.j);
    ASSERT_EQ(contacts.nPairs(), a.near.nPairs());
    for (std::size_t k = 0; k < contacts.nPairs(); ++k)
    {
        EXPECT_TRUE(sameState(contacts.history(k), a.near.history(k))) << "slot " << k;
    }
    expectBitwise(evaluateAll(field, q, box, a.flow, contacts, search.far()), before, "after the round trip");
}


TEST(ForceField, ParticleStressletsSumToTheBulk)
{
    // Each particle holds its Stokes stresslet and half of each of its pair
    // stresslets (near and far pass), so their sum is the sum over the
    // contributions of eq. (8), taken by the loop on another path
    const Fixture fx = makeFixture();
    auto expectSum = [](const Forces& f, const std::string& what)
    {
        Mat3 particles = Mat3::Zero();
        double scale = 0;
        for (const Mat3& S : f.S)
        {
            particles += S;
            scale += S.norm();
        }
        Mat3 bulk = Mat3::Zero();
        for (const Mat3& S : f.summary.stresslet)
        {
            bulk += S;
        }
        EXPECT_LE((particles - bulk).norm(), 1e-12*scale)
            << what << ": sum of particles " << str(particles) << ", bulk " << str(bulk);
    };
    for (const Combination& c : combinations())
    {
        expectSum(evaluateFixture(fx, c, Stencil::half), c.name());
    }
    for (const Attraction att : {Attraction::near, Attraction::far})
    {
        System s(everyModel(att), Stencil::half);
        const Forces f = s.evaluate();
        ASSERT_NE(f.summary.stresslet[contributionIndex("attraction")], Mat3::Zero());
        expectSum(f, everyModel(att).name() + ", 600 spheres");
    }
}


TEST(ForceField, EvaluateIsReadOnly)
{
    // evaluate() reads the contact history (the state after the last
    // advance, dt = 0) and writes only its Output: the history and p.F,
    // p.T stay as they were, bit for bit, and a second evaluation gives the
    // same. The kernels recompute the state after the step from the state
    // kept, so evaluate() gives the forces of the last advance (to
    // round-off), and advance() with dt = 0 computes exactly what
    // evaluate() computes and keeps the history (to round-off: the stretch
    // is projected onto the tangent plane it already lies in)
    for (const Contact contact : {Contact::frictional, Contact::criticalLoad})
    {
        const Combination c{true, contact, true, Attraction::far};
        System s(c, Stencil::half);
        ASSERT_GT(s.activeContacts(), 100u);
        const std::vector<ContactState> history = histories(s.near);
        const std::vector<Vec3> F = s.particles.F;
        const std::vector<Vec3> T = s.particles.T;

        const Forces first = s.evaluate();
        const Forces second = s.evaluate();
        ASSERT_EQ(s.near.nPairs(), history.size());
        for (std::size_t k = 0; k < history.size(); ++k)
        {
            EXPECT_TRUE(sameState(s.near.history(k), history[k])) << "slot " << k;
        }
        EXPECT_EQ(s.particles.F, F);
        EXPECT_EQ(s.particles.T, T);
        expectBitwise(first, second, c.name() + ", second evaluation");
        const std::vector<std::int64_t>& ids = s.particles.id;
        expectClose(first.F, F, 1e-12, ids, c.name() + ", F of the last advance");
        expectClose(first.T, T, 1e-12, ids, c.name() + ", T of the last advance");

        // The history is read: without it the friction is gone
        PairList fresh = s.near;
        fresh.clearHistory();
        const Forces noHistory =
            evaluateAll(s.field, s.particles, s.box, s.flow, fresh, s.search.far());
        EXPECT_NE(noHistory.T, first.T) << c.name();

        const ForceSummary summary =
            s.field.advance(s.particles, s.box, s.flow, s.near, s.search.far(), 0);
        EXPECT_EQ(s.particles.F, first.F) << c.name();
        EXPECT_EQ(s.particles.T, first.T) << c.name();
        EXPECT_EQ(summary.stresslet, first.summary.stresslet) << c.name();
        for (std::size_t k = 0; k < history.size(); ++k)
        {
            const double scale = history[k].xiT.norm() + history[k].xiR.norm();
            EXPECT_LE((s.near.history(k).xiT - history[k].xiT).norm(), 1e-14*scale) << "slot " << k;
            EXPECT_LE((s.near.history(k).xiR - history[k].xiR).norm(), 1e-14*scale) << "slot " << k;
        }
    }
}
