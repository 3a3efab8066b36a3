#include "dynamics/HydrodynamicResistance.H"
#include "dynamics/SimulationError.H"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
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

    // Minimum-image r of a slot, and whether it is in lubrication range
    auto separation = [&](std::size_t i, std::size_t j)
    {
        Vec3 r = p.x[j] - p.x[i];
        box.minimumImage(r);
        return r;
    };
    auto lubricated = [&](std::size_t i, std::size_t j, const Vec3& r)
    {
        const double R = p.a[i] + p.a[j] + gap;
        return gap >= 0 && r.squaredNorm() < R*R;
    };

    // The index of the pairs in lubrication range
    index_.offset.assign(N + 1, 0);
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        std::uint32_t count = 0;
        for (std::uint32_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
        {
            const std::uint32_t j = pairs.j[k];
            count += lubricated(i, j, separation(i, j));
        }
        index_.offset[i + 1] = count;
    }
    for (std::size_t i = 0; i < N; ++i)
    {
        index_.offset[i + 1] += index_.offset[i];
    }
    const std::size_t nPairs = index_.offset[N];
    index_.j.resize(nPairs);
    pairs_.resize(nPairs);
    pairRows_.resize(nPairs);
    ambientForces_.resize(6*N);
    shearRows_.resize(rateChanges_ ? nPairs : 0);
    shearForces_.setZero(rateChanges_ ? 6*N : 0);
    pairStress_.resize(rateChanges_ ? nPairs : 0);

    // A unit shear rate, for F_s and the Stokes stresslet
    FlowSample unit;
    unit.gradU(1, 0) = 1;
    const Mat3 unitShear = unit.E();

    // Pass 1: Stokes drag, pair coefficients and the rows of i of each
    // pair; the rows of j wait in pairRows_. Stresslets per block.
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

            const Vec6 vi = relativeVelocity(p, fi, i);
            std::uint32_t s = index_.offset[i];
            for (std::uint32_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
            {
                const std::uint32_t j = pairs.j[k];
                const Vec3 r = separation(i, j);
                if (!lubricated(i, j, r))
                {
                    continue;
                }
                const PairGeometry g = PairGeometry::make(r, p.a[i], p.a[j]);
                const LubricationCoefficients c = lubrication_->coefficients(g);
                index_.j[s] = j;
                Pair& q = pairs_[s];
                q = Pair{g.n, c.XA, c.YA, c.YB, c.YC};

                // (A.3): F^E, T^E of i now, of j in pass 2
                const Lubrication::PairVector fE = Lubrication::strainForces
                (
                    c, g.n, fi.E(), ambient[j].E()
                );
                b.head<3>() += fE.segment<3>(0);
                b.tail<3>() += fE.segment<3>(6);
                pairRows_[s] << fE.segment<3>(3), fE.segment<3>(9);
                if (rateChanges_)
                {
                    const Lubrication::PairVector fS = Lubrication::strainForces
                    (
                        c, g.n, unitShear, unitShear
                    );
                    shearForces_.segment<3>(6*i) += fS.segment<3>(0);
                    shearForces_.segment<3>(6*i + 3) += fS.segment<3>(6);
                    shearRows_[s] << fS.segment<3>(3), fS.segment<3>(9);
                    pairStress_[s] = {g.r, fE.segment<3>(0), fS.segment<3>(0)};
                }

                // Stresslet (9b) of the force on i at the current velocities
                Vec6 yi, yj;
                pairProduct(q, vi, relativeVelocity(p, ambient[j], j), yi, yj);
                lubricationS[blk] += symm(outer(g.r, fE.segment<3>(0) - yi.head<3>()));
                ++s;
            }
            ambientForces_.segment<6>(6*i) = b;
        }
    }
    index_.transpose();

    // Pass 2: the rows of j, F^E, T^E, in pair order
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t j = 0; j < N; ++j)
    {
        for (std::uint32_t k = index_.offsetT[j]; k < index_.offsetT[j + 1]; ++k)
        {
            ambientForces_.segment<6>(6*j) += pairRows_[index_.slotT[k]];
        }
        if (rateChanges_)
        {
            for (std::uint32_t k = index_.offsetT[j]; k < index_.offsetT[j + 1]; ++k)
            {
                shearForces_.segment<6>(6*j) += shearRows_[index_.slotT[k]];
            }
        }
    }

    // The contacts with a spring in the operator (all, or with the normal
    // springs explicit those with a sticking tangential or rolling one)
    // and their index
    contacts_.clear();
    contactIndex_.offset.assign(N + 1, 0);
    contactIndex_.j.clear();
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
        contactIndex_.j.push_back(c.j);
        ++contactIndex_.offset[c.i + 1];
    }
    contactRows_.resize(contacts_.size());
    for (std::size_t i = 0; i < N; ++i)
    {
        contactIndex_.offset[i + 1] += contactIndex_.offset[i];
    }
    contactIndex_.transpose();

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
    const std::size_t N = index_.nParticles();
    const std::size_t nB = reductionBlocks(N);
    std::vector<Mat3> S(nB, Mat3::Zero());
    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t blk = 0; blk < nB; ++blk)
    {
        const std::size_t end = std::min(N, (blk + 1)*reductionBlock);
        for (std::size_t i = blk*reductionBlock; i < end; ++i)
        {
            const Vec6 vi = v.segment<6>(6*i);
            for (std::uint32_t s = index_.offset[i]; s < index_.offset[i + 1]; ++s)
            {
                const PairStress& q = pairStress_[s];
                Vec6 yi, yj;
                pairProduct(pairs_[s], vi, v.segment<6>(6*index_.j[s]), yi, yj);
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
    const double eta = drag_.params().eta;
    const double a = p.a[i];
    const double m = invDt*p.m[i];
    const double I = invDt*p.I[i];

    // R: the Stokes drag (A.1) and the self blocks of R_Lub
    Block R = Block::Zero();
    R.diagonal() << Vec3::Constant(6*pi*eta*a), Vec3::Constant(8*pi*eta*a*a*a);
    for (std::uint32_t s = index_.offset[i]; s < index_.offset[i + 1]; ++s)
    {
        const Pair& q = pairs_[s];
        R += selfBlock(q.n, q.XA.ii, q.YA.ii, q.YB.ii, q.YC.ii);
    }
    for (std::uint32_t k = index_.offsetT[i]; k < index_.offsetT[i + 1]; ++k)
    {
        const Pair& q = pairs_[index_.slotT[k]];
        R += selfBlock(q.n, q.XA.jj, q.YA.jj, q.YB.jj, q.YC.jj);
    }

    // K and Gamma: the springs and dashpots of its contacts
    Block K = Block::Zero();
    Block G = Block::Zero();
    auto add = [&](const Contact& c, double side, double radius)
    {
        const ContactStiffness& k = c.k;
        K += contactSelfBlock(c.n, side, radius, c.aij, k.kn, k.kt, k.kr);
        G.topLeftCorner<3, 3>() += k.gammaN*outer(c.n, c.n);
    };
    for (std::uint32_t s = contactIndex_.offset[i]; s < contactIndex_.offset[i + 1]; ++s)
    {
        add(contacts_[s], -1, contacts_[s].ai);
    }
    for (std::uint32_t t = contactIndex_.offsetT[i]; t < contactIndex_.offsetT[i + 1]; ++t)
    {
        const Contact& c = contacts_[contactIndex_.slotT[t]];
        add(c, 1, c.aj);
    }

    Block A = R + dt*K + G;
    A.diagonal() += (Vec6() << Vec3::Constant(m), Vec3::Constant(I)).finished();
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
    const std::size_t nPairs =
        index_.offset[i + 1] - index_.offset[i]
      + index_.offsetT[i + 1] - index_.offsetT[i];
    const std::size_t nContacts =
        contactIndex_.offset[i + 1] - contactIndex_.offset[i]
      + contactIndex_.offsetT[i + 1] - contactIndex_.offsetT[i];

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
    translation_.resize(N);
    rotation_.resize(N);
    inverseA_.resize(N);

    // The diagonal block of A of each particle, inverted; the first whose
    // factorisation fails or whose inverse is not finite
    std::size_t failed = N;
    #pragma omp parallel for schedule(static) reduction(min:failed) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        const double a = p.a[i];
        translation_[i] = 6*pi*eta*a + invDt*p.m[i];
        rotation_[i] = 8*pi*eta*a*a*a + invDt*p.I[i];
        const Eigen::LLT<Block> llt(diagonalBlock(p, i, dt, invDt));
        inverseA_[i] = llt.solve(Block::Identity());
        if (llt.info() != Eigen::Success || !inverseA_[i].allFinite())
        {
            failed = std::min(failed, i);
        }
    }
    if (failed < N)
    {
        throw SimulationError(blockFailure(p, failed, dt, invDt));
    }

    for (Contact& c : contacts_)
    {
        c.cn = dt*c.k.kn + c.k.gammaN;
        c.ct = dt*c.k.kt;
        c.cr = dt*c.k.kr;
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

    #pragma omp parallel if(threaded(N))
    {
        // Pass 1: rows of i; rows of j into contactRows_
        #pragma omp for schedule(static)
        for (std::size_t i = 0; i < N; ++i)
        {
            const Vec6 vi = v.segment<6>(6*i);
            Vec6 Vi;
            Vi << Vec3::Zero(), ambient[i].Omega();
            Vec6 bi = Vec6::Zero();
            for (std::uint32_t s = contactIndex_.offset[i]; s < contactIndex_.offset[i + 1]; ++s)
            {
                const Contact& c = contacts_[s];
                const std::uint32_t j = contactIndex_.j[s];
                Vec6 Vj;
                Vj << c.dUinf + shift*c.dy*Vec3::UnitX(), ambient[j].Omega();
                const Modes ambientModes = contactModes(c, Vi, Vj);
                const Modes start = contactModes(c, vi, v.segment<6>(6*j));
                const Modes m
                {
                    c.k.gammaN*start.n - dt*c.k.kn*ambientModes.n,
                    -dt*c.k.kt*ambientModes.t,
                    -dt*c.k.kr*ambientModes.r
                };
                Vec6 rowsI;
                contactTranspose(c, m, rowsI, contactRows_[s]);
                bi += rowsI;
            }
            b.segment<6>(6*i) += bi;
        }

        // Pass 2: rows of j, in pair order
        #pragma omp for schedule(static)
        for (std::size_t j = 0; j < N; ++j)
        {
            Vec6 bj = Vec6::Zero();
            for (std::uint32_t t = contactIndex_.offsetT[j]; t < contactIndex_.offsetT[j + 1]; ++t)
            {
                bj += contactRows_[contactIndex_.slotT[t]];
            }
            b.segment<6>(6*j) += bj;
        }
    }
}


void HydrodynamicResistance::apply(const Vector& x, Vector& y) const
{
    const std::size_t N = translation_.size();
    y.resize(6*N);

    #pragma omp parallel if(threaded(N))
    {
        // Pass 1: diagonal, rows of i; rows of j into pairRows_
        #pragma omp for schedule(static)
        for (std::size_t i = 0; i < N; ++i)
        {
            const Vec6 xi = x.segment<6>(6*i);
            Vec6 yi;
            yi << translation_[i]*xi.head<3>(), rotation_[i]*xi.tail<3>();
            for (std::uint32_t s = index_.offset[i]; s < index_.offset[i + 1]; ++s)
            {
                Vec6 rowsI;
                pairProduct
                (
                    pairs_[s], xi, x.segment<6>(6*index_.j[s]), rowsI, pairRows_[s]
                );
                yi += rowsI;
            }
            for (std::uint32_t s = contactIndex_.offset[i]; s < contactIndex_.offset[i + 1]; ++s)
            {
                const Contact& c = contacts_[s];
                Vec6 rowsI;
                contactProduct
                (
                    c, xi, x.segment<6>(6*contactIndex_.j[s]), rowsI, contactRows_[s]
                );
                yi += rowsI;
            }
            y.segment<6>(6*i) = yi;
        }

        // Pass 2: rows of j, in pair order
        #pragma omp for schedule(static)
        for (std::size_t j = 0; j < N; ++j)
        {
            Vec6 yj = Vec6::Zero();
            for (std::uint32_t k = index_.offsetT[j]; k < index_.offsetT[j + 1]; ++k)
            {
                yj += pairRows_[index_.slotT[k]];
            }
            for (std::uint32_t k = contactIndex_.offsetT[j]; k < contactIndex_.offsetT[j + 1]; ++k)
            {
                yj += contactRows_[contactIndex_.slotT[k]];
            }
            y.segment<6>(6*j) += yj;
        }
    }
}


void HydrodynamicResistance::precondition(const Vector& r, Vector& z) const
{
    const std::size_t N = inverseA_.size();
    z.resize(6*N);

    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        z.segment<6>(6*i) = inverseA_[i]*r.segment<6>(6*i);
    }
}

} // namespace suspension
