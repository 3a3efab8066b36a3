#include "dynamics/HydrodynamicResistance.H"
#include "core/Scratch.H"
#include "dynamics/SimulationError.H"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace suspension
{

namespace
{
    using Vec6 = HydrodynamicResistance::Vec6;
    using Block = HydrodynamicResistance::Block;

    //- The coupling of a lubricated pair on one of its spheres: the terms
    //  of R_Lub on it due to the motion xp of its partner (Lubrication.H
    //  layout): the force X^A (n.u_p) n + Y^A u_p,T + Bf n x omega_p, the
    //  torque -Bt n x u_p + Y^C omega_p,T (HydrodynamicResistance::
    //  Coupling)
    inline void addCoupling
    (
        const Vec3& n,
        double XA,
        double YA,
        double Bf,
        double Bt,
        double YC,
        const double* xp,
        double (&y)[6]
    )
    {
        const double nx = n.x(), ny = n.y(), nz = n.z();
        const double ux = xp[0], uy = xp[1], uz = xp[2];
        const double wx = xp[3], wy = xp[4], wz = xp[5];
        const double nu = (XA - YA)*(nx*ux + ny*uy + nz*uz);
        const double nw = YC*(nx*wx + ny*wy + nz*wz);
        y[0] += nu*nx + YA*ux + Bf*(ny*wz - nz*wy);
        y[1] += nu*ny + YA*uy + Bf*(nz*wx - nx*wz);
        y[2] += nu*nz + YA*uz + Bf*(nx*wy - ny*wx);
        y[3] += YC*wx - nw*nx - Bt*(ny*uz - nz*uy);
        y[4] += YC*wy - nw*ny - Bt*(nz*ux - nx*uz);
        y[5] += YC*wz - nw*nz - Bt*(nx*uy - ny*ux);
    }

    //- S += the self block of R_Lub of one sphere of a pair, from its self
    //  entries (ii or jj): X^A N + Y^A T, Y^B [n x] and Y^C T
    inline void addSelf
    (
        HydrodynamicResistance::SelfBlock& S,
        const Vec3& n,
        double XA,
        double YA,
        double YB,
        double YC
    )
    {
        const double d = XA - YA;
        S.A[0] += YA + d*n.x()*n.x();
        S.A[1] += d*n.x()*n.y();
        S.A[2] += d*n.x()*n.z();
        S.A[3] += YA + d*n.y()*n.y();
        S.A[4] += d*n.y()*n.z();
        S.A[5] += YA + d*n.z()*n.z();
        S.b += YB*n;
        S.C[0] += YC*(1 - n.x()*n.x());
        S.C[1] -= YC*n.x()*n.y();
        S.C[2] -= YC*n.x()*n.z();
        S.C[3] += YC*(1 - n.y()*n.y());
        S.C[4] -= YC*n.y()*n.z();
        S.C[5] += YC*(1 - n.z()*n.z());
    }

    //- The symmetric 3 x 3 of its 6 upper entries (xx, xy, xz, yy, yz, zz)
    inline Mat3 symmetric(const double (&s)[6])
    {
        Mat3 M;
        M << s[0], s[1], s[2],
             s[1], s[3], s[4],
             s[2], s[4], s[5];
        return M;
    }

    //- y += the self block applied to x: (A u + b x omega, -b x u + C omega)
    inline void addSelf
    (
        const HydrodynamicResistance::SelfBlock& S,
        const double* x,
        double (&y)[6]
    )
    {
        const double ux = x[0], uy = x[1], uz = x[2];
        const double wx = x[3], wy = x[4], wz = x[5];
        const double bx = S.b.x(), by = S.b.y(), bz = S.b.z();
        y[0] += S.A[0]*ux + S.A[1]*uy + S.A[2]*uz + (by*wz - bz*wy);
        y[1] += S.A[1]*ux + S.A[3]*uy + S.A[4]*uz + (bz*wx - bx*wz);
        y[2] += S.A[2]*ux + S.A[4]*uy + S.A[5]*uz + (bx*wy - by*wx);
        y[3] += S.C[0]*wx + S.C[1]*wy + S.C[2]*wz - (by*uz - bz*uy);
        y[4] += S.C[1]*wx + S.C[3]*wy + S.C[4]*wz - (bz*ux - bx*uz);
        y[5] += S.C[2]*wx + S.C[4]*wy + S.C[5]*wz - (bx*uy - by*ux);
    }

    //- The self block as a 6 x 6 matrix
    inline Block full(const HydrodynamicResistance::SelfBlock& S)
    {
        const Mat3 bx = crossMatrix(S.b);
        Block D;
        D.topLeftCorner<3, 3>() = symmetric(S.A);
        D.topRightCorner<3, 3>() = bx;
        D.bottomLeftCorner<3, 3>() = -bx;
        D.bottomRightCorner<3, 3>() = symmetric(S.C);
        return D;
    }

    //- The row of the first sphere of a lubricated pair (its own motion xi,
    //  the partner's xj, its self entries ii = X^A, Y^A, Y^B, Y^C): the
    //  self terms have the form of a coupling with Bf = Bt = Y^B_ii
    inline Vec6 firstRow
    (
        const HydrodynamicResistance::Coupling& c,
        const double (&ii)[4],
        const Vec6& xi,
        const Vec6& xj
    )
    {
        double y[6] = {0, 0, 0, 0, 0, 0};
        addCoupling(c.n, ii[0], ii[1], ii[2], ii[2], ii[3], xi.data(), y);
        addCoupling(c.n, c.XA, c.YA, c.Bf, c.Bt, c.YC, xj.data(), y);
        return Eigen::Map<const Vec6>(y);
    }

    //- The modes of a pair in contact (header): u_n, u_t, u_r of its
    //  velocities xi, xj
    struct Modes
    {
        double n;
        Vec3 t;
        Vec3 r;
    };

    inline Modes contactModes
    (
        const HydrodynamicResistance::Contact& c,
        const Vec6& xi,
        const Vec6& xj
    )
    {
        const Vec3 du = xj.head<3>() - xi.head<3>();
        const double un = c.n.dot(du);
        return Modes
        {
            un,
            du - un*c.n - (c.ai*xi.tail<3>() + c.aj*xj.tail<3>()).cross(c.n),
            c.aij*c.n.cross(xi.tail<3>() - xj.tail<3>())
        };
    }

    //- B^T s of a pair in contact: its rows of i (yi) and of j (yj)
    inline void contactTranspose
    (
        const HydrodynamicResistance::Contact& c,
        const Modes& s,
        Vec6& yi,
        Vec6& yj
    )
    {
        const Vec3 f = s.n*c.n + s.t;
        const Vec3 nxt = c.n.cross(s.t);
        const Vec3 nxr = c.aij*c.n.cross(s.r);
        yi << -f, -c.ai*nxt - nxr;
        yj << f, -c.aj*nxt + nxr;
    }

    //- (dt K + Gamma) of a pair in contact applied to its velocities xi,
    //  xj: B^T diag(c_n, c_t, c_r) B, its rows of i (yi) and of j (yj).
    //  The tangential and rolling modes only where their springs act (a
    //  frictionless or sliding contact has c_t = 0, no rolling c_r = 0)
    inline void contactProduct
    (
        const HydrodynamicResistance::Contact& c,
        const Vec6& xi,
        const Vec6& xj,
        Vec6& yi,
        Vec6& yj
    )
    {
        const Vec3 du = xj.head<3>() - xi.head<3>();
        const double un = c.n.dot(du);
        Vec3 f = (c.cn*un)*c.n;
        Vec3 Ti = Vec3::Zero();
        Vec3 Tj = Vec3::Zero();
        if (c.ct != 0)
        {
            const Vec3 st = c.ct*
            (
                du - un*c.n - (c.ai*xi.tail<3>() + c.aj*xj.tail<3>()).cross(c.n)
            );
            f += st;
            const Vec3 nxt = c.n.cross(st);
            Ti = -c.ai*nxt;
            Tj = -c.aj*nxt;
        }
        if (c.cr != 0)
        {
            const Vec3 sr = (c.cr*c.aij)*c.n.cross(xi.tail<3>() - xj.tail<3>());
            const Vec3 nxr = c.aij*c.n.cross(sr);
            Ti -= nxr;
            Tj += nxr;
        }
        yi << -f, Ti;
        yj << f, Tj;
    }

    //- Diagonal 6 x 6 block of B^T diag(kn, kt, kr) B of sphere i
    //  (side = -1, radius a_i) or j (side = 1, radius a_j) of a pair
    Block contactSelfBlock
    (
        const Vec3& n,
        double side,
        double a,
        double aij,
        double kn,
        double kt,
        double kr
    )
    {
        const Mat3 N = outer(n, n);
        const Mat3 T = Mat3::Identity() - N;
        const Mat3 nx = crossMatrix(n);
        Block D;
        D.topLeftCorner<3, 3>() = kn*N + kt*T;
        D.topRightCorner<3, 3>() = side*kt*a*nx;
        D.bottomLeftCorner<3, 3>() = -side*kt*a*nx;
        D.bottomRightCorner<3, 3>() = (kt*a*a + kr*aij*aij)*T;
        return D;
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
    const ForceModels& models,
    bool implicitNormalContact,
    bool shearForces
)
:
    models_(models),
    gap_(-1),
    implicitNormalContact_(implicitNormalContact),
    rateChanges_(shearForces),
    stokesShear_(Mat3::Zero())
{
    models_.forEachResistance([&](const auto& m)
    {
        using M = std::decay_t<decltype(m)>;
        pairContributions_.push_back(contributionIndex(M::contribution));
        gap_ = std::max(gap_, m.gap());
    });
}


HydrodynamicResistance::Stresslets HydrodynamicResistance::assemble
(
    const Particles& p,
    const LeesEdwardsBox& box,
    const std::vector<FlowSample>& ambient,
    const PairList& pairs,
    const std::vector<LinearisedContact>& contacts
)
{
    const std::size_t N = p.size();
    const std::size_t nB = reductionBlocks(N);
    const std::size_t nH = pairContributions_.size();
    const double gap = gap_;
    const StokesDrag& drag = models_.drag();
    const bool ghosts = !p.ghost.empty();
    ghostRows_.clear();
    for (std::size_t i = 0; ghosts && i < N; ++i)
    {
        if (p.ghost[i])
        {
            ghostRows_.push_back(static_cast<std::uint32_t>(i));
        }
    }

    // The slots of the list within the range of a hydrodynamic pair
    // model (a byte each) and the count of each first particle. Pass 1
    // takes the minimum image of those again: a few operations, against
    // the 24 bytes a slot that keeping it would hold
    auto separation = [&](std::size_t i, std::uint32_t j)
    {
        Vec3 r = p.x[j] - p.x[i];
        box.minimumImage(r);
        return r;
    };
    resizeScratch(inRange_, pairs.nPairs());
    first_.assign(N + 1, 0);
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        std::uint32_t count = 0;
        for (std::uint32_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
        {
            const std::uint32_t j = pairs.j[k];
            const double R = p.a[i] + p.a[j] + gap;
            const bool in = gap >= 0 && separation(i, j).squaredNorm() < R*R;
            inRange_[k] = in;
            count += in;
        }
        first_[i + 1] = count;
    }
    for (std::size_t i = 0; i < N; ++i)
    {
        first_[i + 1] += first_[i];
    }
    const std::size_t nPairs = first_[N];
    resizeScratch(partner_, nPairs);
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        std::uint32_t s = first_[i];
        for (std::uint32_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
        {
            if (inRange_[k])
            {
                partner_[s++] = pairs.j[k];
            }
        }
    }
    rows_.build(first_, partner_);
    resizeScratch(couplings_, rows_.partner.size());
    resizeScratch(secondRows_, nPairs);
    selfR_.resize(N);
    ambientForces_.resize(6*N);
    resizeScratch(shearRows_, rateChanges_ ? nPairs : 0);
    shearForces_.setZero(rateChanges_ ? 6*N : 0);
    resizeScratch(pairStress_, rateChanges_ ? nPairs : 0);
    resizeScratch(uncounted_, rateChanges_ && ghosts ? nPairs : 0);

    // A unit shear rate, for F_s and the Stokes stresslet
    FlowSample unit;
    unit.gradU(1, 0) = 1;
    const Mat3 unitShear = unit.E();

    // Pass 1, over the first particles: Stokes drag, pair coefficients,
    // the terms of i and its couplings (the first entries of its row, in
    // slot order); those of j wait in secondRows_. Stresslets per block.
    std::vector<Mat3> stokesS(nB, Mat3::Zero());
    std::vector<Mat3> stokesUnitS(nB, Mat3::Zero());
    std::vector<Mat3> pairS(nB*nH, Mat3::Zero());
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t blk = 0; blk < nB; ++blk)
    {
        const std::size_t end = std::min(N, (blk + 1)*reductionBlock);
        for (std::size_t i = blk*reductionBlock; i < end; ++i)
        {
            const double a = p.a[i];
            const FlowSample& fi = ambient[i];

            // Drag at u = U_inf, omega = Omega_inf: the Faxen force (A.1)
            const StokesDrag::Result d = drag.eval(a, fi.U, fi.Omega(), fi);
            Vec6 b;
            b << d.F, d.T;
            const bool owned = !ghosts || !p.ghost[i];
            if (owned)
            {
                stokesS[blk] += d.S;
            }
            if (rateChanges_ && owned)
            {
                stokesUnitS[blk] += drag.eval(a, unit.U, unit.Omega(), unit).S;
            }
            SelfBlock R{{0, 0, 0, 0, 0, 0}, Vec3::Zero(), {0, 0, 0, 0, 0, 0}};

            const Vec6 vi = relativeVelocity(p, fi, i);
            std::uint32_t s = first_[i];
            std::uint32_t e = rows_.offset[i];
            for (std::uint32_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
            {
                if (!inRange_[k])
                {
                    continue;
                }
                const std::uint32_t j = pairs.j[k];
                const Vec3 r = separation(i, j);
                const PairGeometry g = PairGeometry::make(r, a, p.a[j]);
                const Vec6 vj = relativeVelocity(p, ambient[j], j);
                const bool counted = !ghosts || p.countsPair(i, j);

                // The scalars and (A.3) F^E, T^E of the models in range
                // added, and each model's stresslet (9b) of the force on
                // i at the current velocities
                LubricationCoefficients c = LubricationCoefficients::none();
                Lubrication::PairVector fE = Lubrication::PairVector::Zero();
                std::size_t h = 0;
                models_.forEachResistance([&](const auto& m)
                {
                    const double Rm = a + p.a[j] + m.gap();
                    if (r.squaredNorm() < Rm*Rm)
                    {
                        const LubricationCoefficients cm = m.coefficients(g);
                        const Lubrication::PairVector fEm =
                            Lubrication::strainForces(cm, g.n, fi.E(), ambient[j].E());
                        const double ii[4] = {cm.XA.ii, cm.YA.ii, cm.YB.ii, cm.YC.ii};
                        const Vec6 yi = firstRow
                        (
                            Coupling{g.n, cm.XA.ij, cm.YA.ij, cm.YB.ji, cm.YB.ij, cm.YC.ij},
                            ii, vi, vj
                        );
                        if (counted)
                        {
                            pairS[blk*nH + h] +=
                                symm(outer(g.r, fEm.segment<3>(0) - yi.head<3>()));
                        }
                        c += cm;
                        fE += fEm;
                    }
                    ++h;
                });
                couplings_[e++] = Coupling{g.n, c.XA.ij, c.YA.ij, c.YB.ji, c.YB.ij, c.YC.ij};
                addSelf(R, g.n, c.XA.ii, c.YA.ii, c.YB.ii, c.YC.ii);

                // F^E, T^E of i now, of j in pass 2
                b.head<3>() += fE.segment<3>(0);
                b.tail<3>() += fE.segment<3>(6);
                SecondRow& second = secondRows_[s];
                second.fE << fE.segment<3>(3), fE.segment<3>(9);
                second.jj[0] = c.XA.jj;
                second.jj[1] = c.YA.jj;
                second.jj[2] = c.YB.jj;
                second.jj[3] = c.YC.jj;
                const double ii[4] = {c.XA.ii, c.YA.ii, c.YB.ii, c.YC.ii};
                if (rateChanges_)
                {
                    const Lubrication::PairVector fS = Lubrication::strainForces
                    (
                        c, g.n, unitShear, unitShear
                    );
                    shearForces_.segment<3>(6*i) += fS.segment<3>(0);
                    shearForces_.segment<3>(6*i + 3) += fS.segment<3>(6);
                    shearRows_[s] << fS.segment<3>(3), fS.segment<3>(9);
                    pairStress_[s] =
                        {g.r, fE.segment<3>(0), fS.segment<3>(0), {ii[0], ii[1], ii[2], ii[3]}};
                    if (ghosts)
                    {
                        uncounted_[s] = !counted;
                    }
                }
                ++s;
            }
            ambientForces_.segment<6>(6*i) = b;
            selfR_[i] = R;
        }
    }

    // Pass 2, over the second particles: their couplings (the coupling of
    // the first particle with Bf and Bt exchanged), self blocks, F^E, T^E
    // (and F_s), in pair order
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t j = 0; j < N; ++j)
    {
        SelfBlock& R = selfR_[j];
        for (std::uint32_t e = rows_.offset[j]; e < rows_.offset[j + 1]; ++e)
        {
            if (!PairRows::second(rows_.slot[e]))
            {
                continue;
            }
            const std::uint32_t s = PairRows::slotOf(rows_.slot[e]);
            const std::uint32_t i = rows_.partner[e];
            const Coupling& c = couplings_[rows_.offset[i] + s - first_[i]];
            couplings_[e] = Coupling{c.n, c.XA, c.YA, c.Bt, c.Bf, c.YC};
            const SecondRow& second = secondRows_[s];
            addSelf(R, c.n, second.jj[0], second.jj[1], second.jj[2], second.jj[3]);
            ambientForces_.segment<6>(6*j) += second.fE;
            if (rateChanges_)
            {
                shearForces_.segment<6>(6*j) += shearRows_[s];
            }
        }
    }

    // The contacts with a spring in the operator (all, or with the normal
    // springs explicit those with a sticking tangential or rolling one)
    // and their rows
    contacts_.clear();
    first_.assign(N + 1, 0);
    partner_.clear();
    for (const LinearisedContact& c : contacts)
    {
        ContactStiffness k = c.k;
        if (!implicitNormalContact_)
        {
            k.kn = 0;
            k.gammaN = 0;
            if (k.kt == 0 && k.kr == 0)
            {
                continue;
            }
        }
        contacts_.push_back
        ({
            c.n, c.ai, c.aj, 2*c.ai*c.aj/(c.ai + c.aj), c.dUinf, c.dy, k, 0, 0, 0
        });
        partner_.push_back(c.j);
        ++first_[c.i + 1];
    }
    for (std::size_t i = 0; i < N; ++i)
    {
        first_[i + 1] += first_[i];
    }
    contactRows_.build(first_, partner_);

    Stresslets S{Mat3::Zero(), std::vector<Mat3>(nH, Mat3::Zero())};
    stokesShear_.setZero();
    for (std::size_t blk = 0; blk < nB; ++blk)
    {
        S.stokes += stokesS[blk];
        for (std::size_t h = 0; h < nH; ++h)
        {
            S.pairs[h] += pairS[blk*nH + h];
        }
        stokesShear_ += stokesUnitS[blk];
    }
    return S;
}


Mat3 HydrodynamicResistance::lubricationStresslet
(
    const Vector& v,
    double a,
    double b
) const
{
    if (!rateChanges_)
    {
        throw std::logic_error
        (
            "HydrodynamicResistance: the stresslet of given velocities needs"
            " the data of a resistance constructed with shearForces"
        );
    }
    const std::size_t N = rows_.nParticles();
    const std::size_t nB = reductionBlocks(N);
    std::vector<Mat3> S(nB, Mat3::Zero());
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t blk = 0; blk < nB; ++blk)
    {
        const std::size_t end = std::min(N, (blk + 1)*reductionBlock);
        for (std::size_t i = blk*reductionBlock; i < end; ++i)
        {
            const Vec6 vi = v.segment<6>(6*i);
            for (std::uint32_t e = rows_.offset[i]; e < rows_.offset[i + 1]; ++e)
            {
                if (PairRows::second(rows_.slot[e]))
                {
                    continue;
                }
                const std::uint32_t s = rows_.slot[e];
                if (!uncounted_.empty() && uncounted_[s])
                {
                    continue;
                }
                const PairStress& q = pairStress_[s];
                const Vec6 yi = firstRow(couplings_[e], q.ii, vi, v.segment<6>(6*rows_.partner[e]));
                S[blk] += symm(outer(q.r, a*q.fE + b*q.fS - yi.head<3>()));
            }
        }
    }
    Mat3 sum = Mat3::Zero();
    for (const Mat3& s : S)
    {
        sum += s;
    }
    return sum;
}


std::array<double, 2> HydrodynamicResistance::dragAndInertia
(
    const Particles& p,
    std::size_t i,
    double invDt
) const
{
    const double eta = models_.drag().params().eta;
    const double a = p.a[i];
    return {6*pi*eta*a + invDt*p.m[i], 8*pi*eta*a*a*a + invDt*p.I[i]};
}


HydrodynamicResistance::Block HydrodynamicResistance::diagonalBlock
(
    const Particles& p,
    std::size_t i,
    double dt,
    double invDt
) const
{
    // K and Gamma: the springs and dashpots of its contacts
    Block K = Block::Zero();
    Block G = Block::Zero();
    for (std::uint32_t e = contactRows_.offset[i]; e < contactRows_.offset[i + 1]; ++e)
    {
        const bool second = PairRows::second(contactRows_.slot[e]);
        const Contact& c = contacts_[PairRows::slotOf(contactRows_.slot[e])];
        const ContactStiffness& k = c.k;
        K += contactSelfBlock
        (
            c.n, second ? 1 : -1, second ? c.aj : c.ai, c.aij, k.kn, k.kt, k.kr
        );
        G.topLeftCorner<3, 3>() += k.gammaN*outer(c.n, c.n);
    }

    // R: the Stokes drag (A.1) and the self blocks of R_Lub; M/dt
    const std::array<double, 2> d = dragAndInertia(p, i, invDt);
    Block A = full(selfR_[i]) + dt*K + G;
    A.diagonal() += (Vec6() << Vec3::Constant(d[0]), Vec3::Constant(d[1])).finished();
    return A;
}


std::string HydrodynamicResistance::blockFailure
(
    const Particles& p,
    std::size_t i,
    double dt,
    double invDt
) const
{
    const Block A = diagonalBlock(p, i, dt, invDt);
    const std::size_t nPairs = rows_.offset[i + 1] - rows_.offset[i];
    const std::size_t nContacts = contactRows_.offset[i + 1] - contactRows_.offset[i];

    std::ostringstream msg;
    msg << "the diagonal block of the implicit velocity operator of particle "
        << p.id[i];
    if (!A.allFinite())
    {
        msg << " is not finite: a non-finite state of the particle (x = "
            << p.x[i].transpose() << ", radius " << p.a[i] << ", mass "
            << p.m[i] << ") or of its " << nPairs << " lubricated pairs and "
            << nContacts << " contacts";
    }
    else
    {
        const Vec6 lambda =
            Eigen::SelfAdjointEigenSolver<Block>(A, Eigen::EigenvaluesOnly)
           .eigenvalues();
        msg << " is not positive definite to working precision (eigenvalues "
            << lambda(0) << " to " << lambda(5) << "; radius " << p.a[i]
            << ", mass " << p.m[i] << ", in " << nPairs
            << " lubricated pairs and " << nContacts << " contacts)";
        const Lubrication* lubrication = models_.get<Lubrication>();
        if (lubrication && lubrication->params().terms == LubricationTerms::extended)
        {
            msg << "; lubrication terms extended gives R_Lub negative"
                   " eigenvalues at small gaps (LubricationCoefficients.H):"
                   " use terms leading with an implicit integrator";
        }
    }
    return msg.str();
}


void HydrodynamicResistance::setStep
(
    const Particles& p,
    double dt,
    bool inertia,
    const Domain* domain
)
{
    const std::size_t N = p.size();
    const double invDt = inertia ? 1/dt : 0;
    diagonal_.resize(N);
    inverseA_.resize(N);

    for (Contact& c : contacts_)
    {
        c.cn = dt*c.k.kn + c.k.gammaN;
        c.ct = dt*c.k.kt;
        c.cr = dt*c.k.kr;
    }

    // The diagonal block of A of each particle, inverted; the first whose
    // factorisation fails or whose inverse is not finite. A ghost's is 0
    // (its row is its owner's)
    std::size_t failed = N;
    #pragma omp parallel for schedule(static) reduction(min:failed) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        diagonal_[i] = dragAndInertia(p, i, invDt);
        if (p.isGhost(i))
        {
            inverseA_[i].fill(0);
            continue;
        }
        const Eigen::LLT<Block> llt(diagonalBlock(p, i, dt, invDt));
        const Block inverse = llt.solve(Block::Identity());
        bool finite = inverse.allFinite();
        for (int r = 0, k = 0; r < 6; ++r)
        {
            for (int c = r; c < 6; ++c, ++k)
            {
                inverseA_[i][k] = static_cast<float>(inverse(r, c));
                finite = finite && std::isfinite(inverseA_[i][k]);
            }
        }
        if (llt.info() != Eigen::Success || !finite)
        {
            failed = std::min(failed, i);
        }
    }
    if (domain ? domain->comm().any(failed < N) : failed < N)
    {
        throw SimulationError
        (
            failed < N
          ? blockFailure(p, failed, dt, invDt)
          : "a diagonal block of the implicit velocity operator of another"
            " process is not positive definite or not finite"
        );
    }
}


void HydrodynamicResistance::contactRightHandSide
(
    const Vector& v,
    const std::vector<FlowSample>& ambient,
    double shift,
    double dt,
    Vector& b
) const
{
    const std::size_t N = ambient.size();

    // Each particle adds the terms of its contacts, in row order
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        Vec6 bi = Vec6::Zero();
        for (std::uint32_t e = contactRows_.offset[i]; e < contactRows_.offset[i + 1]; ++e)
        {
            const bool second = PairRows::second(contactRows_.slot[e]);
            const Contact& c = contacts_[PairRows::slotOf(contactRows_.slot[e])];
            const std::size_t first = second ? contactRows_.partner[e] : i;
            const std::size_t other = second ? i : contactRows_.partner[e];
            Vec6 V1, V2;
            V1 << Vec3::Zero(), ambient[first].Omega();
            V2 << c.dUinf + shift*c.dy*Vec3::UnitX(), ambient[other].Omega();
            const Modes ambientModes = contactModes(c, V1, V2);
            const Modes start = contactModes
            (
                c, v.segment<6>(6*first), v.segment<6>(6*other)
            );
            const Modes m
            {
                c.k.gammaN*start.n - dt*c.k.kn*ambientModes.n,
                -dt*c.k.kt*ambientModes.t,
                -dt*c.k.kr*ambientModes.r
            };
            Vec6 rows1, rows2;
            contactTranspose(c, m, rows1, rows2);
            bi += second ? rows2 : rows1;
        }
        b.segment<6>(6*i) += bi;
    }
}


void HydrodynamicResistance::apply(const Vector& x, Vector& y) const
{
    const std::size_t N = inverseA_.size();
    y.resize(6*N);

    // Each particle reads its own row: the drag and M/dt, its self block
    // of R_Lub, the couplings of its lubricated pairs, then its contacts
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        const Vec6 xi = x.segment<6>(6*i);
        const SelfBlock& S = selfR_[i];
        const double* X = x.data();
        double a[6];
        for (int k = 0; k < 3; ++k)
        {
            a[k] = diagonal_[i][0]*xi[k];
            a[k + 3] = diagonal_[i][1]*xi[k + 3];
        }
        addSelf(S, X + 6*i, a);
        for (std::uint32_t e = rows_.offset[i]; e < rows_.offset[i + 1]; ++e)
        {
            const Coupling& c = couplings_[e];
            addCoupling(c.n, c.XA, c.YA, c.Bf, c.Bt, c.YC, X + 6*rows_.partner[e], a);
        }
        for (std::uint32_t e = contactRows_.offset[i]; e < contactRows_.offset[i + 1]; ++e)
        {
            const bool second = PairRows::second(contactRows_.slot[e]);
            const Contact& c = contacts_[PairRows::slotOf(contactRows_.slot[e])];
            const Vec6 xj = x.segment<6>(6*contactRows_.partner[e]);
            Vec6 rows1, rows2;
            if (second)
            {
                contactProduct(c, xj, xi, rows1, rows2);
            }
            else
            {
                contactProduct(c, xi, xj, rows1, rows2);
            }
            const Vec6& rows = second ? rows2 : rows1;
            for (int k = 0; k < 6; ++k)
            {
                a[k] += rows[k];
            }
        }
        for (int k = 0; k < 6; ++k)
        {
            y[6*i + k] = a[k];
        }
    }
    zeroGhostRows(y);
}


void HydrodynamicResistance::precondition(const Vector& r, Vector& z) const
{
    z.resize(r.size());
    precondition(r, z, 0, r.size());
}


void HydrodynamicResistance::precondition
(
    const Vector& r,
    Vector& z,
    Eigen::Index start,
    Eigen::Index length
) const
{
    // Packed upper triangle, row by row: entry (r, c), c >= r, at
    // 6 r - r (r - 1)/2 + c - r
    static constexpr int at[6][6] =
    {
        {0, 1, 2, 3, 4, 5},
        {1, 6, 7, 8, 9, 10},
        {2, 7, 11, 12, 13, 14},
        {3, 8, 12, 15, 16, 17},
        {4, 9, 13, 16, 18, 19},
        {5, 10, 14, 17, 19, 20}
    };
    for (Eigen::Index i = start/6; i < (start + length)/6; ++i)
    {
        const std::array<float, 21>& P = inverseA_[i];
        const double* ri = r.data() + 6*i;
        double* zi = z.data() + 6*i;
        for (int k = 0; k < 6; ++k)
        {
            double sum = 0;
            for (int l = 0; l < 6; ++l)
            {
                sum += double(P[at[k][l]])*ri[l];
            }
            zi[k] = sum;
        }
    }
}

} // namespace suspension
