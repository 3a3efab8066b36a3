#include "dynamics/HydrodynamicResistance.H"

#include <Eigen/Cholesky>
#include <omp.h>

namespace suspension
{

namespace
{
    using Vec6 = HydrodynamicResistance::Vec6;
    using Block = HydrodynamicResistance::Block;

    //- Diagonal 6 x 6 block of R_Lub of one sphere of the pair, from its
    //  self entries (ii or jj) of X^A, Y^A, Y^B, Y^C (layout of
    //  Lubrication.H: force-velocity A, force-spin Y^B [n x], torque-velocity
    //  -Y^B [n x], torque-spin Y^C T)
    Block selfBlock(const Vec3& n, double XA, double YA, double YB, double YC)
    {
        const Mat3 N = outer(n, n);
        const Mat3 T = Mat3::Identity() - N;
        Mat3 nx;
        nx <<       0, -n.z(),  n.y(),
                n.z(),      0, -n.x(),
               -n.y(),  n.x(),      0;
        Block D;
        D.topLeftCorner<3, 3>() = XA*N + YA*T;
        D.topRightCorner<3, 3>() = YB*nx;
        D.bottomLeftCorner<3, 3>() = -YB*nx;
        D.bottomRightCorner<3, 3>() = YC*T;
        return D;
    }

    //- The pair's rows of i (yi) and of j (yj) of R_Lub applied to (xi, xj)
    inline void pairProduct
    (
        const HydrodynamicResistance::Pair& c,
        const Vec6& xi,
        const Vec6& xj,
        Vec6& yi,
        Vec6& yj
    )
    {
        const Vec3& n = c.n;
        const Vec3 ui = xi.head<3>();
        const Vec3 wi = xi.tail<3>();
        const Vec3 uj = xj.head<3>();
        const Vec3 wj = xj.tail<3>();

        // Normal and tangential parts, n x v
        const double nui = n.dot(ui);
        const double nuj = n.dot(uj);
        const Vec3 uiT = ui - nui*n;
        const Vec3 ujT = uj - nuj*n;
        const Vec3 wiT = wi - n.dot(wi)*n;
        const Vec3 wjT = wj - n.dot(wj)*n;
        const Vec3 nxui = n.cross(ui);
        const Vec3 nxuj = n.cross(uj);
        const Vec3 nxwi = n.cross(wi);
        const Vec3 nxwj = n.cross(wj);

        // Rows of R_Lub (Lubrication.H): forces on i, j, then torques on i, j
        yi.head<3>() =
            (c.XA.ii*nui + c.XA.ij*nuj)*n + c.YA.ii*uiT + c.YA.ij*ujT
          + c.YB.ii*nxwi + c.YB.ji*nxwj;
        yj.head<3>() =
            (c.XA.ji*nui + c.XA.jj*nuj)*n + c.YA.ji*uiT + c.YA.jj*ujT
          + c.YB.ij*nxwi + c.YB.jj*nxwj;
        yi.tail<3>() =
           -c.YB.ii*nxui - c.YB.ij*nxuj + c.YC.ii*wiT + c.YC.ij*wjT;
        yj.tail<3>() =
           -c.YB.ji*nxui - c.YB.jj*nxuj + c.YC.ji*wiT + c.YC.jj*wjT;
    }

    //- Velocity of particle i relative to the ambient flow, (u', omega')
    Vec6 relativeVelocity(const Particles& p, const FlowSample& f, std::size_t i)
    {
        Vec6 v;
        v << p.u[i] - f.U, p.omega[i] - f.Omega();
        return v;
    }
}


HydrodynamicResistance::HydrodynamicResistance
(
    const StokesDrag& drag,
    const std::optional<Lubrication>& lubrication
)
:
    drag_(drag),
    lubrication_(lubrication)
{}


HydrodynamicResistance::Stresslets HydrodynamicResistance::assemble
(
    const Particles& p,
    const LeesEdwardsBox& box,
    const std::vector<FlowSample>& ambient,
    const PairList& pairs
)
{
    const std::size_t N = p.size();
    const int nThreads = omp_get_max_threads();
    const double eta = drag_.params().eta;

    auto geometry = [&](std::size_t i, std::size_t j)
    {
        Vec3 r = p.x[j] - p.x[i];
        box.minimumImage(r);
        return PairGeometry::make(r, p.a[i], p.a[j]);
    };
    auto lubricated = [&](const PairGeometry& g)
    {
        return lubrication_ && g.dist < lubrication_->range(g.ai, g.aj);
    };

    // Pairs in lubrication range, counted per first particle
    offset_.assign(N + 1, 0);
    #pragma omp parallel for schedule(static) if(N >= parallelMinParticles)
    for (std::size_t i = 0; i < N; ++i)
    {
        std::uint32_t count = 0;
        for (std::uint32_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
        {
            count += lubricated(geometry(i, pairs.j[k]));
        }
        offset_[i + 1] = count;
    }
    for (std::size_t i = 0; i < N; ++i)
    {
        offset_[i + 1] += offset_[i];
    }
    pairs_.resize(offset_[N]);
    pairRows_.resize(offset_[N]);
    diagonalR_.resize(N);
    ambientForces_.resize(6*N);

    // Pass 1: Stokes drag, pair coefficients and the rows of i of each
    // pair; the rows of j wait in pairRows_
    std::vector<Mat3> stokesS(nThreads, Mat3::Zero());
    std::vector<Mat3> lubricationS(nThreads, Mat3::Zero());
    #pragma omp parallel if(N >= parallelMinParticles)
    {
        const int t = omp_get_thread_num();

        #pragma omp for schedule(static)
        for (std::size_t i = 0; i < N; ++i)
        {
            const double a = p.a[i];
            const FlowSample& fi = ambient[i];

            // Drag at u = U_inf, omega = Omega_inf: the Faxen force (A.1)
            const StokesDrag::Result d = drag_.eval(a, fi.U, fi.Omega(), fi);
            Vec6 b;
            b << d.F, d.T;
            stokesS[t] += d.S;

            Block D = Block::Zero();
            D.diagonal() << Vec3::Constant(6*pi*eta*a), Vec3::Constant(8*pi*eta*a*a*a);

            const Vec6 vi = relativeVelocity(p, fi, i);
            std::uint32_t s = offset_[i];
            for (std::uint32_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
            {
                const std::size_t j = pairs.j[k];
                const PairGeometry g = geometry(i, j);
                if (!lubricated(g))
                {
                    continue;
                }
                const LubricationCoefficients c = lubrication_->coefficients(g);
                Pair& q = pairs_[s];
                q = Pair{static_cast<std::uint32_t>(j), g.n, c.XA, c.YA, c.YB, c.YC};

                // (A.3): F^E, T^E of i now, of j in pass 2
                const Lubrication::PairVector fE = Lubrication::strainForces
                (
                    c, g.n, fi.E(), ambient[j].E()
                );
                b.head<3>() += fE.segment<3>(0);
                b.tail<3>() += fE.segment<3>(6);
                pairRows_[s] << fE.segment<3>(3), fE.segment<3>(9);

                D += selfBlock(g.n, c.XA.ii, c.YA.ii, c.YB.ii, c.YC.ii);

                // Stresslet (9b) of the force on i at the current velocities
                Vec6 yi, yj;
                pairProduct(q, vi, relativeVelocity(p, ambient[j], j), yi, yj);
                lubricationS[t] += symm(outer(g.r, fE.segment<3>(0) - yi.head<3>()));
                ++s;
            }
            ambientForces_.segment<6>(6*i) = b;
            diagonalR_[i] = D;
        }
    }

    // Transposed index: the pairs of each second particle, in pair order
    offsetT_.assign(N + 1, 0);
    for (const Pair& q : pairs_)
    {
        ++offsetT_[q.j + 1];
    }
    for (std::size_t j = 0; j < N; ++j)
    {
        offsetT_[j + 1] += offsetT_[j];
    }
    slotT_.resize(pairs_.size());
    {
        std::vector<std::uint32_t> next(offsetT_.begin(), offsetT_.end() - 1);
        for (std::uint32_t s = 0; s < pairs_.size(); ++s)
        {
            slotT_[next[pairs_[s].j]++] = s;
        }
    }

    // Pass 2: the rows of j, F^E, T^E and diagonal blocks, in pair order
    #pragma omp parallel for schedule(static) if(N >= parallelMinParticles)
    for (std::size_t j = 0; j < N; ++j)
    {
        for (std::uint32_t k = offsetT_[j]; k < offsetT_[j + 1]; ++k)
        {
            const std::uint32_t s = slotT_[k];
            const Pair& q = pairs_[s];
            ambientForces_.segment<6>(6*j) += pairRows_[s];
            diagonalR_[j] += selfBlock(q.n, q.XA.jj, q.YA.jj, q.YB.jj, q.YC.jj);
        }
    }

    Stresslets S{Mat3::Zero(), Mat3::Zero()};
    for (int t = 0; t < nThreads; ++t)
    {
        S.stokes += stokesS[t];
        S.lubrication += lubricationS[t];
    }
    return S;
}


void HydrodynamicResistance::setInertia(const Particles& p, double invDt)
{
    const std::size_t N = p.size();
    const double eta = drag_.params().eta;
    translation_.resize(N);
    rotation_.resize(N);
    inverseA_.resize(N);

    #pragma omp parallel for schedule(static) if(N >= parallelMinParticles)
    for (std::size_t i = 0; i < N; ++i)
    {
        const double a = p.a[i];
        const double m = invDt*p.m[i];
        const double I = invDt*p.I[i];
        translation_[i] = 6*pi*eta*a + m;
        rotation_[i] = 8*pi*eta*a*a*a + I;
        Block A = diagonalR_[i];
        A.diagonal() += (Vec6() << Vec3::Constant(m), Vec3::Constant(I)).finished();
        inverseA_[i] = A.llt().solve(Block::Identity());
    }
}


void HydrodynamicResistance::apply(const Vector& x, Vector& y) const
{
    const std::size_t N = translation_.size();
    y.resize(6*N);

    #pragma omp parallel if(N >= solverParallelMinParticles)
    {
        // Pass 1: diagonal, rows of i; rows of j into pairRows_
        #pragma omp for schedule(static)
        for (std::size_t i = 0; i < N; ++i)
        {
            const Vec6 xi = x.segment<6>(6*i);
            Vec6 yi;
            yi << translation_[i]*xi.head<3>(), rotation_[i]*xi.tail<3>();
            for (std::uint32_t s = offset_[i]; s < offset_[i + 1]; ++s)
            {
                const Pair& q = pairs_[s];
                Vec6 rowsI;
                pairProduct(q, xi, x.segment<6>(6*q.j), rowsI, pairRows_[s]);
                yi += rowsI;
            }
            y.segment<6>(6*i) = yi;
        }

        // Pass 2: rows of j, in pair order
        #pragma omp for schedule(static)
        for (std::size_t j = 0; j < N; ++j)
        {
            Vec6 yj = Vec6::Zero();
            for (std::uint32_t k = offsetT_[j]; k < offsetT_[j + 1]; ++k)
            {
                yj += pairRows_[slotT_[k]];
            }
            y.segment<6>(6*j) += yj;
        }
    }
}


void HydrodynamicResistance::precondition(const Vector& r, Vector& z) const
{
    const std::size_t N = inverseA_.size();
    z.resize(6*N);

    #pragma omp parallel for schedule(static) if(N >= solverParallelMinParticles)
    for (std::size_t i = 0; i < N; ++i)
    {
        z.segment<6>(6*i) = inverseA_[i]*r.segment<6>(6*i);
    }
}

} // namespace suspension
