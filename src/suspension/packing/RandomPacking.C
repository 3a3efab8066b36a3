#include "packing/RandomPacking.H"
#include "packing/SizeDistribution.H"
#include "search/NeighbourSearch.H"
#include "core/Parallel.H"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace suspension
{

namespace
{
    const char* const model = "RandomPacking";

    //- Growth schedule: first stage, initial and smallest step of the stage
    //  volume fractions
    constexpr double phiStart = 0.3;
    constexpr double dPhi = 0.05;
    constexpr double dPhiMin = 1e-3;

    //- Target gap h* - minGap and the largest Verlet skin, in units of
    //  a_min (Params::reach may shorten the skin)
    constexpr double margin = 1e-3;
    constexpr double skin = 0.3;

    //- A stage is jammed when the rms force falls below this, in units of
    //  a_min (the minimiser converged with overlaps left)
    constexpr double jammedForce = 1e-10;

    //- FIRE 2.0 (Guenole et al. 2020, table 1, semi-implicit Euler)
    constexpr double dtStart = 0.1;
    constexpr double dtMax = 3*dtStart;
    constexpr double dtMin = 0.02*dtStart;
    constexpr double alphaStart = 0.25;
    constexpr double fAlpha = 0.99;
    constexpr double fInc = 1.1;
    constexpr double fDec = 0.5;
    constexpr std::size_t nDelay = 20;

    //- Outcome of the minimisation of a stage
    enum class Stage
    {
        overlapFree,    // every gap >= minGap
        jammed,         // converged with overlaps left
        unfinished      // step limit reached
    };

    //- Uniform double in [0, 1) from the top 53 bits of the engine output
    double uniform01(std::mt19937_64& rng)
    {
        return static_cast<double>(rng() >> 11)*0x1.0p-53;
    }

    //- Sum of f(i) over [0, N) starting from zero, per reduction block and
    //  the blocks in order (core/Parallel.H). f(i) may update the entries
    //  of particle i.
    template<class T, class Term>
    T sum(std::size_t N, const T& zero, const Term& f)
    {
        std::vector<T> partial(reductionBlocks(N), zero);
        #pragma omp parallel for schedule(static) if(threaded(N))
        for (std::size_t b = 0; b < partial.size(); ++b)
        {
            T s = zero;
            const std::size_t end = std::min(N, (b + 1)*reductionBlock);
            for (std::size_t i = b*reductionBlock; i < end; ++i)
            {
                s += f(i);
            }
            partial[b] = s;
        }
        T total = zero;
        for (const T& s : partial)
        {
            total += s;
        }
        return total;
    }

    //- Minimum image of r = x_j - x_i for positions inside the box
    //  (|r_d| < L_d), without shear offset. For the pairs in range
    //  (|r| <= L/3) it equals LeesEdwardsBox::minimumImage bitwise (the
    //  same single subtraction of L_d), at the cost of two comparisons.
    void nearestImage(Vec3& r, const Vec3& L)
    {
        for (int d = 0; d < 3; ++d)
        {
            if (r[d] > 0.5*L[d])
            {
                r[d] -= L[d];
            }
            else if (r[d] < -0.5*L[d])
            {
                r[d] += L[d];
            }
        }
    }

    //- Harmonic overlap forces towards the target gap hTarget into p.F;
    //  returns the number of pairs with gap below minGap. The two passes of
    //  core/Parallel.H: the force on j waits in slotF.
    std::size_t overlapForces
    (
        Particles& p,
        const LeesEdwardsBox& box,
        const PairList& list,
        double hTarget,
        double minGap,
        std::vector<Vec3>& slotF
    )
    {
        const std::size_t N = p.size();
        std::size_t violations = 0;
        slotF.resize(list.nPairs());
        #pragma omp parallel if(threaded(N))
        {
            #pragma omp for schedule(static) reduction(+:violations)
            for (std::size_t i = 0; i < N; ++i)
            {
                Vec3 Fi = Vec3::Zero();
                for (std::size_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
                {
                    const std::size_t j = list.j[k];
                    Vec3 r = p.x[j] - p.x[i];
                    nearestImage(r, box.L());
                    const double d2 = r.squaredNorm();
                    const double contact = p.a[i] + p.a[j];
                    const double accepted = contact + minGap;
                    const double target = contact + hTarget;
                    if (d2 < accepted*accepted)
                    {
                        ++violations;
                    }
                    if (d2 < target*target && d2 > 0)
                    {
                        const Vec3 f = (target/std::sqrt(d2) - 1)*r;
                        Fi -= f;
                        slotF[k] = f;
                    }
                    else
                    {
                        slotF[k] = Vec3::Zero();
                    }
                }
                p.F[i] = Fi;
            }

            #pragma omp for schedule(static)
            for (std::size_t j = 0; j < N; ++j)
            {
                Vec3 Fj = Vec3::Zero();
                list.forEachAsSecond(j, [&](std::uint32_t k) { Fj += slotF[k]; });
                p.F[j] += Fj;
            }
        }
        return violations;
    }

    //- FIRE (see the header) on the working particles p (masses (a/a_min)^3)
    //  until no pair has a gap below minGap; counts its steps in stats
    Stage relaxOverlaps
    (
        Particles& p,
        const LeesEdwardsBox& box,
        double hTarget,
        double minGap,
        double aMin,
        std::size_t maxStageIterations,
        std::size_t maxIterations,
        NeighbourSearch& search,
        PairList& list,
        RandomPacking::Statistics& stats
    )
    {
        const std::size_t N = p.size();
        const std::vector<Vec3> Uinf(N, Vec3::Zero());
        std::vector<Vec3> slotF;

        // Velocity mixing u <- keep u + mix F, then the move x += dt u,
        // with the path accounting of the Verlet criterion
        auto mixAndMove = [&](double keep, double mix, double dt)
        {
            #pragma omp parallel for schedule(static) if(threaded(N))
            for (std::size_t i = 0; i < N; ++i)
            {
                p.u[i] = keep*p.u[i] + mix*p.F[i];
                p.x[i] += dt*p.u[i];
                box.wrap(p.x[i], p.u[i]);
            }
            search.accumulate(p, Uinf, dt, 0);
        };

        double dt = dtStart;
        double alpha = alphaStart;
        std::size_t nPositive = 0;
        std::fill(p.u.begin(), p.u.end(), Vec3::Zero());
        for (std::size_t step = 0; step < maxStageIterations; ++step)
        {
            search.update(p, box, list);
            if (overlapForces(p, box, list, hTarget, minGap, slotF) == 0)
            {
                return Stage::overlapFree;
            }
            if (stats.iterations == maxIterations)
            {
                return Stage::unfinished;
            }
            ++stats.iterations;

            // power F.u and |F|^2
            const Eigen::Vector2d PF = sum
            (
                N, Eigen::Vector2d::Zero().eval(),
                [&](std::size_t i)
                {
                    return Eigen::Vector2d(p.F[i].dot(p.u[i]), p.F[i].squaredNorm());
                }
            );
            if (PF.y() < N*jammedForce*jammedForce*aMin*aMin)
            {
                return Stage::jammed;
            }
            if (PF.x() > 0)
            {
                if (++nPositive > nDelay)
                {
                    dt = std::min(dt*fInc, dtMax);
                    alpha *= fAlpha;
                }
            }
            else
            {
                nPositive = 0;
                if (step >= nDelay && dt*fDec >= dtMin)
                {
                    dt *= fDec;
                    alpha = alphaStart;
                }
                // half a step back (reversed velocities), then stop
                mixAndMove(-1, 0, 0.5*dt);
                std::fill(p.u.begin(), p.u.end(), Vec3::Zero());
            }

            // u += dt F/m, summing |u|^2
            const double u2 = sum
            (
                N, 0.0,
                [&](std::size_t i)
                {
                    p.u[i] += dt/p.m[i]*p.F[i];
                    return p.u[i].squaredNorm();
                }
            );
            mixAndMove(1 - alpha, alpha*std::sqrt(u2/PF.y()), dt);
        }
        return Stage::unfinished;
    }
}



PackingError::PackingError(const std::string& message, double phiReached)
:
    std::runtime_error(message),
    phiReached_(phiReached)
{}


RandomPacking::RandomPacking(const Params& p)
:
    p_(p)
{
    if (!(p.phi > 0 && p.phi < phiMax))
    {
        throwOutOfRange(model, "phi", p.phi, "(0, 0.74)");
    }
    checkNonNegative(model, "minGap", p.minGap);
    checkPositive(model, "reach", p.reach);
    checkPositive(model, "aspect x", p.aspect.x());
    checkPositive(model, "aspect y", p.aspect.y());
    checkPositive(model, "aspect z", p.aspect.z());
    if (p.maxStageIterations < 1)
    {
        throwOutOfRange(model, "maxStageIterations", 0, "[1, inf)");
    }
    if (p.maxIterations < 1)
    {
        throwOutOfRange(model, "maxIterations", 0, "[1, inf)");
    }
}


double RandomPacking::searchSkin(double hTarget, double aMin) const
{
    if (!(p_.reach > hTarget))
    {
        std::ostringstream msg;
        msg << model << ": reach = " << p_.reach << " (the run's largest"
            << " interaction gap + skin) must exceed the packing's target gap"
            << " h* = minGap + " << margin << " a_min = " << hTarget;
        throw std::invalid_argument(msg.str());
    }
    return std::min(skin*aMin, p_.reach - hTarget);
}


RandomPacking::Result RandomPacking::pack
(
    const std::vector<double>& radii,
    double rho
) const
{
    checkPositive(model, "rho", rho);
    const Vec3 L = boxLengths(radii, p_.phi, p_.aspect);
    const LeesEdwardsBox box(L, 0);
    const std::size_t N = radii.size();
    const double aMin = *std::min_element(radii.begin(), radii.end());
    const double aMax = *std::max_element(radii.begin(), radii.end());
    const double minGap = p_.minGap*aMin;
    const double hTarget = minGap + margin*aMin;
    const double listSkin = searchSkin(hTarget, aMin);
    BoxRule(p_.reach).check(L, aMax);

    // Centres uniform in the box; minimiser masses m = (a/a_min)^3; the
    // working radii are scaled by s at each stage
    std::mt19937_64 rng(p_.seed);
    const double unitMassDensity = 3/(4*pi*aMin*aMin*aMin);
    Particles p;
    for (std::size_t i = 0; i < N; ++i)
    {
        const double x = uniform01(rng);
        const double y = uniform01(rng);
        const double z = uniform01(rng);
        Vec3 centre = L.cwiseProduct(Vec3(x, y, z));
        Vec3 still = Vec3::Zero();
        box.wrap(centre, still);    // (1 - 2^-53) L may round up to L
        p.add
        (
            centre,
            radii[i],
            unitMassDensity,
            static_cast<std::int64_t>(i)
        );
    }

    NeighbourSearch search({hTarget, listSkin, Stencil::half});
    PairList list;
    Statistics stats;

    // Stages: after a success grow by `step`; after a failure retry from the
    // current positions halfway between the last success and the failed
    // stage, until the step falls below dPhiMin
    double phiReached = 0;
    double step = dPhi;
    double phiStage = std::min(p_.phi, phiStart);
    while (true)
    {
        const double s = phiStage == p_.phi ? 1.0 : std::cbrt(phiStage/p_.phi);
        for (std::size_t i = 0; i < N; ++i)
        {
            p.a[i] = s*radii[p.id[i]];
        }
        search.rebuild(p, box, list);
        ++stats.stages;
        const Stage outcome = relaxOverlaps
        (
            p, box, hTarget, minGap, aMin, p_.maxStageIterations,
            p_.maxIterations, search, list, stats
        );
        if (outcome == Stage::overlapFree)
        {
            phiReached = phiStage;
            if (phiStage == p_.phi)
            {
                break;
            }
        }
        else
        {
            step = 0.5*(phiStage - phiReached);
            if (phiReached == 0 || step < dPhiMin || stats.iterations == p_.maxIterations)
            {
                std::ostringstream msg;
                msg << model << ": could not pack " << N << " spheres at phi = "
                    << p_.phi << " (seed " << p_.seed << "): the stage at phi = "
                    << phiStage
                    << (
                           outcome == Stage::jammed
                         ? " jammed (FIRE converged with overlaps left)"
                         : " kept overlaps after the FIRE step limit"
                       )
                    << " (" << stats.iterations << " steps in all; at most "
                    << p_.maxStageIterations << " per stage, "
                    << p_.maxIterations << " in all); the densest"
                    << " overlap-free stage reached phi = " << phiReached;
                throw PackingError(msg.str(), phiReached);
            }
        }
        phiStage = std::min(p_.phi, phiReached + step);
    }
    stats.builds = search.statistics().builds;

    // Particles in id order, full radii (s = 1 at the last stage), at rest
    std::vector<std::size_t> index(N);
    for (std::size_t i = 0; i < N; ++i)
    {
        index[p.id[i]] = i;
    }
    Particles result;
    for (std::size_t k = 0; k < N; ++k)
    {
        result.add(p.x[index[k]], radii[k], rho, static_cast<std::int64_t>(k));
    }
    return Result{std::move(result), box, stats};
}

double RandomPacking::removeOverlaps(Particles& particles, const Vec3& L) const
{
    const LeesEdwardsBox box(L, 0);
    const std::size_t N = particles.size();
    if (N == 0)
    {
        return 0;
    }
    const double aMin = *std::min_element(particles.a.begin(), particles.a.end());
    const double aMax = *std::max_element(particles.a.begin(), particles.a.end());
    const double minGap = p_.minGap*aMin;
    const double hTarget = minGap + margin*aMin;
    const double listSkin = searchSkin(hTarget, aMin);
    BoxRule(p_.reach).check(L, aMax);

    // Working copy with the minimiser's masses (a/a_min)^3
    const double unitMassDensity = 3/(4*pi*aMin*aMin*aMin);
    Particles p;
    for (std::size_t i = 0; i < N; ++i)
    {
        p.add(particles.x[i], particles.a[i], unitMassDensity, particles.id[i]);
    }
    NeighbourSearch search({hTarget, listSkin, Stencil::half});
    PairList list;
    search.rebuild(p, box, list);
    Statistics stats;
    const Stage outcome = relaxOverlaps
    (
        p, box, hTarget, minGap, aMin, p_.maxStageIterations,
        p_.maxIterations, search, list, stats
    );
    if (outcome != Stage::overlapFree)
    {
        std::ostringstream msg;
        msg << model << ": could not remove the overlaps of " << N
            << " spheres in the box (" << L.transpose() << "): "
            << (
                   outcome == Stage::jammed
                 ? "they jam (FIRE converged with overlaps left)"
                 : "overlaps left after the FIRE step limit"
               )
            << " after " << stats.iterations << " steps";
        throw PackingError(msg.str(), 0);
    }

    // The rebuilds re-order the working copy: map back by id
    std::unordered_map<std::int64_t, std::size_t> index;
    for (std::size_t i = 0; i < N; ++i)
    {
        index[p.id[i]] = i;
    }
    double largest = 0;
    for (std::size_t i = 0; i < N; ++i)
    {
        const Vec3& x = p.x[index.at(particles.id[i])];
        Vec3 r = x - particles.x[i];
        nearestImage(r, L);
        largest = std::max(largest, r.norm());
        particles.x[i] = x;
    }
    return largest;
}

} // namespace suspension
