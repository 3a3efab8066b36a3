#include "forces/ForceField.H"

#include "core/Parallel.H"
#include "core/Scratch.H"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace suspension
{

namespace
{
    //- The bits of ForceModels::activeMask of the models of a list
    template<class... Ms>
    constexpr unsigned maskOf(ModelList<Ms...>)
    {
        return ((1u << detail::IndexOf<Ms, PairModels>::value) | ... | 0u);
    }

    //- The central models of a list, appended to Central
    template<class Central, class List>
    struct CentralOf;

    template<class... Cs>
    struct CentralOf<ModelList<Cs...>, ModelList<>>
    {
        using type = ModelList<Cs...>;
    };

    template<class... Cs, class M, class... Ms>
    struct CentralOf<ModelList<Cs...>, ModelList<M, Ms...>>
    :
        CentralOf
        <
            std::conditional_t<M::central, ModelList<Cs..., M>, ModelList<Cs...>>,
            ModelList<Ms...>
        >
    {};

    //- The models of the generic far pass
    using CentralPairModels = CentralOf<ModelList<>, PairModels>::type;

    template<class... Ms>
    constexpr bool anyVelocities = (Ms::usesVelocities || ... || false);

    //- Of the models Ms, those of the pass (mask): each, or null
    template<class... Ms>
    std::tuple<const Ms*...> modelsOn
    (
        const ForceModels& models,
        unsigned mask,
        ModelList<Ms...>
    )
    {
        return std::tuple<const Ms*...>
        (
            ((mask & maskOf(ModelList<Ms>())) ? models.get<Ms>() : nullptr)...
        );
    }

    //- The gap() of each model of the pass, -infinity (no pair within it)
    //  for those that are off
    template<class... Ms>
    std::array<double, sizeof...(Ms)> gapsOf(const std::tuple<const Ms*...>& ms)
    {
        return
        {
            (
                std::get<const Ms*>(ms)
              ? std::get<const Ms*>(ms)->gap()
              : -std::numeric_limits<double>::infinity()
            )...
        };
    }

    //- The kernel of M, called as its traits say (forces/PairModel.H)
    template<class M>
    PairForce evalModel
    (
        const M& model,
        const PairGeometry& g,
        const PairKinematics* kin,
        const ContactState& old,
        ContactState& next,
        double dt
    )
    {
        if constexpr (M::hasHistory)
        {
            return model.eval(g, *kin, old, next, dt);
        }
        else if constexpr (M::usesVelocities)
        {
            return model.eval(g, *kin);
        }
        else
        {
            return model.eval(g);
        }
    }

    //- f(std::integral_constant<std::size_t, m>()) for m = 0 ... n - 1
    template<std::size_t... I, class F>
    void forEachIndex(std::index_sequence<I...>, F&& f)
    {
        (f(std::integral_constant<std::size_t, I>()), ...);
    }

    template<std::size_t n, class F>
    void forEachIndex(F&& f)
    {
        forEachIndex(std::make_index_sequence<n>(), std::forward<F>(f));
    }

    //- The symmetric matrix of the entries xx, xy, xz, yy, yz, zz
    Mat3 symmetricMatrix(const double w[6])
    {
        Mat3 S;
        S << w[0], w[1], w[2],
             w[1], w[3], w[4],
             w[2], w[4], w[5];
        return S;
    }

    //- Rows [begin, end) of reduction block b
    struct BlockRange
    {
        std::size_t begin;
        std::size_t end;

        BlockRange(std::size_t b, std::size_t N)
        :
            begin(b*reductionBlock),
            end(std::min(N, (b + 1)*reductionBlock))
        {}
    };
}


// * * * * * * * * * * * * * * * * Constructor * * * * * * * * * * * * * * * //

ForceField::ForceField
(
    ForceModels models,
    const std::vector<double>& radii,
    GhostSamples ghostSamples,
    PairPasses passes
)
:
    models_(std::move(models)),
    passes_(passes),
    farMask_(0),
    nearGap_(0),
    farGap_(0),
    ghostSamples_(std::move(ghostSamples))
{
    models_.prepare(radii);

    double nonCentralGap = 0;
    models_.forEach([&](const auto& m)
    {
        if (!std::decay_t<decltype(m)>::central)
        {
            nonCentralGap = std::max(nonCentralGap, m.gap());
        }
    });

    unsigned bit = 1;
    forEachPairModelType([&](auto tag)
    {
        using M = typename decltype(tag)::type;
        if (const M* m = models_.template get<M>())
        {
            if (M::central && m->gap() > farPassMinGap && m->gap() > nonCentralGap)
            {
                farMask_ |= bit;
                farGap_ = std::max(farGap_, m->gap());
            }
            else
            {
                nearGap_ = std::max(nearGap_, m->gap());
            }
        }
        bit <<= 1;
    });
}


// * * * * * * * * * * * * * * * * * Dispatch  * * * * * * * * * * * * * * * //

template<class... Sets, class Generic, class Pass>
void ForceField::dispatch
(
    unsigned mask,
    std::tuple<Sets...>,
    Generic generic,
    const Pass& pass
) const
{
    bool done = false;
    if (passes_ == PairPasses::specialised)
    {
        (
            (
                !done && mask == maskOf(Sets())
              ? (pass(Sets(), std::true_type()), done = true)
              : false
            ),
            ...
        );
    }
    if (!done)
    {
        pass(generic, std::false_type());
    }
}


// * * * * * * * * * * * * * * * * Near pass * * * * * * * * * * * * * * * * //

void ForceField::countContact
(
    BlockStats& stats,
    const PairGeometry& g,
    std::int64_t idI,
    std::int64_t idJ
)
{
    ++stats.nContacts;
    const double overlap = -g.h/std::min(g.ai, g.aj);
    if (overlap > stats.maxOverlap)
    {
        stats.maxOverlap = overlap;
        stats.pair[0] = idI;
        stats.pair[1] = idJ;
    }
}


void ForceField::clearLinearised(std::size_t nB, const Output& out)
{
    if (out.contacts)
    {
        blockLinearised_.resize(nB);
        for (std::vector<LinearisedContact>& c : blockLinearised_)
        {
            c.clear();
        }
    }
}


void ForceField::countContacts
(
    const Particles& p,
    const LeesEdwardsBox& box,
    const PairList& near,
    const Output& out
)
{
    const std::size_t N = p.size();
    clearLinearised(reductionBlocks(N), out);
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t b = 0; b < reductionBlocks(N); ++b)
    {
        BlockStats& stats = blockStats_[b];
        const BlockRange rows(b, N);
        for (std::size_t i = rows.begin; i < rows.end; ++i)
        {
            for (std::uint32_t k = near.offset[i]; k < near.offset[i + 1]; ++k)
            {
                const std::uint32_t j = near.j[k];
                Vec3 r = p.x[j] - p.x[i];
                box.minimumImage(r);
                const double R = p.a[i] + p.a[j];
                if (r.squaredNorm() < R*R && p.countsPair(i, j))
                {
                    countContact
                    (
                        stats, PairGeometry::make(r, p.a[i], p.a[j]),
                        p.id[i], p.id[j]
                    );
                }
            }
        }
    }
    gatherBlocks(nullptr, out);
}


namespace
{
    //- What the models of a pair in range give it
    struct PairEvaluation
    {
        PairForce total;                // summed over the models
        ContactStiffness stiffness;     // of the linearisable ones
        bool linearised = false;
    };

    //- Every model of Ms that is on within its gap() on one pair: their sum, the
    //  stresslet of each into S[m], and (linearise) the springs of the
    //  linearisable ones about the state the pair keeps (the advanced one,
    //  or the one read)
    template<class... Ms>
    PairEvaluation evaluatePair
    (
        const std::tuple<const Ms*...>& ms,
        const std::array<double, sizeof...(Ms)>& gap,
        const PairGeometry& g,
        const PairKinematics* kin,
        const ContactState& old,
        ContactState& next,
        double dt,
        bool perParticle,
        bool linearise,
        bool advanceHistory,
        Mat3* S
    )
    {
        PairEvaluation e;
        std::size_t m = 0;
        (
            [&]
            {
                if (g.h < gap[m])
                {
                    const Ms& model = *std::get<const Ms*>(ms);
                    const PairForce f = evalModel(model, g, kin, old, next, dt);
                    e.total.F += f.F;
                    e.total.Ti += f.Ti;
                    e.total.Tj += f.Tj;
                    if (perParticle)
                    {
                        e.total.S += f.S;
                    }
                    S[m] += f.S;
                    if constexpr (linearisable<Ms>)
                    {
                        if (linearise)
                        {
                            const ContactStiffness c = model.stiffness
                            (
                                g, *kin, advanceHistory ? next : old
                            );
                            e.stiffness.kn += c.kn;
                            e.stiffness.gammaN += c.gammaN;
                            e.stiffness.kt += c.kt;
                            e.stiffness.kr += c.kr;
                            e.linearised = true;
                        }
                    }
                }
                ++m;
            }(),
            ...
        );
        return e;
    }
}


void ForceField::gatherBlocks(PairList* history, const Output& out)
{
    // The linearised contacts in block (so slot) order
    if (out.contacts)
    {
        out.contacts->clear();
        for (const std::vector<LinearisedContact>& c : blockLinearised_)
        {
            out.contacts->insert(out.contacts->end(), c.begin(), c.end());
        }
    }

    // The next pool: the contacts in block (so slot) order
    if (history)
    {
        pool_.clear();
        for (const std::vector<NewContact>& contacts : blockContacts_)
        {
            for (const NewContact& c : contacts)
            {
                history->contactOf[c.slot] = static_cast<std::uint32_t>(pool_.size());
                pool_.push_back(c.state);
            }
        }
        std::swap(history->contacts, pool_);
    }
}


void ForceField::secondParticles(const PairList& near, const Output& out)
{
    // Pass 2: the parts of j, in the transposed order of the slots
    const std::size_t N = near.nParticles();
    const bool perParticle = out.S != nullptr;
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t j = 0; j < N; ++j)
    {
        Vec3 F = Vec3::Zero();
        Vec3 T = Vec3::Zero();
        Mat3 S = Mat3::Zero();
        near.forEachAsSecond(j, [&](std::uint32_t k)
        {
            if (slotOn_[k])
            {
                F += slotForce_[k].F;
                T += slotForce_[k].T;
                if (perParticle)
                {
                    S += symmetricMatrix(slotS_[k].data());
                }
            }
        });
        if (out.F) (*out.F)[j] += F;
        if (out.T) (*out.T)[j] += T;
        if (perParticle) (*out.S)[j] += S;
    }
}


template<bool AllOn, class... Ms>
void ForceField::nearPass
(
    ModelList<Ms...> list,
    std::bool_constant<AllOn>,
    unsigned mask,
    const Particles& p,
    const LeesEdwardsBox& box,
    const PairList& near,
    PairList* history,
    double dt,
    const Output& out
)
{
    static_assert
    (
        ((!linearisable<Ms> || Ms::usesVelocities) && ...),
        "a model with stiffness() is linearised about the velocities"
    );
    const std::size_t N = p.size();
    const std::size_t nB = reductionBlocks(N);
    clearLinearised(nB, out);
    const std::size_t nC = contributionNames().size();
    const std::tuple<const Ms*...> ms = modelsOn(models_, mask, list);
    const std::array<double, sizeof...(Ms)> gap = gapsOf(ms);
    const bool on[] = {(std::get<const Ms*>(ms) != nullptr)...};
    const int contribution[] = {contributionIndex(Ms::contribution)...};
    const double maxGap = *std::max_element(gap.begin(), gap.end());
    const bool velocitiesOn = AllOn
      ? anyVelocities<Ms...>
      : ((std::get<const Ms*>(ms) && Ms::usesVelocities) || ...);
    const bool historyOn = ((std::get<const Ms*>(ms) && Ms::hasHistory) || ...);
    const double imageVelocity = box.imageVelocity();
    const bool perParticle = out.S != nullptr;
    const bool ghosts = !p.ghost.empty();
    const bool readHistory = historyOn && !near.contactOf.empty();
    const bool advanceHistory = historyOn && history;
    if (advanceHistory && near.contactOf.size() != near.nPairs())
    {
        throw std::logic_error
        (
            "ForceField: the near list carries no contact history"
            " (PairList::clearHistory)"
        );
    }
    if (advanceHistory)
    {
        blockContacts_.resize(nB);
    }
    const bool linearise =
        ((std::get<const Ms*>(ms) && linearisable<Ms>) || ...) && out.contacts;
    resizeScratch(slotForce_, near.nPairs());
    resizeScratch(slotOn_, near.nPairs());
    if (perParticle)
    {
        resizeScratch(slotS_, near.nPairs());
    }

    // Pass 1: the rows of i; the parts of j wait in the slots
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t b = 0; b < nB; ++b)
    {
        // The stresslet sums of the pairs counted here, and of those another
        // process counts (decomposition/Domain.H), discarded
        Mat3 S[sizeof...(Ms)];
        Mat3 uncounted[sizeof...(Ms)];
        for (std::size_t m = 0; m < sizeof...(Ms); ++m)
        {
            S[m].setZero();
            uncounted[m].setZero();
        }
        BlockStats& stats = blockStats_[b];
        if (advanceHistory)
        {
            blockContacts_[b].clear();
        }
        const BlockRange rows(b, N);
        for (std::size_t i = rows.begin; i < rows.end; ++i)
        {
            Vec3 Fi = Vec3::Zero();
            Vec3 Ti = Vec3::Zero();
            Mat3 Si = Mat3::Zero();
            const Mat3 Ei = ambient_[i].E();
            for (std::uint32_t k = near.offset[i]; k < near.offset[i + 1]; ++k)
            {
                const std::uint32_t j = near.j[k];

                // Minimum image of x_j, and one test before anything else
                Vec3 r = p.x[j] - p.x[i];
                const int image = box.minimumImage(r);
                const double R = p.a[i] + p.a[j] + maxGap;
                if (!(r.squaredNorm() < R*R))
                {
                    if (advanceHistory && near.contactOf[k] != PairList::noContact)
                    {
                        // eq. (5): a pair out of contact has no stretch
                        history->contactOf[k] = PairList::noContact;
                    }
                    slotOn_[k] = 0;
                    continue;
                }

                const PairGeometry g = PairGeometry::make(r, p.a[i], p.a[j]);

                // The image moves faster by m gammaDot Ly, and so does
                // U_inf there: relative velocities unchanged
                const Vec3 jump = image*imageVelocity*Vec3::UnitX();
                const Vec3 du = p.u[j] + jump - p.u[i];
                const bool count = !ghosts || p.countsPair(i, j);
                if (g.h < 0 && count)
                {
                    countContact(stats, g, p.id[i], p.id[j]);
                }
                Mat3* const sums = count ? S : uncounted;

                ContactState next;
                const ContactState& old = readHistory ? near.history(k) : next;
                const PairEvaluation e = [&]
                {
                    if constexpr (anyVelocities<Ms...>)
                    {
                        if (AllOn || velocitiesOn)
                        {
                            const PairKinematics kin
                            {
                                uRel_[i], uRel_[j], wRel_[i], wRel_[j], du,
                                p.omega[i], p.omega[j], Ei, ambient_[j].E()
                            };
                            return evaluatePair
                            (
                                ms, gap, g, &kin, old, next, dt, perParticle,
                                linearise, advanceHistory, sums
                            );
                        }
                    }
                    return evaluatePair
                    (
                        ms, gap, g, nullptr, old, next, dt, perParticle,
                        linearise, advanceHistory, sums
                    );
                }();
                if (e.linearised)
                {
                    blockLinearised_[b].push_back
                    ({
                        static_cast<std::uint32_t>(i), j, g.n, g.ai, g.aj,
                        ambient_[j].U + jump - ambient_[i].U, r.y(), e.stiffness
                    });
                }
                if (advanceHistory)
                {
                    // The state after the step joins the next pool; a slot
                    // that leaves contact has none
                    if (near.contactOf[k] != PairList::noContact)
                    {
                        history->contactOf[k] = PairList::noContact;
                    }
                    if (next.active())
                    {
                        blockContacts_[b].push_back({k, next});
                    }
                }

                // Newton's third law: j receives -F (eqs. 4c, 6b, 7b)
                Fi += e.total.F;
                Ti += e.total.Ti;
                slotForce_[k] = SlotForce{-e.total.F, e.total.Tj};
                if (perParticle)
                {
                    const Mat3 half = 0.5*e.total.S;
                    Si += half;
                    slotS_[k] =
                    {
                        half(0, 0), half(0, 1), half(0, 2),
                        half(1, 1), half(1, 2), half(2, 2)
                    };
                }
                slotOn_[k] = 1;
            }
            if (out.F) (*out.F)[i] += Fi;
            if (out.T) (*out.T)[i] += Ti;
            if (perParticle) (*out.S)[i] += Si;
        }
        for (std::size_t m = 0; m < sizeof...(Ms); ++m)
        {
            if (AllOn || on[m])
            {
                blockS_[b*nC + contribution[m]] += S[m];
            }
        }
    }
    gatherBlocks(advanceHistory ? history : nullptr, out);
    secondParticles(near, out);
}


// * * * * * * * * * * * * * * * * Far pass  * * * * * * * * * * * * * * * * //

template<bool AllOn, class... Ms>
void ForceField::farPass
(
    ModelList<Ms...> list,
    std::bool_constant<AllOn>,
    unsigned mask,
    const Particles& p,
    const LeesEdwardsBox& box,
    const PairRows& far,
    const Output& out
)
{
    static_assert((Ms::central && ...), "the far pass takes central models only");
    if constexpr (sizeof...(Ms) > 0)
    {
        constexpr std::size_t nM = sizeof...(Ms);
        const std::size_t N = p.size();
        const std::size_t nC = contributionNames().size();
        const std::tuple<const Ms*...> ms = modelsOn(models_, mask, list);
        const std::array<double, nM> gap = gapsOf(ms);
        const bool on[] = {(std::get<const Ms*>(ms) != nullptr)...};
        const int contribution[] = {contributionIndex(Ms::contribution)...};
        const double maxGap = *std::max_element(gap.begin(), gap.end());
        const bool perParticle = out.S != nullptr;

        // Over the particles i, their rows: the central force f n of each
        // partner, half of the pair's stresslet (f/|r|) r r (eq. 9d, six
        // entries), per block; the halves taken of the sums (exactly the
        // sums of the halves: a factor of 2 rounds nothing)
        #pragma omp parallel for schedule(static) if(threaded(N))
        for (std::size_t b = 0; b < reductionBlocks(N); ++b)
        {
            double W[nM][6] = {};
            const BlockRange rows(b, N);
            for (std::size_t i = rows.begin; i < rows.end; ++i)
            {
                const Vec3 xi = p.x[i];
                const double ai = p.a[i];
                Vec3 Fi = Vec3::Zero();
                double Wi[6] = {0, 0, 0, 0, 0, 0};
                for (std::uint32_t k = far.offset[i]; k < far.offset[i + 1]; ++k)
                {
                    const std::uint32_t j = far.partner[k];
                    Vec3 r = p.x[j] - xi;
                    box.minimumImage(r);
                    const double d2 = r.squaredNorm();
                    const double aj = p.a[j];
                    const double R = ai + aj + maxGap;
                    if (!(d2 < R*R))
                    {
                        continue;
                    }
                    const double d = std::sqrt(d2);
                    const double invD = 1/d;
                    // h as d - (a_i + a_j): the same from both sides
                    const PairGeometry g{r, d, invD*r, ai, aj, d - (ai + aj)};
                    const double rr[6] =
                    {
                        r.x()*r.x(), r.x()*r.y(), r.x()*r.z(),
                        r.y()*r.y(), r.y()*r.z(), r.z()*r.z()
                    };
                    double s = 0;
                    forEachIndex<nM>([&](auto m)
                    {
                        if (g.h < gap[m])
                        {
                            const double sm = std::get<m>(ms)->force(g)*invD;
                            s += sm;
                            for (int c = 0; c < 6; ++c)
                            {
                                W[m][c] += sm*rr[c];
                            }
                        }
                    });
                    Fi += s*r;
                    if (perParticle)
                    {
                        for (int c = 0; c < 6; ++c)
                        {
                            Wi[c] += s*rr[c];
                        }
                    }
                }
                if (out.F) (*out.F)[i] += Fi;
                if (perParticle) (*out.S)[i] += 0.5*symmetricMatrix(Wi);
            }
            for (std::size_t m = 0; m < nM; ++m)
            {
                if (AllOn || on[m])
                {
                    blockS_[b*nC + contribution[m]] += 0.5*symmetricMatrix(W[m]);
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Evaluation * * * * * * * * * * * * * * * //

ForceSummary ForceField::run
(
    const Particles& p,
    const LeesEdwardsBox& box,
    const AmbientFlow& flow,
    const PairList& near,
    PairList* history,
    const PairRows& far,
    double dt,
    Forces forces,
    const Output& out
)
{
    const std::size_t N = p.size();
    const std::size_t nB = reductionBlocks(N);
    const std::size_t nC = contributionNames().size();
    const bool hydrodynamic = forces == Forces::all;

    ambient_.resize(N);
    uRel_.resize(N);
    wRel_.resize(N);
    blockS_.assign(nB*nC, Mat3::Zero());
    blockStats_.assign(nB, BlockStats{0, 0, {-1, -1}});
    if (out.F) out.F->resize(N);
    if (out.T) out.T->resize(N);
    if (out.S) out.S->resize(N);

    // Once per particle: the flow, then the per-particle models (the drag,
    // torque and stresslet, A.1, 9a)
    {
        ScopedTime timer(times_.flowSampling);
        int particleContribution[ParticleModels::size];
        forEachParticleModelType([&](auto tag)
        {
            using M = typename decltype(tag)::type;
            particleContribution[detail::IndexOf<M, ParticleModels>::value] =
                contributionIndex(M::contribution);
        });
        // A flow known on this process's part only: every particle here
        // sampled where it is known, then completed from the other
        // processes (GhostSamples: collective, so decided by the run, not
        // by this process's particles, of which it may have none)
        const bool fromOwners = ghostSamples_ && !flow.sampledAnywhere();
        if (fromOwners)
        {
            known_.resize(N);
            #pragma omp parallel for schedule(static) if(threaded(N))
            for (std::size_t i = 0; i < N; ++i)
            {
                known_[i] = flow.sampleHere(p.x[i], box.shearRate(), ambient_[i]);
            }
            ghostSamples_(ambient_, known_);
            for (std::size_t i = 0; i < N; ++i)
            {
                if (!p.isGhost(i) && !known_[i])
                {
                    std::ostringstream msg;
                    msg << "the ambient flow is not known at particle id "
                        << p.id[i] << " at (" << p.x[i].transpose()
                        << ") on any process";
                    throw std::runtime_error(msg.str());
                }
            }
        }
        #pragma omp parallel for schedule(static) if(threaded(N))
        for (std::size_t b = 0; b < nB; ++b)
        {
            const BlockRange rows(b, N);
            for (std::size_t i = rows.begin; i < rows.end; ++i)
            {
                const FlowSample& f =
                    fromOwners
                  ? ambient_[i]
                  : (ambient_[i] = flow.sample(p.x[i], box.shearRate()));
                uRel_[i] = p.u[i] - f.U;
                wRel_[i] = p.omega[i] - f.Omega();
                Vec3 F = Vec3::Zero();
                Vec3 T = Vec3::Zero();
                Mat3 Si = Mat3::Zero();
                models_.forEachParticleModel([&](const auto& model)
                {
                    using M = std::decay_t<decltype(model)>;
                    if (hydrodynamic || !M::hydrodynamic)
                    {
                        const auto d = model.eval(p.a[i], p.u[i], p.omega[i], f);
                        F += d.F;
                        T += d.T;
                        Si += d.S;
                        const int c =
                            particleContribution[detail::IndexOf<M, ParticleModels>::value];
                        if (!p.isGhost(i))
                        {
                            blockS_[b*nC + c] += d.S;
                        }
                    }
                });
                if (out.F) (*out.F)[i] = F;
                if (out.T) (*out.T)[i] = T;
                if (out.S) (*out.S)[i] = Si;
            }
        }
        flow.sampled(p);
    }

    // The pair passes, compiled for the models that are on
    {
        ScopedTime timer(times_.pairLoop);
        unsigned mask = models_.activeMask();
        if (!hydrodynamic)
        {
            unsigned bit = 1;
            forEachPairModelType([&](auto tag)
            {
                if (decltype(tag)::type::hydrodynamic) mask &= ~bit;
                bit <<= 1;
            });
        }
        const unsigned nearMask = mask & ~farMask_;
        const unsigned farOn = mask & farMask_;
        if (nearMask)
        {
            dispatch
            (
                nearMask, SpecialisedNearSets(), PairModels(),
                [&](auto models, auto allOn)
                {
                    nearPass
                    (
                        models, allOn, nearMask, p, box, near, history, dt, out
                    );
                }
            );
        }
        else
        {
            // No model here: the contacts are still counted (Simulation's
            // checks of the overlap need them)
            countContacts(p, box, near, out);
        }
        if (farOn)
        {
            dispatch
            (
                farOn, SpecialisedFarSets(), CentralPairModels(),
                [&](auto models, auto allOn)
                {
                    farPass(models, allOn, farOn, p, box, far, out);
                }
            );
        }
    }

    // Sums in block order
    ScopedTime timer(times_.particleTerms);
    ForceSummary summary;
    for (std::size_t b = 0; b < nB; ++b)
    {
        for (std::size_t c = 0; c < nC; ++c)
        {
            summary.stresslet[c] += blockS_[b*nC + c];
        }
        const BlockStats& s = blockStats_[b];
        summary.nContacts += s.nContacts;
        if (s.maxOverlap > summary.maxOverlap)
        {
            summary.maxOverlap = s.maxOverlap;
            summary.maxOverlapPair[0] = s.pair[0];
            summary.maxOverlapPair[1] = s.pair[1];
        }
    }
    return summary;
}


ForceSummary ForceField::advance
(
    Particles& p,
    const LeesEdwardsBox& box,
    const AmbientFlow& flow,
    PairList& near,
    const PairRows& far,
    double dt,
    Forces forces,
    std::vector<LinearisedContact>* contacts
)
{
    Output out;
    out.F = &p.F;
    out.T = &p.T;
    out.contacts = contacts;
    return run(p, box, flow, near, &near, far, dt, forces, out);
}


ForceSummary ForceField::evaluate
(
    const Particles& p,
    const LeesEdwardsBox& box,
    const AmbientFlow& flow,
    const PairList& near,
    const PairRows& far,
    const Output& out,
    Forces forces
)
{
    return run(p, box, flow, near, nullptr, far, 0, forces, out);
}

} // namespace suspension
