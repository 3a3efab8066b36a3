#include "forces/ForceField.H"

#include "core/Parallel.H"

#include <omp.h>

#include <algorithm>

namespace suspension
{

ForceField::ForceField(ForceModels models)
:
    models_(std::move(models))
{}


template<bool Lub, bool Con, bool Rep, bool Att>
void ForceField::pairLoop
(
    const Particles& p,
    const LeesEdwardsBox& box,
    PairList& pairs,
    double dt,
    bool perParticleStress,
    std::vector<ForceSummary>& threadSummary
)
{
    const std::size_t N = p.size();
    const double imageVelocity = box.imageVelocity();

    #pragma omp parallel num_threads(static_cast<int>(threadF_.size()))
    {
        const int t = omp_get_thread_num();
        std::vector<Vec3>& F = threadF_[t];
        std::vector<Vec3>& T = threadT_[t];
        std::vector<Mat3>& S = threadS_[t];
        ForceSummary& sum = threadSummary[t];

        #pragma omp for schedule(static)
        for (std::size_t i = 0; i < N; ++i)
        {
            const FlowSample& fi = ambient_[i];
            const Vec3 wi = p.omega[i] - fi.Omega();
            const Vec3 ui = p.u[i] - fi.U;
            const Mat3 Ei = fi.E();

            for (std::uint32_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
            {
                const std::size_t j = pairs.j[k];

                // Minimum image of x_j and the image's velocity jump (eq. 16)
                Vec3 r = p.x[j] - p.x[i];
                const int m = box.minimumImage(r);
                const PairGeometry g = PairGeometry::make(r, p.a[i], p.a[j]);

                const FlowSample& fj = ambient_[j];
                // The image moves faster by m gammaDot Ly, and so does U_inf
                // there: the velocity relative to the ambient flow is unchanged
                const Vec3 uj = p.u[j] + m*imageVelocity*Vec3::UnitX();
                const PairKinematics kin
                {
                    ui,
                    p.u[j] - fj.U,
                    wi,
                    p.omega[j] - fj.Omega(),
                    uj - p.u[i],
                    p.omega[i],
                    p.omega[j],
                    Ei,
                    fj.E()
                };

                PairForce total;
                auto add = [&](const PairForce& f, int c)
                {
                    total.F += f.F;
                    total.Ti += f.Ti;
                    total.Tj += f.Tj;
                    sum.stresslet[c] += f.S;
                    if (perParticleStress) total.S += f.S;
                };

                if constexpr (Lub)
                {
                    if (g.dist < models_.lubrication->range(g.ai, g.aj))
                    {
                        add(models_.lubrication->eval(g, kin), lubrication);
                    }
                }
                if constexpr (Con)
                {
                    ContactState& state = pairs.history[k];
                    if (FrictionalContact::inContact(g))
                    {
                        add(models_.contact->eval(g, kin, state, dt), contact);
                        ++sum.nContacts;
                        const double overlap = -g.h/std::min(g.ai, g.aj);
                        if (overlap > sum.maxOverlap)
                        {
                            sum.maxOverlap = overlap;
                            sum.maxOverlapPair[0] = p.id[i];
                            sum.maxOverlapPair[1] = p.id[j];
                        }
                    }
                    else
                    {
                        state = ContactState();     // eq. (5): xi(t0) = 0
                    }
                }
                if constexpr (Rep)
                {
                    if (g.dist < models_.repulsion->range(g.ai, g.aj))
                    {
                        add(models_.repulsion->eval(g), repulsion);
                    }
                }
                if constexpr (Att)
                {
                    if (g.dist < models_.attraction->range(g.ai, g.aj))
                    {
                        add(models_.attraction->eval(g), attraction);
                    }
                }

                // Newton's third law: j receives -F (eqs. 4c, 6b, 7b)
                F[i] += total.F;
                F[j] -= total.F;
                T[i] += total.Ti;
                T[j] += total.Tj;
                if (perParticleStress)
                {
                    S[i] += 0.5*total.S;
                    S[j] += 0.5*total.S;
                }
            }
        }
    }
}


ForceSummary ForceField::compute
(
    Particles& p,
    const LeesEdwardsBox& box,
    const AmbientFlow& flow,
    PairList& pairs,
    double dt,
    std::vector<Mat3>* particleStresslet,
    Forces forces
)
{
    const std::size_t N = p.size();
    const int nThreads = threadsFor(N);
    const bool perParticle = particleStresslet != nullptr;
    const bool hydrodynamic = forces == Forces::all;

    ambient_.resize(N);
    threadF_.resize(nThreads);
    threadT_.resize(nThreads);
    threadS_.resize(nThreads);
    std::vector<ForceSummary> threadSummary(nThreads);
    for (ForceSummary& s : threadSummary)
    {
        s.stresslet.fill(Mat3::Zero());
    }

    // Ambient flow at the particles, and per-thread buffers cleared
    {
        ScopedTime timer(times_.flowSampling);
        #pragma omp parallel num_threads(nThreads)
        {
            const int t = omp_get_thread_num();
            threadF_[t].assign(N, Vec3::Zero());
            threadT_[t].assign(N, Vec3::Zero());
            threadS_[t].assign(perParticle ? N : 0, Mat3::Zero());

            #pragma omp for schedule(static)
            for (std::size_t i = 0; i < N; ++i)
            {
                ambient_[i] = flow.sample(p.x[i]);
            }
        }
    }

    // One pair loop, compiled for the active models only
    const int active =
        (hydrodynamic && models_.lubrication ? 1 : 0)
      | (models_.contact ? 2 : 0)
      | (models_.repulsion ? 4 : 0) | (models_.attraction ? 8 : 0);

    using Loop = void (ForceField::*)
    (
        const Particles&, const LeesEdwardsBox&, PairList&, double, bool,
        std::vector<ForceSummary>&
    );
    static const Loop loops[16] =
    {
        &ForceField::pairLoop<false, false, false, false>,
        &ForceField::pairLoop<true,  false, false, false>,
        &ForceField::pairLoop<false, true,  false, false>,
        &ForceField::pairLoop<true,  true,  false, false>,
        &ForceField::pairLoop<false, false, true,  false>,
        &ForceField::pairLoop<true,  false, true,  false>,
        &ForceField::pairLoop<false, true,  true,  false>,
        &ForceField::pairLoop<true,  true,  true,  false>,
        &ForceField::pairLoop<false, false, false, true>,
        &ForceField::pairLoop<true,  false, false, true>,
        &ForceField::pairLoop<false, true,  false, true>,
        &ForceField::pairLoop<true,  true,  false, true>,
        &ForceField::pairLoop<false, false, true,  true>,
        &ForceField::pairLoop<true,  false, true,  true>,
        &ForceField::pairLoop<false, true,  true,  true>,
        &ForceField::pairLoop<true,  true,  true,  true>
    };
    {
        ScopedTime timer(times_.pairLoop);
        (this->*loops[active])(p, box, pairs, dt, perParticle, threadSummary);
    }
    ScopedTime timer(times_.particleTerms);

    // Stokes drag (A.1, 9a) plus the thread buffers, summed in thread order
    ForceSummary summary = threadSummary[0];
    for (int t = 1; t < nThreads; ++t)
    {
        for (int c = 0; c < nContributions; ++c)
        {
            summary.stresslet[c] += threadSummary[t].stresslet[c];
        }
        summary.nContacts += threadSummary[t].nContacts;
        if (threadSummary[t].maxOverlap > summary.maxOverlap)
        {
            summary.maxOverlap = threadSummary[t].maxOverlap;
            summary.maxOverlapPair[0] = threadSummary[t].maxOverlapPair[0];
            summary.maxOverlapPair[1] = threadSummary[t].maxOverlapPair[1];
        }
    }

    if (perParticle)
    {
        particleStresslet->resize(N);
    }

    std::vector<Mat3> stokesStresslet(nThreads, Mat3::Zero());
    #pragma omp parallel num_threads(nThreads)
    {
        const int t = omp_get_thread_num();

        #pragma omp for schedule(static)
        for (std::size_t i = 0; i < N; ++i)
        {
            const StokesDrag::Result d = hydrodynamic
              ? models_.drag.eval(p.a[i], p.u[i], p.omega[i], ambient_[i])
              : StokesDrag::Result{Vec3::Zero(), Vec3::Zero(), Mat3::Zero()};
            Vec3 F = d.F;
            Vec3 T = d.T;
            for (int s = 0; s < nThreads; ++s)
            {
                F += threadF_[s][i];
                T += threadT_[s][i];
            }
            p.F[i] = F;
            p.T[i] = T;
            stokesStresslet[t] += d.S;
            if (perParticle)
            {
                Mat3 S = d.S;
                for (int s = 0; s < nThreads; ++s)
                {
                    S += threadS_[s][i];
                }
                (*particleStresslet)[i] = S;
            }
        }
    }
    for (int t = 0; t < nThreads; ++t)
    {
        summary.stresslet[stokes] += stokesStresslet[t];
    }

    return summary;
}

} // namespace suspension
