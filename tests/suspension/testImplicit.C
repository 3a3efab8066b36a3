// The implicit integrators: resistance operator, CG solve, stability and
// trajectories against independent references
#include "dynamics/Simulation.H"
#include "modelTestTools.H"
#include "flow/ShearFlow.H"
#include "packing/RandomPacking.H"
#include "packing/SizeDistribution.H"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>

using namespace suspension;

namespace
{
    const double rho = 1e-3;        // St (eq. 11)

    //- 30 random spheres (radii 1 and 1.4, overlaps allowed) in a sheared
    //  box with a wavy flow, lubrication only; random velocities and
    //  random explicit forces F_c in F, T
    struct RandomBox
    {
        ForceModels models;
        LeesEdwardsBox box{Vec3(11, 11, 11), 1.0};
        ShearFlow flow{1.0, 2.0, 1.0, 11.0};
        Particles p;
        PairList pairs;
        std::vector<FlowSample> ambient;

        explicit RandomBox(unsigned seed)
        {
            models.set(Lubrication(test::lubrication(1e-3, 0.5)));
            box.setStrain(box.shearRate()*(0.37));
            std::mt19937 gen(seed);
            std::uniform_real_distribution<double> u(0, 1);
            for (int i = 0; i < 30; ++i)
            {
                const Vec3 x = Vec3(u(gen), u(gen), u(gen))*11.0;
                p.add(x, (i % 2) ? 1.4 : 1.0, rho, i);
                p.u.back() = Vec3(u(gen), u(gen), u(gen)) - Vec3::Constant(0.5);
                p.omega.back() = Vec3(u(gen), u(gen), u(gen)) - Vec3::Constant(0.5);
                p.F.back() = Vec3(u(gen), u(gen), u(gen)) - Vec3::Constant(0.5);
                p.T.back() = Vec3(u(gen), u(gen), u(gen)) - Vec3::Constant(0.5);
            }
            NeighbourSearch search({models.interactionGap(), 0.1});
            search.rebuild(p, box, pairs);
            for (const Vec3& x : p.x)
            {
                ambient.push_back(flow.sample(x));
            }
        }

        //- Indices of the 12 pair unknowns (U_i, U_j, Omega_i, Omega_j) of
        //  Lubrication.H in the 6-per-particle layout
        static std::array<int, 12> pairIndex(int i, int j)
        {
            std::array<int, 12> k;
            for (int d = 0; d < 3; ++d)
            {
                k[d] = 6*i + d;
                k[3 + d] = 6*j + d;
                k[6 + d] = 6*i + 3 + d;
                k[9 + d] = 6*j + 3 + d;
            }
            return k;
        }

        //- Every pair in lubrication range, by brute force
        void forLubricatedPairs
        (
            const std::function<void(int, int, const PairGeometry&)>& f
        ) const
        {
            const int N = p.size();
            for (int i = 0; i < N; ++i)
            {
                for (int j = i + 1; j < N; ++j)
                {
                    Vec3 r = p.x[j] - p.x[i];
                    box.minimumImage(r);
                    const PairGeometry g = PairGeometry::make(r, p.a[i], p.a[j]);
                    if (g.h < models.get<Lubrication>()->gap())
                    {
                        f(i, j, g);
                    }
                }
            }
        }

        //- R + M invDt, dense, from A.1 and Lubrication::resistanceMatrix
        Eigen::MatrixXd denseA(double invDt) const
        {
            const int N = p.size();
            Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6*N, 6*N);
            for (int i = 0; i < N; ++i)
            {
                const double a = p.a[i];
                for (int d = 0; d < 3; ++d)
                {
                    A(6*i + d, 6*i + d) = 6*pi*a + invDt*p.m[i];
                    A(6*i + 3 + d, 6*i + 3 + d) = 8*pi*a*a*a + invDt*p.I[i];
                }
            }
            forLubricatedPairs([&](int i, int j, const PairGeometry& g)
            {
                const Lubrication::PairMatrix R =
                    models.get<Lubrication>()->resistanceMatrix(g);
                const std::array<int, 12> k = pairIndex(i, j);
                for (int r = 0; r < 12; ++r)
                    for (int c = 0; c < 12; ++c)
                        A(k[r], k[c]) += R(r, c);
            });
            return A;
        }

        //- Hydrodynamic forces at V = V_inf: Faxen (A.1) and strain (A.3)
        Eigen::VectorXd denseAmbientForces() const
        {
            const int N = p.size();
            Eigen::VectorXd F = Eigen::VectorXd::Zero(6*N);
            for (int i = 0; i < N; ++i)
            {
                const double a = p.a[i];
                F.segment<3>(6*i) = 6*pi*a*a*a/6*ambient[i].laplacianU;
            }
            forLubricatedPairs([&](int i, int j, const PairGeometry& g)
            {
                const Lubrication::PairVector fE =
                    models.get<Lubrication>()->strainForces(g, ambient[i].E(), ambient[j].E());
                const std::array<int, 12> k = pairIndex(i, j);
                for (int r = 0; r < 12; ++r)
                    F(k[r]) += fE(r);
            });
            return F;
        }

        //- (u - U_inf, omega - Omega_inf), or (F, T), as one vector
        Eigen::VectorXd stack
        (
            const std::vector<Vec3>& a,
            const std::vector<Vec3>& b,
            bool relative
        ) const
        {
            Eigen::VectorXd v(6*p.size());
            for (std::size_t i = 0; i < p.size(); ++i)
            {
                v.segment<3>(6*i) = a[i] - (relative ? ambient[i].U : Vec3::Zero());
                v.segment<3>(6*i + 3) = b[i] - (relative ? ambient[i].Omega() : Vec3::Zero());
            }
            return v;
        }
    };


    //- Surface gap of a pair of particles
    double gap(const Particles& p)
    {
        return (p.x[1] - p.x[0]).norm() - p.a[0] - p.a[1];
    }

    //- Two spheres of radius 1 at gap h0 along e_x, pushed together by +-F
    //  along their line of centres, stepped by the implicit integrator
    //  with the models' other forces; the gap after each step
    std::vector<double> pushedPair
    (
        const ForceModels& models,
        bool inertia,
        double F,
        double h0,
        double dt,
        int steps
    )
    {
        LeesEdwardsBox box(Vec3(20, 20, 20), 0.0);
        const ShearFlow flow(0.0);
        Particles p;
        p.add(Vec3(9, 10, 10), 1.0, rho, 0);
        p.add(Vec3(11 + h0, 10, 10), 1.0, rho, 1);
        ForceField forces(models, p.a);
        ImplicitEuler implicit(models, inertia, ConjugateGradient::Params());
        NeighbourSearch search({1.0, 0.5});
        PairList pairs;
        search.rebuild(p, box, pairs);

        std::vector<LinearisedContact> contacts;
        auto evaluate = [&](double dtContact)
        {
            ForceSummary summary = forces.advance
            (
                p, box, flow, pairs, search.far(), dtContact,
                ForceField::Forces::nonHydrodynamic, &contacts
            );
            const Vec3 n = (p.x[1] - p.x[0]).normalized();
            p.F[0] += F*n;
            p.F[1] -= F*n;
            implicit.evaluate(p, box, forces.ambient(), pairs, contacts, summary);
        };

        std::vector<double> h;
        evaluate(0);
        for (int k = 0; k < steps; ++k)
        {
            implicit.solve(p, forces.ambient(), 0, dt);
            ImplicitEuler::move(p, box, dt);
            evaluate(dt);
            h.push_back(gap(p));
        }
        return h;
    }

    //- Classical RK4 for y' = f(y), n steps of dt
    template<class State, class F>
    State rk4(State y, F f, double dt, int n)
    {
        for (int k = 0; k < n; ++k)
        {
            const State k1 = f(y);
            const State k2 = f(y + 0.5*dt*k1);
            const State k3 = f(y + 0.5*dt*k2);
            const State k4 = f(y + dt*k3);
            y += dt/6*(k1 + 2*k2 + 2*k3 + k4);
        }
        return y;
    }

    //- The largest |z - D^-1 x| when z = P x and P is D^-1 rounded to
    //  single precision entry by entry (HydrodynamicResistance.H): each
    //  entry off by at most 2^-24 of itself, so at most 2^-24 |D^-1| |x|
    //  (Frobenius norm), and a margin of 1 % for the double arithmetic
    double singlePrecision
    (
        const Eigen::Matrix<double, 6, 6>& D,
        const Eigen::Matrix<double, 6, 1>& x
    )
    {
        return 1.01*std::ldexp(1.0, -24)*D.inverse().norm()*x.norm();
    }

    Simulation::Params simParams(Integrator integrator)
    {
        Simulation::Params s;
        s.rho = rho;
        s.integrator = integrator;
        return s;
    }
}


TEST(Implicit, MatrixFreeProductEqualsDenseAssembly)
{
    RandomBox s(3);
    HydrodynamicResistance R(s.models);
    R.assemble(s.p, s.box, s.ambient, s.pairs);
    ASSERT_GT(R.nPairs(), 20u);

    std::mt19937 gen(7);
    std::normal_distribution<double> normal;
    const int n = 6*s.p.size();
    Eigen::VectorXd x(n);
    for (int k = 0; k < n; ++k) x(k) = normal(gen);

    for (const bool inertia : {false, true})
    {
        const double dt = 1e-4;
        const double invDt = inertia ? 1/dt : 0;
        R.setStep(s.p, dt, inertia);
        const Eigen::MatrixXd A = s.denseA(invDt);
        Eigen::VectorXd y;
        R.apply(x, y);
        const Eigen::VectorXd yDense = A*x;
        EXPECT_LT((y - yDense).norm(), 1e-13*yDense.norm());

        // Block-Jacobi: the inverses of the 6 x 6 diagonal blocks, kept in
        // single precision
        Eigen::VectorXd z;
        R.precondition(x, z);
        for (std::size_t i = 0; i < s.p.size(); ++i)
        {
            const Eigen::Matrix<double, 6, 6> D = A.block<6, 6>(6*i, 6*i);
            const Eigen::Matrix<double, 6, 1> xi = x.segment<6>(6*i);
            EXPECT_LT((z.segment<6>(6*i) - D.inverse()*xi).norm(), singlePrecision(D, xi));
        }
        // The dense operator is symmetric positive definite
        EXPECT_LT((A - A.transpose()).norm(), 1e-13*A.norm());
        EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().minCoeff(), 0);
    }

    const Eigen::VectorXd Famb = s.denseAmbientForces();
    EXPECT_LT((R.ambientForces() - Famb).norm(), 1e-13*Famb.norm());
}


TEST(Implicit, PreconditionerInvertsTheDiagonalBlocksWithContacts)
{
    // Springs and dashpots on every third pair of the list, so that the
    // diagonal blocks of A hold R, dt K and Gamma; each block is read
    // from the operator itself, A applied to the unit vectors of one
    // particle
    RandomBox s(3);
    std::vector<LinearisedContact> contacts;
    for (std::uint32_t i = 0; i < s.p.size(); ++i)
    {
        for (std::uint32_t k = s.pairs.offset[i]; k < s.pairs.offset[i + 1]; k += 3)
        {
            const std::uint32_t j = s.pairs.j[k];
            Vec3 r = s.p.x[j] - s.p.x[i];
            s.box.minimumImage(r);
            contacts.push_back
            ({
                i, j, r.normalized(), s.p.a[i], s.p.a[j], Vec3::Zero(), r.y(),
                ContactStiffness{4e3, 0.7, (k % 2) ? 1e3 : 0.0, 3e2}
            });
        }
    }
    HydrodynamicResistance R(s.models);
    HydrodynamicResistance R0(s.models);
    R.assemble(s.p, s.box, s.ambient, s.pairs, contacts);
    R0.assemble(s.p, s.box, s.ambient, s.pairs);
    ASSERT_GT(R.nContacts(), 10u);

    const std::size_t N = s.p.size();
    std::mt19937 gen(11);
    std::normal_distribution<double> normal;
    Eigen::VectorXd x(6*N);
    for (int k = 0; k < x.size(); ++k) x(k) = normal(gen);

    for (const bool inertia : {false, true})
    {
        const double dt = 1e-3;
        R.setStep(s.p, dt, inertia);
        R0.setStep(s.p, dt, inertia);
        Eigen::VectorXd z, z0;
        R.precondition(x, z);
        R0.precondition(x, z0);
        for (std::size_t i = 0; i < N; ++i)
        {
            Eigen::Matrix<double, 6, 6> D;
            for (int c = 0; c < 6; ++c)
            {
                Eigen::VectorXd e = Eigen::VectorXd::Zero(6*N), y;
                e(6*i + c) = 1;
                R.apply(e, y);
                D.col(c) = y.segment<6>(6*i);
            }
            const Eigen::Matrix<double, 6, 1> xi = x.segment<6>(6*i);
            EXPECT_LT((z.segment<6>(6*i) - D.inverse()*xi).norm(), singlePrecision(D, xi))
                << "particle " << i << ", inertia " << inertia;
        }
        // The contacts change the blocks (a preconditioner without them
        // would pass the check above only where a particle has none)
        EXPECT_GT((z - z0).norm(), 1e-2*z0.norm());
    }
}


TEST(Implicit, ResistanceGivesTheForcesAndStressOfTheExplicitPairLoop)
{
    // -R V' + F_amb and the hydrodynamic stresslets equal Stokes drag plus
    // lubrication as the explicit scheme's ForceField evaluates them
    RandomBox s(4);
    ImplicitEuler implicit(s.models, true, ConjugateGradient::Params());
    ForceSummary summary;
    implicit.evaluate(s.p, s.box, s.ambient, s.pairs, {}, summary);

    Particles q = s.p;
    PairList pairs = s.pairs;
    ForceField forces(s.models, q.a);
    const ForceSummary explicitSummary =
        forces.advance(q, s.box, s.flow, pairs, PairRows(), 0);

    HydrodynamicResistance R(s.models);
    R.assemble(s.p, s.box, s.ambient, s.pairs);
    R.setStep(s.p, 1, false);
    Eigen::VectorXd RV;
    R.apply(s.stack(s.p.u, s.p.omega, true), RV);
    const Eigen::VectorXd F = R.ambientForces() - RV;
    const Eigen::VectorXd Fexplicit = s.stack(q.F, q.T, false);
    EXPECT_LT((F - Fexplicit).norm(), 1e-12*Fexplicit.norm());

    std::vector<int> hydrodynamic = R.pairContributions();
    ASSERT_EQ(hydrodynamic.size(), 1u);
    hydrodynamic.push_back(contributionIndex("stokes"));
    for (const int c : hydrodynamic)
    {
        const Mat3& S = explicitSummary.stresslet[c];
        EXPECT_LT((summary.stresslet[c] - S).norm(), 1e-12*S.norm())
            << contributionNames()[c];
    }
}


namespace
{
    struct HydrodynamicWithResistance
    {
        static constexpr bool hydrodynamic = true;
        LubricationCoefficients coefficients(const PairGeometry&) const;
    };

    struct HydrodynamicWithoutResistance
    {
        static constexpr bool hydrodynamic = true;
        PairForce eval(const PairGeometry&, const PairKinematics&) const;
    };

    struct NotHydrodynamic
    {
        static constexpr bool hydrodynamic = false;
    };
}


TEST(Implicit, RegistryRefusesAHydrodynamicModelWithoutItsResistance)
{
    // The check behind ForceModels.H's static_assert: an implicit
    // integrator can drop no hydrodynamic pair model of the registry
    EXPECT_TRUE(resistanceOfEveryHydrodynamicModel(PairModels()));
    EXPECT_TRUE
    (
        resistanceOfEveryHydrodynamicModel
        (
            ModelList<HydrodynamicWithResistance, NotHydrodynamic>()
        )
    );
    EXPECT_FALSE
    (
        resistanceOfEveryHydrodynamicModel
        (
            ModelList<Lubrication, HydrodynamicWithoutResistance, NotHydrodynamic>()
        )
    );
}


TEST(Implicit, SolvedVelocitiesSatisfyTheDenseResistanceEquations)
{
    // Contacts off: (M/dt + R) V' = (M/dt) V'^n + F_amb + F_c, and the
    // overdamped R V' = F_amb + F_c, with R and F_amb assembled densely
    for (const bool inertia : {true, false})
    {
        RandomBox s(5);
        const double dt = 1e-4;
        const double invDt = inertia ? 1/dt : 0;
        const Eigen::VectorXd Vn = s.stack(s.p.u, s.p.omega, true);
        const Eigen::VectorXd Fc = s.stack(s.p.F, s.p.T, false);

        ConjugateGradient::Params cg;
        cg.tolerance = 1e-8;
        ImplicitEuler implicit(s.models, inertia, cg);
        ForceSummary summary;
        implicit.evaluate(s.p, s.box, s.ambient, s.pairs, {}, summary);
        implicit.solve(s.p, s.ambient, 0, dt);
        EXPECT_TRUE(implicit.statistics().converged);
        EXPECT_GT(implicit.statistics().iterations, 5u);
        EXPECT_LE(implicit.statistics().residual, cg.tolerance);

        Eigen::VectorXd M(Vn.size());
        for (std::size_t i = 0; i < s.p.size(); ++i)
        {
            M.segment<6>(6*i) <<
                Vec3::Constant(s.p.m[i]), Vec3::Constant(s.p.I[i]);
        }
        const Eigen::VectorXd b =
            invDt*M.cwiseProduct(Vn) + s.denseAmbientForces() + Fc;
        const Eigen::VectorXd V = s.stack(s.p.u, s.p.omega, true);
        const double residual = (s.denseA(invDt)*V - b).norm()/b.norm();
        EXPECT_LT(residual, cg.tolerance) << "inertia " << inertia;
    }
}


TEST(Implicit, SqueezeIsStableFarBeyondTheExplicitLimitAndFollowsTheOde)
{
    // Two spheres pushed together by +-F against Stokes drag and the
    // regularised squeeze resistance, at 100 times the explicit limit
    ForceModels models;
    models.set(Lubrication(test::lubrication(1e-3, 0.5)));
    const TimeStepLimits explicitLimits(models, 1.0, 1.0, rho, 1.0);
    ASSERT_EQ(explicitLimits.binding().name, "lubrication");
    const double dt = 100*explicitLimits.binding().value;

    const double F = 100;
    const double h0 = 0.2;
    const double duration = 2000*dt;    // closes the gap to ~ 0.006

    // Reference: the line-of-centres ODE of sphere 1, with velocity v and
    // resistance zeta(h) = 6 pi eta a + X^A_jj - X^A_ji (sphere 0 moves
    // with -v), dh/dt = 2 v; overdamped v = -F/zeta(h)
    auto zeta = [&](double h)
    {
        const LubricationCoefficients c =
            models.get<Lubrication>()->coefficients(PairGeometry::make(Vec3(2 + h, 0, 0), 1, 1));
        return 6*pi + c.XA.jj - c.XA.ji;
    };
    const double m = 4.0/3.0*pi*rho;

    for (const bool inertia : {true, false})
    {
        // The gap at 10 times from a fine RK4 integration of the ODE
        using State = Eigen::Vector2d;      // (h, v)
        auto rhs = [&](const State& y) -> State
        {
            if (inertia)
            {
                return State(2*y(1), (-F - zeta(y(0))*y(1))/m);
            }
            return State(-2*F/zeta(y(0)), 0);
        };
        const int sub = 10000;              // RK4 steps per output time
        std::vector<double> reference;
        State y(h0, 0);
        for (int k = 1; k <= 10; ++k)
        {
            y = rk4(y, rhs, duration/10/sub, sub);
            reference.push_back(y(0));
        }

        // The implicit scheme, largest relative error at the 10 times
        auto maxError = [&](int stepsPerOutput)
        {
            const int steps = 10*stepsPerOutput;
            const std::vector<double> h =
                pushedPair(models, inertia, F, h0, duration/steps, steps);

            // Stable: the gap closes monotonically, no oscillation
            for (int k = 1; k < steps; ++k)
            {
                EXPECT_LT(h[k], h[k - 1]) << "step " << k;
            }
            EXPECT_GT(h0/h.back(), 20);     // closes to the regularised scale

            double e = 0;
            for (int k = 1; k <= 10; ++k)
            {
                const double hRef = reference[k - 1];
                e = std::max(e, std::abs(h[k*stepsPerOutput - 1] - hRef)/hRef);
            }
            return e;
        };

        const double e = maxError(200);
        EXPECT_LT(e, 0.01) << "inertia " << inertia;
        // First order: half the step, half the error
        const double eHalf = maxError(400);
        EXPECT_NEAR(e/eHalf, 2, 0.1) << "inertia " << inertia;
    }
}


TEST(Implicit, LoneSphereInWavyFlowMovesWithFaxenVelocity)
{
    const Vec3 L(8, 8, 8);
    const ShearFlow flow(1.0, 3.0, 1.0, L.y());
    const double a = 1.2;
    ForceModels models;
    models.set(FrictionalContact(FrictionalContact::fromGroups(4e5, 2.0/7.0, 1e-7, 1.0)));

    for (const Integrator integrator : {Integrator::implicitEuler, Integrator::overdamped})
    {
        LeesEdwardsBox box(L, 1.0);
        Particles p;
        p.add(Vec3(2, 3.1, 4), a, rho, 0);
        // Converged to the velocities of the last step within the CG
        // tolerance, the warm start is kept: solve tighter than tested.
        // The contact springs are implicit and set no step: 200 steps
        Simulation::Params params = simParams(integrator);
        params.solver.tolerance = 1e-12;
        params.deltaT = 1e-4;
        Simulation sim(p, box, flow, models, params);
        sim.start(0);
        sim.advance(0.02);     // ~ 60 drag relaxation times
        const Vec3 x = sim.particles().x[0];
        const FlowSample f = flow.sample(x);
        const Vec3 expected = f.U + a*a/6*f.laplacianU;
        EXPECT_LT((sim.particles().u[0] - expected).norm(), 1e-10*expected.norm());
        EXPECT_LT((sim.particles().omega[0] - f.Omega()).norm(), 1e-10);
        EXPECT_GT((a*a/6*f.laplacianU).norm(), 0.1);
    }
}


TEST(Implicit, DiluteViscosityAgreesWithVelocityVerlet)
{
    // phi = 0.1, random packing (near-touching pairs), lubrication and
    // frictional contact; the explicit run takes about 100 x more steps
    const std::vector<double> radii =
        SizeDistribution::bidisperse(1.0, 1.4, 1.0).radii(100);
    RandomPacking::Params pp;
    pp.phi = 0.1;
    pp.seed = 3;
    pp.reach = 0.35;        // the run's: lubrication gap 0.25 + skin 0.1
    const RandomPacking::Result packed = RandomPacking(pp).pack(radii, rho);
    ForceModels models;
    models.set(Lubrication(test::lubrication(1e-2, 0.25)));
    models.set(FrictionalContact(FrictionalContact::fromGroups(4e5, 2.0/7.0, 1e-7, 1.0)));

    const ShearFlow flow(1.0);
    std::vector<Rheology> result;
    for (const Integrator integrator : {Integrator::velocityVerlet, Integrator::implicitEuler})
    {
        Particles p = packed.particles;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            p.u[i] = flow.sample(p.x[i]).U;
            p.omega[i] = flow.sample(p.x[i]).Omega();
        }
        Simulation sim(p, LeesEdwardsBox(packed.box.L(), 1.0), flow, models, simParams(integrator));
        sim.start(0);
        sim.advance(0.01);
        result.push_back(sim.rheology());
    }
    EXPECT_NEAR(result[1].etaR, result[0].etaR, 0.01*result[0].etaR);
    const int lubrication = contributionIndex("lubrication");
    EXPECT_GT(result[0].etaRPart[lubrication], 0.01);
    EXPECT_NEAR
    (
        result[1].etaRPart[lubrication], result[0].etaRPart[lubrication],
        0.01*result[0].etaRPart[lubrication]
    );
}


TEST(Implicit, IndependentOfThreadCount)
{
    // Random box with overlaps and every force model, a few implicit steps;
    // more particles than parallelMinParticles(), so that every loop runs
    // on two threads too
    const std::size_t N = parallelMinParticles() + 100;
    const double side = 12*std::cbrt(N/300.0);
    const Vec3 L(side, side, side);
    const ShearFlow flow(1.0, 2.0, 1.0, L.y());
    ForceModels models;
    models.set(Lubrication(test::lubrication(1e-3, 0.25)));
    FrictionalContact::Params c = FrictionalContact::fromGroups(4e5, 2.0/7.0, 1e-7, 1.0);
    c.kr = 0.1*c.kn;
    models.set(FrictionalContact(c));
    std::mt19937 gen(2);
    std::uniform_real_distribution<double> u(0, 1);
    Particles start;
    for (std::size_t i = 0; i < N; ++i)
    {
        start.add(Vec3(u(gen), u(gen), u(gen)).cwiseProduct(L), (i % 2) ? 1.4 : 1.0, rho, i);
    }
    Simulation::Params params = simParams(Integrator::implicitEuler);
    params.maxOverlap = 10;     // random boxes overlap

    const int threads = omp_get_max_threads();
    std::vector<Particles> result;
    std::vector<Rheology> stress;
    std::vector<std::size_t> iterations;
    for (int nt : {1, 2})
    {
        omp_set_num_threads(nt);
        Simulation sim(start, LeesEdwardsBox(L, 1.0), flow, models, params);
        sim.start(0.1);
        for (int s = 0; s < 5; ++s) sim.step(1e-5);
        result.push_back(sim.particles());
        stress.push_back(sim.rheology());
        iterations.push_back(sim.implicit()->statistics().iterations);
    }
    omp_set_num_threads(threads);

    EXPECT_GT(iterations[0], 5u);
    for (std::size_t i = 0; i < start.size(); ++i)
    {
        EXPECT_EQ(result[0].id[i], result[1].id[i]);
        EXPECT_LT((result[0].u[i] - result[1].u[i]).norm(), 1e-10*(1 + result[0].u[i].norm()));
        EXPECT_LT((result[0].x[i] - result[1].x[i]).norm(), 1e-12*L.norm());
    }
    EXPECT_NEAR(stress[0].etaR, stress[1].etaR, 1e-10*std::abs(stress[0].etaR));
}


TEST(Implicit, LubricationGapBoundsTheImplicitStepForSmallEpsilon)
{
    // Contacts with lubrication: the contact springs are implicit and set
    // no limit, so the accuracy bound 25 eps/G binds; it scales with
    // eps/G, and neither the explicit integrator nor a flow without
    // gradient has it
    auto models = [](double eps)
    {
        ForceModels m;
        m.set(FrictionalContact(FrictionalContact::fromGroups(4e5, 2.0/7.0, 1e-7, 0.0)));
        m.set(Lubrication(test::lubrication(eps, 0.05)));
        return m;
    };
    auto limit = [](const TimeStepLimits& l, const std::string& name)
    {
        for (const TimeStepLimit& t : l.all())
        {
            if (t.name == name)
            {
                return t.value;
            }
        }
        return -1.0;
    };
    const Integrator implicit = Integrator::implicitEuler;

    const TimeStepLimits small(models(1e-4), 1.0, 1.4, rho, 0.2, implicit, 1.0);
    EXPECT_EQ(small.binding().name, "lubricationGap");
    EXPECT_DOUBLE_EQ(small.binding().value, 25*1e-4);
    EXPECT_EQ(limit(small, "contact"), -1.0);

    const TimeStepLimits wavy(models(1e-4), 1.0, 1.4, rho, 0.2, implicit, 4.0);
    EXPECT_DOUBLE_EQ(limit(wavy, "lubricationGap"), 25*1e-4/4);

    // At the paper's eps = 1e-3 too, overdamped as well; the explicit
    // integrator keeps its contact limit
    for (const Integrator integrator : {implicit, Integrator::overdamped})
    {
        const TimeStepLimits paper(models(1e-3), 1.0, 1.4, rho, 0.2, integrator, 1.0);
        EXPECT_EQ(paper.binding().name, "lubricationGap");
        EXPECT_EQ(limit(paper, "contact"), -1.0);
    }
    EXPECT_GT
    (
        limit
        (
            TimeStepLimits(models(1e-3), 1.0, 1.4, rho, 0.2, Integrator::velocityVerlet, 1.0),
            "contact"
        ),
        0
    );

    EXPECT_EQ(limit(TimeStepLimits(models(1e-4), 1.0, 1.4, rho, 0.2, implicit, 0.0), "lubricationGap"), -1.0);
    EXPECT_EQ
    (
        limit
        (
            TimeStepLimits(models(1e-4), 1.0, 1.4, rho, 0.2, Integrator::velocityVerlet, 1.0),
            "lubricationGap"
        ),
        -1.0
    );
}


TEST(Implicit, AdaptiveStepsBoundTheDisplacementAndLandOnTheInterval)
{
    // A lone sphere in the wavy flow, overdamped, no explicit force: no
    // stability limit, so the displacement bound sets the steps. It moves
    // along x at the Faxen velocity, so |u - U_inf| = |a^2/6 lap U| stays.
    const Vec3 L(8, 8, 8);
    const ShearFlow flow(1.0, 3.0, 1.0, L.y());
    const double a = 1.2;
    Particles p;
    p.add(Vec3(2, 3.1, 4), a, rho, 0);
    const FlowSample f = flow.sample(p.x[0]);
    p.u[0] = f.U + a*a/6*f.laplacianU;
    p.omega[0] = f.Omega();

    Simulation::Params params = simParams(Integrator::overdamped);
    params.maxDisplacement = 0;
    EXPECT_THROW
    (
        Simulation(p, LeesEdwardsBox(L, 1.0), flow, ForceModels(), params),
        std::invalid_argument
    );

    params.maxDisplacement = 0.01;
    Simulation sim(p, LeesEdwardsBox(L, 1.0), flow, ForceModels(), params);
    sim.start(0);
    sim.advance(0.5);
    const double bound = params.maxDisplacement*a/(a*a/6*f.laplacianU).norm();
    EXPECT_EQ(sim.time(), 0.5);
    EXPECT_EQ(sim.steps(), static_cast<std::uint64_t>(std::ceil(0.5/bound)));
    EXPECT_GT(sim.steps(), 10u);
    ASSERT_EQ(sim.stepLimitCounts().size(), 2u);
    EXPECT_EQ(sim.stepLimitCounts()[1].name, "maxDisplacement");
    EXPECT_EQ(sim.stepLimitCounts()[1].steps, sim.steps());
}
