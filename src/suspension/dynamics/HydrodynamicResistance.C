#include "dynamics/HydrodynamicResistance.H"
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

    //- Diagonal 6 x 6 block of R_Lub of one sphere of the pair, from its
    //  self entries (ii or jj) of X^A, Y^A, Y^B, Y^C (layout of
    //  Lubrication.H: force-velocity A, force-spin Y^B [n x], torque-velocity
    //  -Y^B [n x], torque-spin Y^C T)
    Block selfBlock(const Vec3& n, double XA, double YA, double YB, double YC)
    {
        const Mat3 N = outer(n, n);
        const Mat3 T = Mat3::Identity() - N;
        const Mat3 nx = crossMatrix(n);
        Block D;
        D.topLeftCorner<3, 3>() = XA*N + YA*T;
        D.topRightCorner<3, 3>() = YB*nx;
        D.bottomLeftCorner<3, 3>() = -YB*nx;
        D.bottomRightCorner<3, 3>() = YC*T;
        return D;
    }

    //- The coupling of a lubricated pair on one of its spheres: the terms
    //  of R_Lub on it due to the motion xp of its partner, with the
    //  pair's off-diagonal scalars (Lubrication.H layout): the force
    //  X^A (n.u_p) n + Y^A u_p,T + Bf n x omega_p, the torque
    //  -Bt n x u_p + Y^C omega_p,T, where (Bf, Bt) = (Y^B_ji, Y^B_ij) on
    //  the first sphere and (Y^B_ij, Y^B_ji) on the second
    inline Vec6 coupling
    (
        const Vec3& n,
        double XA,
        double YA,
        double Bf,
        double Bt,
        double YC,
        const Vec6& xp
    )
    {
        const Vec3 u = xp.head<3>();
        const Vec3 w = xp.tail<3>();
        const double nu = n.dot(u);
        Vec6 y;
        y.head<3>() = (XA - YA)*nu*n + YA*u + Bf*n.cross(w);
        y.tail<3>() = -Bt*n.cross(u) + YC*(w - n.dot(w)*n);
        return y;
    }

    //- The row of the first sphere of a lubricated pair (its own motion xi,
    //  the partner's xj, its self entries ii = X^A, Y^A, Y^B, Y^C): the
    //  self terms have the form of a coupling with Bf = Bt = Y^B_ii
    inline Vec6 firstRow
    (
        const HydrodynamicResistance::Pair& c,
        const double (&ii)[4],
        const Vec6& xi,
        const Vec6& xj
    )
    {
        return coupling(c.n, ii[0], ii[1], ii[2], ii[2], ii[3], xi)
            + coupling(c.n, c.XA, c.YA, c.YBji, c.YBij, c.YC, xj);
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
    const StokesDrag& drag,
    const Lubrication* lubrication,
    bool implicitNormalContact,
    bool shearForces
)
:
    drag_(drag),
    lubrication_(),
    implicitNormalContact_(implicitNormalContact),
    rateChanges_(shearForces),
    stokesShear_(Mat3::Zero())
{
    if (lubrication)
    {
        lubrication_ = *lubrication;
    }
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
    const double gap = lubrication_ ? lubrication_->gap() : -1;

    // The minimum-image r of each slot of the list, computed once: NaN
    // for a slot out of lubrication range; the count of each first
    // particle
    separation_.resize(pairs.nPairs());
    first_.assign(N + 1, 0);
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        std::uint32_t count = 0;
        for (std::uint32_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
        {
            const std::uint32_t j = pairs.j[k];
            Vec3 r = p.x[j] - p.x[i];
            box.minimumImage(r);
            const double R = p.a[i] + p.a[j] + gap;
            const bool in = gap >= 0 && r.squaredNorm() < R*R;
            separation_[k] = in ? r : Vec3::Constant(std::nan(""));
            count += in;
        }
        first_[i + 1] = count;
    }
    for (std::size_t i = 0; i < N; ++i)
    {
        first_[i + 1] += first_[i];
    }
    const std::size_t nPairs = first_[N];
    partner_.resize(nPairs);
    pairs_.resize(nPairs);
    secondRows_.resize(nPairs);
    selfR_.resize(N);
    ambientForces_.resize(6*N);
    shearRows_.resize(rateChanges_ ? nPairs : 0);
    shearForces_.setZero(rateChanges_ ? 6*N : 0);
    pairStress_.resize(rateChanges_ ? nPairs : 0);

    // A unit shear rate, for F_s and the Stokes stresslet
    FlowSample unit;
    unit.gradU(1, 0) = 1;
    const Mat3 unitShear = unit.E();

    // Pass 1, over the first particles: Stokes drag, pair coefficients,
    // the terms of i; those of j wait in secondRows_. Stresslets per block.
    std::vector<Mat3> stokesS(nB, Mat3::Zero());
    std::vector<Mat3> stokesUnitS(nB, Mat3::Zero());
    std::vector<Mat3> lubricationS(nB, Mat3::Zero());
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t blk = 0; blk < nB; ++blk)
    {
        const std::size_t end = std::min(N, (blk + 1)*reductionBlock);
        for (std::size_t i = blk*reductionBlock; i < end; ++i)
        {
            const double a = p.a[i];
            const FlowSample& fi = ambient[i];

            // Drag at u = U_inf, omega = Omega_inf: the Faxen force (A.1)
            const StokesDrag::Result d = drag_.eval(a, fi.U, fi.Omega(), fi);
            Vec6 b;
            b << d.F, d.T;
            stokesS[blk] += d.S;
            if (rateChanges_)
            {
                stokesUnitS[blk] += drag_.eval(a, unit.U, unit.Omega(), unit).S;
            }
            Block R = Block::Zero();

            const Vec6 vi = relativeVelocity(p, fi, i);
            std::uint32_t s = first_[i];
            for (std::uint32_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
            {
                const Vec3& r = separation_[k];
                if (std::isnan(r.x()))
                {
                    continue;
                }
                const std::uint32_t j = pairs.j[k];
                const PairGeometry g = PairGeometry::make(r, a, p.a[j]);
                const LubricationCoefficients c = lubrication_->coefficients(g);
                partner_[s] = j;
                Pair& q = pairs_[s];
                q = Pair{g.n, c.XA.ij, c.YA.ij, c.YB.ij, c.YB.ji, c.YC.ij};
                R += selfBlock(g.n, c.XA.ii, c.YA.ii, c.YB.ii, c.YC.ii);

                // (A.3): F^E, T^E of i now, of j in pass 2
                const Lubrication::PairVector fE = Lubrication::strainForces
                (
                    c, g.n, fi.E(), ambient[j].E()
                );
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
                }

                // Stresslet (9b) of the force on i at the current velocities
                const Vec6 yi = firstRow(q, ii, vi, relativeVelocity(p, ambient[j], j));
                lubricationS[blk] += symm(outer(g.r, fE.segment<3>(0) - yi.head<3>()));
                ++s;
            }
            ambientForces_.segment<6>(6*i) = b;
            selfR_[i] = R;
        }
    }
    rows_.build(first_, partner_);

    // Pass 2, over the second particles: their self blocks, F^E, T^E (and
    // F_s), in pair order
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t j = 0; j < N; ++j)
    {
        Block& R = selfR_[j];
        for (std::uint32_t e = rows_.offset[j]; e < rows_.offset[j + 1]; ++e)
        {
            if (!PairRows::second(rows_.slot[e]))
            {
                continue;
            }
            const std::uint32_t s = PairRows::slotOf(rows_.slot[e]);
            const SecondRow& second = secondRows_[s];
            R += selfBlock(pairs_[s].n, second.jj[0], second.jj[1], second.jj[2], second.jj[3]);
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

    Stresslets S{Mat3::Zero(), Mat3::Zero()};
    stokesShear_.setZero();
    for (std::size_t blk = 0; blk < nB; ++blk)
    {
        S.stokes += stokesS[blk];
        S.lubrication += lubricationS[blk];
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
                const PairStress& q = pairStress_[s];
                const Vec6 yi = firstRow(pairs_[s], q.ii, vi, v.segment<6>(6*rows_.partner[e]));
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
    const double eta = drag_.params().eta;
    const double a = p.a[i];
    Block A = selfR_[i] + dt*K + G;
    A.diagonal() +=
        (Vec6() << Vec3::Constant(6*pi*eta*a + invDt*p.m[i]),
                   Vec3::Constant(8*pi*eta*a*a*a + invDt*p.I[i])).finished();
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
        if (lubrication_ && lubrication_->params().terms == LubricationTerms::extended)
        {
            msg << "; lubrication terms extended gives R_Lub negative"
                   " eigenvalues at small gaps (LubricationCoefficients.H):"
                   " use terms leading with an implicit integrator";
        }
    }
    return msg.str();
}


void HydrodynamicResistance::setStep(const Particles& p, double dt, bool inertia)
{
    const std::size_t N = p.size();
    const double eta = drag_.params().eta;
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
    // factorisation fails or whose inverse is not finite
    std::size_t failed = N;
    #pragma omp parallel for schedule(static) reduction(min:failed) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        const double a = p.a[i];
        diagonal_[i] = {6*pi*eta*a + invDt*p.m[i], 8*pi*eta*a*a*a + invDt*p.I[i]};
        const Eigen::LLT<Block> llt(diagonalBlock(p, i, dt, invDt));
        const Block inverse = llt.solve(Block::Identity());
        inverseA_[i] = inverse.cast<float>();
        if
        (
            llt.info() != Eigen::Success || !inverse.allFinite()
         || !inverseA_[i].allFinite()
        )
        {
            failed = std::min(failed, i);
        }
    }
    if (failed < N)
    {
        throw SimulationError(blockFailure(p, failed, dt, invDt));
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
        Vec6 yi = selfR_[i]*xi;
        yi.head<3>() += diagonal_[i][0]*xi.head<3>();
        yi.tail<3>() += diagonal_[i][1]*xi.tail<3>();
        for (std::uint32_t e = rows_.offset[i]; e < rows_.offset[i + 1]; ++e)
        {
            const std::uint32_t code = rows_.slot[e];
            const Pair& c = pairs_[PairRows::slotOf(code)];
            const Vec6 xj = x.segment<6>(6*rows_.partner[e]);
            yi += PairRows::second(code)
              ? coupling(c.n, c.XA, c.YA, c.YBij, c.YBji, c.YC, xj)
              : coupling(c.n, c.XA, c.YA, c.YBji, c.YBij, c.YC, xj);
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
                yi += rows2;
            }
            else
            {
                contactProduct(c, xi, xj, rows1, rows2);
                yi += rows1;
            }
        }
        y.segment<6>(6*i) = yi;
    }
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
    for (Eigen::Index i = start/6; i < (start + length)/6; ++i)
    {
        z.segment<6>(6*i) = inverseA_[i].cast<double>()*r.segment<6>(6*i);
    }
}

} // namespace suspension
