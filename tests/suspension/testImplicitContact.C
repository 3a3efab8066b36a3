// The contact springs inside the implicit step (ImplicitEuler,
// HydrodynamicResistance, FrictionalContact::stiffness): the linearisation
// against the kernel, two-particle normal, tangential and sliding contacts
// against their analytic overdamped (and inertial) relaxation, far beyond
// the explicit contact limit; the Lees-Edwards ambient term, the stress,
// restart and thread counts of a suspension
#include "dynamics/Simulation.H"
#include "modelTestTools.H"
#include "core/Parallel.H"
#include "flow/ShearFlow.H"
#include "packing/RandomPacking.H"
#include "packing/SizeDistribution.H"
#include "contactTestTools.H"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <tuple>
#include <vector>

using namespace suspension;

namespace
{
    const double rho = 1e-3;        // St (eq. 11)
    const double kHat = 4e5;        // k_n (eq. 12), Table 1
    const double F = 100;           // normal load of the two-particle tests

    using Vec12 = Eigen::Matrix<double, 12, 1>;
    using Mat12 = Lubrication::PairMatrix;

    //- Table 1 springs with mu_C, and lubrication at the paper's eps,
    //  delta_lub
    ForceModels tableOne(double muC)
    {
        return test::lubricatedContacts(0.05, kHat, muC);
    }

    const FrictionalContact::Params& springs(const ForceModels& m)
    {
        return m.get<FrictionalContact>()->params();
    }

    //- Resistance of two unit spheres in contact along e_x (12 dof: U_0,
    //  U_1, Omega_0, Omega_1): Stokes drag and torque (A.1) and the
    //  lubrication at the regularised gap (A.2, A.6), the same for every
    //  overlap
    Mat12 pairResistance(const ForceModels& m)
    {
        const PairGeometry g = PairGeometry::make(Vec3(2 - F/kHat, 0, 0), 1, 1);
        Mat12 R = m.get<Lubrication>()->resistanceMatrix(g);
        for (int d = 0; d < 6; ++d)
        {
            R(d, d) += 6*pi;
            R(6 + d, 6 + d) += 8*pi;
        }
        return R;
    }

    //- Modes of the pair (n = e_x, t = e_y): normal (-n, n, 0, 0) and
    //  tangential (-t, t, -a n x t, -a n x t) (eqs. 4a, 4b, 5)
    Vec12 normalMode()
    {
        Vec12 b = Vec12::Zero();
        b(0) = -1;
        b(3) = 1;
        return b;
    }

    Vec12 tangentialMode()
    {
        Vec12 b = Vec12::Zero();
        b(1) = -1;
        b(4) = 1;
        b(8) = -1;
        b(11) = -1;
        return b;
    }

    double sphereMass() { return 4.0/3.0*pi*rho; }

    //- The old explicit-contact stability limit of a spring k with
    //  dashpot gamma on the mode b against the pair's resistance (the
    //  Jury bound of the scheme that took the springs explicitly):
    //  (c + sqrt(c^2 + 4 k m))/k, c = 1/(b.R^-1 b) - gamma, m the mode's
    //  inertia 1/(b.M^-1 b) (0 overdamped)
    double explicitContactLimit
    (
        const Mat12& R,
        const Vec12& b,
        double k,
        double gamma,
        bool inertia
    )
    {
        const double c = 1/b.dot(R.ldlt().solve(b)) - gamma;
        Vec12 invM;
        invM << Vec3::Constant(1/sphereMass()), Vec3::Constant(1/sphereMass()),
                Vec3::Constant(1/(0.4*sphereMass())), Vec3::Constant(1/(0.4*sphereMass()));
        const double m = inertia ? 1/b.cwiseAbs2().dot(invM) : 0;
        return (c + std::sqrt(c*c + 4*k*m))/k;
    }

    //- After each step of a two-sphere run: the kernel contact force on
    //  sphere 1 along the pair's n and t
    struct PairRun
    {
        std::vector<double> gap;
        std::vector<double> Fn;         // n.F_c, > 0 repulsive
        std::vector<double> Ft;         // t.F_c
        std::vector<double> FtOff;      // |F_c - Fn n - Ft t|
        std::vector<double> slip;       // t.u_t (eq. 5)
        std::size_t linearised = 0;     // contacts in the last solve
    };

    //- Two unit spheres along e_x at gap h0, held together by +-F along
    //  their line of centres and, every step, driven by G b_t along the
    //  tangential mode (sphere 1 by G t, sphere 0 by -G t, both by the
    //  torque -G n x t: no net couple), t the tangent closest to e_y; the
    //  contact history starts at xi0 (oriented from sphere 0 to 1).
    //  Stepped by the implicit integrator as Simulation does, without the
    //  list updates.
    PairRun heldPair
    (
        const ForceModels& models,
        bool inertia,
        double h0,
        const Vec3& xi0,
        double G,
        double dt,
        int steps,
        bool implicitNormal = true
    )
    {
        LeesEdwardsBox box(Vec3(20, 20, 20), 0.0);
        const ShearFlow flow(0.0);
        Particles p;
        p.add(Vec3(9, 10, 10), 1.0, rho, 0);
        p.add(Vec3(11 + h0, 10, 10), 1.0, rho, 1);
        ForceField forces(models, p.a);
        ImplicitEuler implicit
        (
            models, inertia, ConjugateGradient::Params(), implicitNormal
        );
        NeighbourSearch search({models.interactionGap(), 0.5});
        PairList pairs;
        search.rebuild(p, box, pairs);
        const std::size_t s0 = p.id[0] == 0 ? 0 : 1;
        const std::size_t s1 = 1 - s0;
        pairs.clearHistory();
        pairs.setHistory(0, s0 == 0 ? ContactState{xi0, Vec3::Zero()}
                                    : ContactState{-xi0, Vec3::Zero()});

        auto direction = [&]()
        {
            const Vec3 n = (p.x[s1] - p.x[s0]).normalized();
            const Vec3 t = Vec3::UnitY() - n.y()*n;
            return std::make_pair(n, t.normalized());
        };
        PairRun run;
        std::vector<LinearisedContact> contacts;
        auto evaluate = [&](double dtContact)
        {
            ForceSummary summary = forces.advance
            (
                p, box, flow, pairs, search.far(), dtContact,
                ForceField::Forces::nonHydrodynamic, &contacts
            );
            const auto [n, t] = direction();
            if (dtContact > 0)
            {
                const Vec3& Fc = p.F[s1];
                run.gap.push_back((p.x[s1] - p.x[s0]).norm() - 2);
                run.Fn.push_back(n.dot(Fc));
                run.Ft.push_back(t.dot(Fc));
                run.FtOff.push_back((Fc - n.dot(Fc)*n - t.dot(Fc)*t).norm());
                const Vec3 ut =
                    p.u[s1] - p.u[s0] - n.dot(p.u[s1] - p.u[s0])*n
                  - (p.omega[s0] + p.omega[s1]).cross(n);
                run.slip.push_back(t.dot(ut));
            }
            p.F[s0] += F*n - G*t;
            p.F[s1] -= F*n - G*t;
            p.T[s0] -= G*n.cross(t);
            p.T[s1] -= G*n.cross(t);
            implicit.evaluate(p, box, forces.ambient(), pairs, contacts, summary);
        };

        evaluate(0);
        for (int k = 0; k < steps; ++k)
        {
            run.linearised = implicit.resistance().nContacts();
            implicit.solve(p, forces.ambient(), 0, dt);
            ImplicitEuler::move(p, box, dt);
            evaluate(dt);
        }
        return run;
    }

    //- Largest |f(k) - reference(t_k)| over the steps, t_k = (k + 1) dt
    double maxError
    (
        const std::vector<double>& f,
        double dt,
        const std::function<double(double)>& reference
    )
    {
        double e = 0;
        for (std::size_t k = 0; k < f.size(); ++k)
        {
            e = std::max(e, std::abs(f[k] - reference((k + 1)*dt)));
        }
        return e;
    }

    //- A sheared frictional suspension (Table 1 FR groups, phi = 0.5, 60
    //  spheres of radii 1 and 1.4), rolling resistance on, implicit
    struct Suspension
    {
        ForceModels models;
        RandomPacking::Result packed;
        ShearFlow flow{1.0};
        Simulation::Params params;

        explicit Suspension(Integrator integrator)
        :
            models(test::frictionalWithRolling()),
            packed(test::packing(models, rho))
        {
            params.rho = rho;
            params.integrator = integrator;
        }

        Simulation make() const
        {
            return Simulation
            (
                packed.particles, LeesEdwardsBox(packed.box.L(), 1.0), flow,
                models, params
            );
        }

        //- Sheared to strain 0.1, when it has contacts with history
        Simulation sheared() const
        {
            Simulation sim = make();
            sim.start(0);
            sim.advance(0.1);
            return sim;
        }
    };
}


TEST(ImplicitContact, LinearisedSpringsAreTheKernelsForceChange)
{
    // The operator's contact part against finite differences of the
    // kernel: over a short step delta at velocities V, the generalized
    // forces (F_i, F_j, T_i, T_j) change by -delta K V (springs, eqs. 4a,
    // 4b, 5, B.1; the rotation of the small existing forces with the pair
    // is of their order and not in K); at fixed positions a change W of
    // the velocities changes them by -Gamma W (dashpot)
    FrictionalContact::Params c = test::springs(4e5, 1.2e5, 0, 1e9);
    c.kr = 4e4;
    c.muR = 1e9;
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    auto random3 = [&]() { return Vec3(u(gen), u(gen), u(gen)); };

    for (const double gammaN : {0.0, 30.0})
    {
        c.gammaN = gammaN;
        const FrictionalContact contact(c);
        const double ai = 1.0;
        const double aj = 1.4;
        const Vec3 n = Vec3(0.3, 0.9, -0.2).normalized();
        const Vec3 xi = Vec3(3, 4, 5);
        const Vec3 xj = xi + (ai + aj - 1e-5)*n;
        Vec12 V;
        V << random3(), random3(), random3(), random3();    // U_i, U_j, W_i, W_j
        const ContactState state
        {
            1e-6*(random3() - n.dot(random3())*n), Vec3::Zero()
        };

        // The kernel's generalized forces at positions x and velocities v
        auto kernel = [&](const Vec3& x0, const Vec3& x1, const Vec12& v, double dt)
        {
            const PairGeometry g = PairGeometry::make(x1 - x0, ai, aj);
            const PairKinematics kin = test::kinematics
            (
                v.segment<3>(0), v.segment<3>(3), v.segment<3>(6), v.segment<3>(9)
            );
            ContactState next;
            const PairForce f = contact.eval(g, kin, state, next, dt);
            Vec12 G;
            G << f.F, -f.F, f.Ti, f.Tj;
            return G;
        };

        // The operator with and without the contact, drag only
        Particles p;
        p.add(xi, ai, rho, 0);
        p.add(xj, aj, rho, 1);
        for (int s = 0; s < 2; ++s)
        {
            p.u[s] = V.segment<3>(3*s);
            p.omega[s] = V.segment<3>(6 + 3*s);
        }
        const LeesEdwardsBox box(Vec3(20, 20, 20), 0.0);
        const std::vector<FlowSample> ambient(2, ShearFlow(0.0).sample(xi));
        const PairGeometry g = PairGeometry::make(xj - xi, ai, aj);
        const ContactStiffness k = contact.stiffness
        (
            g,
            test::kinematics(p.u[0], p.u[1], p.omega[0], p.omega[1]),
            state
        );
        ASSERT_EQ(k.kt, c.kt);
        ASSERT_EQ(k.kr, c.kr);
        const LinearisedContact linear{0, 1, g.n, ai, aj, Vec3::Zero(), g.r.y(), k};
        PairList noPairs;
        noPairs.offset.assign(3, 0);
        noPairs.transpose();
        HydrodynamicResistance A{ForceModels()};
        HydrodynamicResistance A0{ForceModels()};
        A.assemble(p, box, ambient, noPairs, {linear});
        A0.assemble(p, box, ambient, noPairs, {});
        auto contactPart = [&](const Vec12& v, double dt)
        {
            Eigen::VectorXd x(12), y, y0;
            x << v.segment<3>(0), v.segment<3>(6), v.segment<3>(3), v.segment<3>(9);
            A.setStep(p, dt, false);
            A0.setStep(p, dt, false);
            A.apply(x, y);
            A0.apply(x, y0);
            const Eigen::VectorXd d = y - y0;
            Vec12 out;
            out << d.segment<3>(0), d.segment<3>(6), d.segment<3>(3), d.segment<3>(9);
            return out;
        };

        // Springs: positions moved by delta V, the history by delta u_t
        const double delta = 1e-8;
        const Vec12 dG =
            kernel(xi + delta*V.segment<3>(0), xj + delta*V.segment<3>(3), V, delta)
          - kernel(xi, xj, V, 0);
        const Vec12 KV = contactPart(V, delta) - contactPart(V, 0);
        EXPECT_LT((dG + KV).norm(), 1e-3*dG.norm()) << "gammaN " << gammaN;
        // ... with the torques of the tangential and rolling springs
        EXPECT_GT(dG.tail<6>().norm(), 0.1*dG.norm());

        // Dashpot: the velocities changed by W at the same positions
        Vec12 W;
        W << random3(), random3(), random3(), random3();
        const Vec12 dGW = kernel(xi, xj, V + W, 0) - kernel(xi, xj, V, 0);
        EXPECT_LT((dGW + contactPart(W, 0)).norm(), 1e-9*(1 + dGW.norm()));
        if (gammaN > 0)
        {
            EXPECT_GT(dGW.norm(), 1);
        }
    }
}


TEST(ImplicitContact, StiffnessIsZeroForSlidingOrFrictionlessStretches)
{
    FrictionalContact::Params c = test::springs(4e5, 2.0/7.0*4e5, 0, 0.5);
    c.kr = 4e4;
    const FrictionalContact contact(c);
    const PairGeometry g = PairGeometry::make(Vec3(2 - 1e-4, 0, 0), 1, 1);
    const PairKinematics kin = test::kinematics
    (
        Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()
    );
    const double load = 40;                 // k_n |h|
    const double capT = 0.5*load/c.kt;
    const double capR = 0.5*load/c.kr;

    // Sticking below both caps
    ContactStiffness k = contact.stiffness(g, kin, {Vec3(0, 0.5*capT, 0), Vec3(0, 0, 0.5*capR)});
    EXPECT_EQ(k.kn, c.kn);
    EXPECT_EQ(k.kt, c.kt);
    EXPECT_EQ(k.kr, c.kr);

    // A stretch capped by the kernel slides
    ContactState capped;
    test::advanceContact
    (
        contact, g,
        test::kinematics(Vec3::Zero(), Vec3(0, 10, 0), Vec3::Zero(), Vec3::Zero()),
        capped, 1
    );
    ASSERT_NEAR(capped.xiT.norm(), capT, 1e-10*capT);
    k = contact.stiffness(g, kin, capped);
    EXPECT_EQ(k.kt, 0);
    EXPECT_EQ(k.kn, c.kn);

    // Frictionless: no tangential or rolling stiffness
    c.muC = 0;
    c.muR = 0;
    k = FrictionalContact(c).stiffness(g, kin, ContactState());
    EXPECT_EQ(k.kt, 0);
    EXPECT_EQ(k.kr, 0);

    // The critical-load model: no friction below F_CL
    const CriticalLoadContact clm({test::springs(4e5, 2.0/7.0*4e5, 0, 1), 2*load});
    EXPECT_EQ(clm.stiffness(g, kin, ContactState()).kt, 0);
    const CriticalLoadContact loaded({test::springs(4e5, 2.0/7.0*4e5, 0, 1), 0.5*load});
    EXPECT_GT(loaded.stiffness(g, kin, ContactState()).kt, 0);
}


TEST(ImplicitContact, NormalContactFollowsTheOverdampedRelaxationFarBeyondTheExplicitLimit)
{
    // Two spheres held by +-F, started 50% beyond the equilibrium overlap
    // F/k_n: the overlap relaxes against the pair's resistance along the
    // normal mode, zeta = 6 pi eta a + X^A_11 - X^A_12 at the regularised
    // gap (A.6), and the dashpot: e = h - h*, h* = -F/k_n,
    //   overdamped     (zeta + 2 gamma_n) de/dt = -2 k_n e
    //   with inertia   m e'' + (zeta + 2 gamma_n) e' + 2 k_n e = 0, e'(0) = 0
    const ForceModels models = tableOne(0.0);
    const double kn = springs(models).kn;
    const double gamma = springs(models).gammaN;
    const Mat12 R = pairResistance(models);
    const double c = 2/normalMode().dot(R.ldlt().solve(normalMode())) + 2*gamma;
    const double m = sphereMass();
    const double tau = c/(2*kn);
    const double e0 = -0.5*F/kn;
    const double hEq = -F/kn;

    for (const bool inertia : {false, true})
    {
        // The roots of m r^2 + c r + 2 k_n = 0 (both real: overdamped)
        const double disc = std::sqrt(c*c - 8*m*kn);
        const double r1 = (-c + disc)/(2*m);
        const double r2 = (-c - disc)/(2*m);
        auto reference = [&](double t)
        {
            if (!inertia)
            {
                return hEq + e0*std::exp(-t/tau);
            }
            return hEq + e0*(r1*std::exp(r2*t) - r2*std::exp(r1*t))/(r1 - r2);
        };

        // 100 times the old explicit-contact limit: stable, monotone, at
        // the equilibrium after one step as implicit Euler gives it
        const double dtOld = explicitContactLimit(R, normalMode(), kn, gamma, inertia);
        const PairRun far = heldPair(models, inertia, hEq + e0, Vec3::Zero(), 0, 100*dtOld, 20);
        ASSERT_EQ(far.linearised, 1u);
        double last = std::abs(e0);
        for (std::size_t k = 0; k < far.gap.size(); ++k)
        {
            const double e = far.gap[k] - hEq;
            EXPECT_LE(std::abs(e), last) << "step " << k;
            EXPECT_GE(e/e0, -1e-9) << "step " << k;     // no overshoot
            last = std::abs(e);
        }
        EXPECT_LT(std::abs(far.gap[0] - hEq), 0.01*std::abs(e0));
        EXPECT_LT(std::abs(far.gap.back() - hEq), 1e-6*std::abs(e0));

        // Resolved steps: first order, half the step, half the error
        auto error = [&](int stepsPerTau)
        {
            const double dt = tau/stepsPerTau;
            const PairRun run = heldPair
            (
                models, inertia, hEq + e0, Vec3::Zero(), 0, dt, 5*stepsPerTau
            );
            return maxError(run.gap, dt, reference)/std::abs(e0);
        };
        const double e = error(8);
        EXPECT_LT(e, 0.05) << "inertia " << inertia;
        EXPECT_NEAR(e/error(16), 2, 0.2) << "inertia " << inertia;
    }
}


TEST(ImplicitContact, ExplicitNormalSpringRelaxesAsExplicitEuler)
{
    // The normal spring left explicit (implicitNormalContact false), the
    // overlap error e = h - h* of a frictionless held pair, overdamped,
    // shrinks by 1 - x per step, x = dt 2 k_n/zeta (zeta the normal mode's
    // resistance at the regularised gap; the explicit dashpot, gamma_n =
    // 1e-7 k_n, changes it by ~1e-5); taken implicitly, by 1/(1 + x)
    const ForceModels models = tableOne(0.0);
    const double kn = springs(models).kn;
    const Mat12 R = pairResistance(models);
    const double zeta = 2/normalMode().dot(R.ldlt().solve(normalMode()));
    const double x = 0.5;
    const double dt = x*zeta/(2*kn);
    const double e0 = -0.5*F/kn;
    const double hEq = -F/kn;
    for (const bool implicitNormal : {false, true})
    {
        const PairRun run = heldPair
        (
            models, false, hEq + e0, Vec3::Zero(), 0, dt, 4, implicitNormal
        );
        EXPECT_EQ(run.linearised, implicitNormal ? 1u : 0u);
        const double factor = implicitNormal ? 1/(1 + x) : 1 - x;
        double e = e0;
        for (std::size_t k = 0; k < run.gap.size(); ++k)
        {
            e *= factor;
            EXPECT_NEAR((run.gap[k] - hEq)/e, 1, 1e-3)
                << "implicit normal " << implicitNormal << ", step " << k;
        }
    }
}


TEST(ImplicitContact, NormalSpringImplicitOnlyWhereItsExplicitLimitWouldBind)
{
    // Table 1 FR (k_hat = 4e5, eps = 1e-3): the explicit normal spring's
    // limit is far above slidingFriction's, so auto keeps it explicit and
    // names its limit; frictionless and 1000 times stiffer, it would be
    // 1000 times below lubricationGap, so it is implicit and sets none;
    // the integration entry overrides either way
    auto run = [](double stiffness, double muC, std::optional<bool> given)
    {
        ForceModels m = tableOne(muC);
        m.set(FrictionalContact(FrictionalContact::fromGroups(stiffness, 2.0/7.0, 1e-7, muC)));
        RandomPacking::Params pp;
        pp.phi = 0.3;
        pp.seed = 2;
        pp.reach = m.interactionGap() + Simulation::Params().skin;
        RandomPacking::Result packed = RandomPacking(pp).pack
        (
            SizeDistribution::bidisperse(1.0, 1.4, 1.0).radii(60), rho
        );
        const ShearFlow flow(1.0);
        Simulation::Params params;
        params.rho = rho;
        params.integrator = Integrator::overdamped;
        params.implicitNormalContact = given;
        const Simulation sim
        (
            packed.particles, LeesEdwardsBox(packed.box.L(), 1.0), flow, m, params
        );
        bool named = false;
        for (const TimeStepLimit& l : sim.limits().all())
        {
            named = named || l.name == "contact";
        }
        EXPECT_EQ(named, !sim.implicitNormalContact());
        EXPECT_EQ(sim.implicit()->implicitNormalContact(), sim.implicitNormalContact());
        return sim.implicitNormalContact();
    };
    EXPECT_FALSE(run(kHat, 1, std::nullopt));
    EXPECT_TRUE(run(1000*kHat, 0, std::nullopt));
    EXPECT_TRUE(run(kHat, 1, true));
    EXPECT_FALSE(run(1000*kHat, 0, false));
}


TEST(ImplicitContact, StickingTangentialContactFollowsTheOverdampedRelaxation)
{
    // A frictional pair at its equilibrium overlap with a tangential
    // stretch xi0 (half the Coulomb cap): the spring relaxes along the
    // tangential mode b (rank one), overdamped
    //     dxi/dt = -k_t (b.R^-1 b) xi,
    // R the pair's Stokes drag and torque with its lubrication Y^A, Y^B,
    // Y^C at the regularised gap; with inertia M V' = -R V - k_t xi b,
    // xi' = b.V (RK4 reference). The tangential force is k_t xi.
    const ForceModels models = tableOne(1.0);
    const double kt = springs(models).kt;
    const Mat12 R = pairResistance(models);
    const Vec12 b = tangentialMode();
    const double lambda = b.dot(R.ldlt().solve(b));
    const double tau = 1/(kt*lambda);
    const double xi0 = 0.5*F/kt;
    const double hEq = -F/springs(models).kn;

    Vec12 M;
    M << Vec3::Constant(sphereMass()), Vec3::Constant(sphereMass()),
         Vec3::Constant(0.4*sphereMass()), Vec3::Constant(0.4*sphereMass());

    for (const bool inertia : {false, true})
    {
        // Reference |F_t|(t) = k_t xi(t)
        std::vector<std::pair<double, double>> table;       // (t, k_t xi)
        std::function<double(double)> reference;
        if (!inertia)
        {
            reference = [&](double t) { return kt*xi0*std::exp(-t/tau); };
        }
        else
        {
            // (V, xi) by RK4 on a fine grid, linear interpolation between
            using State = Eigen::Matrix<double, 13, 1>;
            auto rhs = [&](const State& y)
            {
                State d;
                d.head<12>() = (-R*y.head<12>() - kt*y(12)*b).cwiseQuotient(M);
                d(12) = b.dot(y.head<12>());
                return d;
            };
            const double h = 2e-7;
            State y = State::Zero();
            y(12) = xi0;
            table.push_back({0, kt*xi0});
            for (int k = 1; k*h <= 6*tau; ++k)
            {
                const State k1 = rhs(y);
                const State k2 = rhs(y + 0.5*h*k1);
                const State k3 = rhs(y + 0.5*h*k2);
                const State k4 = rhs(y + h*k3);
                y += h/6*(k1 + 2*k2 + 2*k3 + k4);
                table.push_back({k*h, kt*y(12)});
            }
            reference = [&table, h](double t)
            {
                const std::size_t k = std::min<std::size_t>(t/h, table.size() - 2);
                const double w = t/h - k;
                return (1 - w)*table[k].second + w*table[k + 1].second;
            };
        }
        auto forces = [](const PairRun& run)
        {
            std::vector<double> f;
            for (const double Ft : run.Ft)
            {
                f.push_back(-Ft);       // on sphere 1: -k_t xi t
            }
            return f;
        };

        // 100 times the old explicit limit of the tangential spring
        const double dtOld = explicitContactLimit(R, b, kt, 0, inertia);
        const PairRun far = heldPair
        (
            models, inertia, hEq, Vec3(0, xi0, 0), 0, 100*dtOld, 20
        );
        const std::vector<double> f = forces(far);
        double last = kt*xi0;
        for (std::size_t k = 0; k < f.size(); ++k)
        {
            EXPECT_LE(std::abs(f[k]), last + 1e-9*kt*xi0) << "step " << k;
            EXPECT_GE(f[k], -1e-9*kt*xi0) << "step " << k;
            last = std::abs(f[k]);
        }
        EXPECT_LT(f[0], 0.01*kt*xi0);

        // Resolved steps: first order
        auto error = [&](int stepsPerTau)
        {
            const double dt = tau/stepsPerTau;
            const PairRun run = heldPair
            (
                models, inertia, hEq, Vec3(0, xi0, 0), 0, dt, 5*stepsPerTau
            );
            EXPECT_EQ(run.linearised, 1u);
            return maxError(forces(run), dt, reference)/(kt*xi0);
        };
        const double e = error(8);
        EXPECT_LT(e, 0.05) << "inertia " << inertia;
        EXPECT_NEAR(e/error(16), 2, 0.2) << "inertia " << inertia;
    }
}


TEST(ImplicitContact, SlidingContactStaysOnTheCoulombCap)
{
    // A pair held by +-F and driven along the tangential mode by G >
    // mu_C F, at ten times the old explicit limit of the normal spring:
    // the stretch slides on the cap, |F_t| = mu_C |F_n|, its force is
    // explicit (no k_t), so the pair slips at the speed of the force
    // balance with the capped force, t.u_t = (G - mu_C F) b.R^-1 b (a
    // stuck linearisation would slow it by 1 + dt k_t b.R^-1 b)
    const ForceModels models = tableOne(1.0);
    const double muC = springs(models).muC;
    const Mat12 R = pairResistance(models);
    const Vec12 b = tangentialMode();
    // The excess drive small: moving on straight lines, the pair opens
    // by (slip dt)^2/4 a step and loses load, which would feed back
    const double G = muC*F + 1e-3;
    const double hEq = -F/springs(models).kn;
    const double slip = (G - muC*F)*b.dot(R.ldlt().solve(b));
    const double dt = 10*explicitContactLimit
    (
        R, normalMode(), springs(models).kn, springs(models).gammaN, false
    );

    for (const bool inertia : {false, true})
    {
        const PairRun run = heldPair(models, inertia, hEq, Vec3::Zero(), G, dt, 20);
        ASSERT_EQ(run.linearised, 1u);
        // Sticking while the stretch approaches the cap, then sliding
        for (std::size_t k = 5; k < run.Ft.size(); ++k)
        {
            // The Coulomb cap to round-off, the force along -t on sphere 1
            EXPECT_NEAR(-run.Ft[k], muC*std::abs(run.Fn[k]), 1e-12*F) << "step " << k;
            EXPECT_LT(run.FtOff[k], 1e-12*F) << "step " << k;
            EXPECT_NEAR(run.Fn[k], F, 1e-3*F) << "step " << k;
            EXPECT_NEAR(run.slip[k], slip, 1e-2*slip) << "step " << k;
        }
    }
}


TEST(ImplicitContact, SlidingFrictionLimitIsTheChatterThresholdOfASlidingContact)
{
    // The Coulomb force of a sliding stretch is explicit (k_t = 0 in the
    // step). A pair held by +-F at its equilibrium overlap, its stretch on
    // the cap and nothing driving it: overdamped, that force moves it back
    // along the tangential mode b, the stretch becomes xi (1 - dt k_t
    // b.R^-1 b), which sticks again within the cap only for dt < t_s =
    // 2/(k_t b.R^-1 b). slidingFriction is 2.5 t_s, so the default safety
    // 0.2 steps at t_s/2: below t_s the friction relaxes, above it flips
    // from cap to cap every step (chatter)
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
    const ForceModels models = tableOne(1.0);
    const FrictionalContact::Params& c = springs(models);
    const Mat12 R = pairResistance(models);
    const double ts = explicitContactLimit(R, tangentialMode(), c.kt, 0, false);

    const TimeStepLimits limits(models, 1.0, 1.0, rho, 0.2, Integrator::overdamped, 1.0);
    EXPECT_NEAR(limit(limits, "slidingFriction"), 2.5*ts, 1e-6*ts);
    EXPECT_EQ(limits.binding().name, "slidingFriction");
    EXPECT_NEAR(limits.deltaT(), 0.5*ts, 1e-6*ts);

    const double cap = c.muC*F/c.kt;
    const double hEq = -F/c.kn;
    const PairRun relaxes =
        heldPair(models, false, hEq, Vec3(0, cap, 0), 0, 0.9*ts, 6);
    EXPECT_NEAR(std::abs(relaxes.Ft[0]), 0.8*c.muC*F, 1e-2*c.muC*F);
    EXPECT_LT(std::abs(relaxes.Ft.back()), 0.05*c.muC*F);
    const PairRun chatters =
        heldPair(models, false, hEq, Vec3(0, cap, 0), 0, 1.1*ts, 6);
    for (std::size_t k = 0; k < chatters.Ft.size(); ++k)
    {
        // On the cap, to round-off, of a load that stays
        EXPECT_NEAR(std::abs(chatters.Ft[k]), c.muC*std::abs(chatters.Fn[k]), 1e-12*F)
            << "step " << k;
        EXPECT_GT(chatters.Fn[k], 0.98*F) << "step " << k;
        if (k > 0)
        {
            EXPECT_LT(chatters.Ft[k]*chatters.Ft[k - 1], 0) << "step " << k;
        }
    }

    // With inertia the Jury bound of the same mode; the rolling spring's
    // when it is stiffer
    const TimeStepLimits inertial(models, 1.0, 1.0, rho, 0.2, Integrator::implicitEuler, 1.0);
    EXPECT_NEAR
    (
        limit(inertial, "slidingFriction"),
        2.5*explicitContactLimit(R, tangentialMode(), c.kt, 0, true),
        1e-6*ts
    );
    FrictionalContact::Params rolling = c;
    rolling.kr = 10*c.kt;
    ForceModels withRollingFriction = models;
    withRollingFriction.set(FrictionalContact(rolling));
    Vec12 rollingMode = Vec12::Zero();
    rollingMode(8) = -1;
    rollingMode(11) = 1;
    EXPECT_NEAR
    (
        limit
        (
            TimeStepLimits(withRollingFriction, 1.0, 1.0, rho, 0.2, Integrator::overdamped, 1.0),
            "slidingFriction"
        ),
        2.5*explicitContactLimit(R, rollingMode, rolling.kr, 0, false),
        1e-6*ts
    );

    // Frictionless, every contact force is implicit: no such limit, the
    // lubrication gap binds; the explicit integrator has its contact limit
    for (const Integrator integrator : {Integrator::implicitEuler, Integrator::overdamped})
    {
        const TimeStepLimits frictionless(tableOne(0.0), 1.0, 1.4, rho, 0.2, integrator, 1.0);
        EXPECT_EQ(limit(frictionless, "slidingFriction"), -1.0);
        EXPECT_EQ(frictionless.binding().name, "lubricationGap");
    }
    const TimeStepLimits explicitLimits(models, 1.0, 1.4, rho, 0.2, Integrator::velocityVerlet, 1.0);
    EXPECT_EQ(limit(explicitLimits, "slidingFriction"), -1.0);
    EXPECT_GT(limit(explicitLimits, "contact"), 0);
}


TEST(ImplicitContact, PairAcrossTheShearedBoundaryMovesAsUnwrapped)
{
    // A touching pair carried by the shear flow loads its springs through
    // -dt K V_inf; across the Lees-Edwards boundary V_inf of the image
    // carries the image velocity: the same motion as inside the box
    const Vec3 L(10, 10, 10);
    const ShearFlow flow(1.0);
    const ForceModels models = tableOne(1.0);

    auto run = [&](const Vec3& xi, double t)
    {
        LeesEdwardsBox box(L, 1.0);
        box.setStrain(box.shearRate()*(t));
        Particles p;
        p.add(xi, 1.0, rho, 0);
        p.add(xi + Vec3(0.3, 2.0, 0.2), 1.1, rho, 1);
        for (std::size_t s = 0; s < 2; ++s)
        {
            p.u[s] = flow.sample(p.x[s]).U;
            p.omega[s] = flow.sample(p.x[s]).Omega();
        }
        box.wrap(p.x[1], p.u[1]);
        Simulation::Params params;
        params.rho = rho;
        params.integrator = Integrator::overdamped;
        params.maxOverlap = 10;
        Simulation sim(p, box, flow, models, params);
        sim.start(t, false, Simulation::Shear{t, 1.0});
        for (int k = 0; k < 5; ++k)
        {
            sim.step(2e-3);
        }
        EXPECT_EQ(sim.implicit()->resistance().nContacts(), 1u);
        const Particles& q = sim.particles();
        const std::size_t i = q.id[0] == 0 ? 0 : 1;
        return std::make_tuple
        (
            Vec3(q.u[i] - flow.sample(q.x[i]).U), q.omega[i], q.F[i], q.T[i]
        );
    };

    const auto inside = run(Vec3(5, 4, 5), 0.37);
    const auto across = run(Vec3(5, 8.5, 5), 0.37);
    const Vec3& F0 = std::get<2>(inside);
    EXPECT_GT(F0.norm(), 1);
    EXPECT_LT((std::get<0>(inside) - std::get<0>(across)).norm(), 1e-8*std::get<0>(inside).norm());
    EXPECT_LT((std::get<1>(inside) - std::get<1>(across)).norm(), 1e-8*std::get<1>(inside).norm());
    EXPECT_LT((F0 - std::get<2>(across)).norm(), 1e-8*F0.norm());
    EXPECT_LT((std::get<3>(inside) - std::get<3>(across)).norm(), 1e-8*std::get<3>(inside).norm());
}


TEST(ImplicitContact, StressIsThatOfThePairKernelsAtTheEndOfTheStep)
{
    // The contact stresslet of a step (eq. 9c) and the contact forces F_c
    // of the next one are the kernels' at (x^(n+1), V^(n+1)) with the
    // history advanced, not the linearised forces of the solve
    for (const Integrator integrator : {Integrator::implicitEuler, Integrator::overdamped})
    {
        const Suspension s(integrator);
        Simulation sim = s.make();
        sim.start(0);
        std::size_t sticking = 0;
        for (int interval = 0; interval < 10; ++interval)
        {
            sim.advance(0.02);
            const int c = contributionIndex("contact");
            const Mat3 S = sim.summary().stresslet[c];

            std::vector<Vec3> F, T;
            ForceField::Output out;
            out.F = &F;
            out.T = &T;
            std::vector<LinearisedContact> contacts;
            out.contacts = &contacts;
            ForceField forces(s.models, sim.particles().a);
            const ForceSummary kernels = forces.evaluate
            (
                sim.particles(), sim.box(), sim.flow(), sim.pairs(),
                sim.search().far(), out, ForceField::Forces::nonHydrodynamic
            );
            EXPECT_LE((kernels.stresslet[c] - S).norm(), 1e-10*S.norm());
            for (std::size_t i = 0; i < F.size(); ++i)
            {
                EXPECT_LT((F[i] - sim.particles().F[i]).norm(), 1e-10*(1 + F[i].norm()));
                EXPECT_LT((T[i] - sim.particles().T[i]).norm(), 1e-10*(1 + T[i].norm()));
            }
            // The operator holds every linearised contact, or with the
            // normal springs explicit (auto, here) those with a sticking
            // tangential or rolling spring
            std::size_t implicitSprings = 0;
            for (const LinearisedContact& l : contacts)
            {
                sticking += l.k.kt > 0;
                implicitSprings +=
                    sim.implicitNormalContact() || l.k.kt > 0 || l.k.kr > 0;
            }
            EXPECT_EQ(implicitSprings, sim.implicit()->resistance().nContacts());
        }
        EXPECT_GT(sim.summary().nContacts, 10u);
        EXPECT_GT(sticking, 0u);
    }
}


namespace
{
    //- Bitwise the same time, particles (in the same order) and viscosity
    void expectSameState(const Simulation& a, const Simulation& b)
    {
        const Particles& p = a.particles();
        const Particles& q = b.particles();
        ASSERT_EQ(p.size(), q.size());
        EXPECT_EQ(a.time(), b.time());
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            ASSERT_EQ(p.id[i], q.id[i]);
            EXPECT_EQ(p.x[i], q.x[i]);
            EXPECT_EQ(p.u[i], q.u[i]);
            EXPECT_EQ(p.omega[i], q.omega[i]);
            EXPECT_EQ(p.F[i], q.F[i]);
            EXPECT_EQ(p.T[i], q.T[i]);
        }
        EXPECT_EQ(a.rheology().etaR, b.rheology().etaR);
    }
}


TEST(ImplicitContact, RestartIsBitwise)
{
    // A run written and restarted at strain 0.1 (new Simulation from the
    // particles and the contact history, start(t, forces given)) equals
    // the uninterrupted run, which restarts itself at every write as the
    // cloud does (Simulation::start after a write)
    const Suspension s(Integrator::implicitEuler);
    Simulation a = s.make();
    a.start(0);
    a.advance(0.1);
    Simulation b = s.make();
    b.start(0);
    b.advance(0.1);
    ASSERT_GT(a.implicit()->resistance().nContacts(), 0u);

    a.start(a.time(), true);
    const std::uint64_t before = a.steps();
    a.advance(0.05);

    Simulation c
    (
        b.particles(), b.box(), s.flow, s.models, s.params
    );
    c.pairs() = b.pairs();
    c.start(b.time(), true, b.shear());
    c.advance(0.05);

    EXPECT_EQ(a.steps() - before, c.steps());
    expectSameState(a, c);
}


TEST(ImplicitContact, RestoreFromACheckpointIsARestart)
{
    // A checkpoint taken at strain 0.1 by a run that then goes on (as a run
    // that fails does, the cloud restoring its last good state): restored,
    // the run continues bitwise as the one that restarted itself at 0.1
    // (start(t, true), as after a write), for both implicit integrators
    // (velocityVerlet restores through the same start(t, true) as its
    // restarts, tests/suspensionFoam restart)
    for (const Integrator integrator :
        {Integrator::implicitEuler, Integrator::overdamped})
    {
        const Suspension s(integrator);
        Simulation a = s.sheared();
        Simulation b = s.sheared();
        ASSERT_GT(a.pairs().nContacts(), 0u);
        Simulation::Checkpoint c;
        a.checkpoint(c);
        EXPECT_TRUE(c.pairs.slotT.empty());
        const std::uint64_t steps = a.steps();

        a.advance(0.03);
        ASSERT_NE(a.particles().x, c.particles.x);
        a.restore(c);
        EXPECT_EQ(a.time(), b.time());
        EXPECT_EQ(a.steps(), steps);
        a.advance(0.05);

        b.start(b.time(), true);
        b.advance(0.05);

        EXPECT_EQ(a.steps(), b.steps());
        EXPECT_EQ(a.pairs().nContacts(), b.pairs().nContacts());
        expectSameState(a, b);
    }
}


TEST(ImplicitContact, RestoreAfterAnUnconvergedSolve)
{
    // A step whose velocity solve fails (one CG iteration allowed) throws;
    // the checkpoint before it restores without a second throw (restore
    // checks the state, not the discarded solve), as the cloud needs to
    // write its last good state
    const Suspension s(Integrator::implicitEuler);
    const Simulation sheared = s.sheared();
    Simulation::Params params = s.params;
    params.solver.maxIterations = 1;
    Simulation sim(sheared.particles(), sheared.box(), s.flow, s.models, params);
    sim.pairs() = sheared.pairs();
    sim.start(sheared.time(), true, sheared.shear());
    Simulation::Checkpoint c;
    sim.checkpoint(c);

    EXPECT_THROW(sim.advance(0.01), SimulationError);
    EXPECT_FALSE(sim.implicit()->statistics().converged);
    EXPECT_NO_THROW(sim.restore(c));
    EXPECT_EQ(sim.time(), sheared.time());
    EXPECT_EQ(sim.steps(), c.steps);
}


TEST(ImplicitContact, WarmStartCarriesTheLastRateOfChange)
{
    // Each step stores (u^(n+1) - u^n)/dt and that of omega; the next
    // solve starts from V'^n + dt of them. From a sheared state with
    // contacts, over 40 steps the extrapolated warm start takes fewer CG
    // iterations than V'^n alone (the rates zeroed before every step),
    // both solved to the same tolerance
    const Suspension s(Integrator::implicitEuler);
    const Simulation sheared = s.sheared();
    ASSERT_GT(sheared.implicit()->resistance().nContacts(), 0u);

    std::uint64_t iterations[2];
    for (const bool extrapolate : {true, false})
    {
        Simulation sim(sheared.particles(), sheared.box(), s.flow, s.models, s.params);
        sim.pairs() = sheared.pairs();
        sim.start(sheared.time(), true, sheared.shear());
        const double dt = sim.deltaT();
        const std::uint64_t before = sim.implicit()->iterations();
        for (int k = 0; k < 40; ++k)
        {
            Particles& p = sim.particles();
            if (!extrapolate)
            {
                std::fill(p.dudt.begin(), p.dudt.end(), Vec3::Zero());
                std::fill(p.domegadt.begin(), p.domegadt.end(), Vec3::Zero());
            }
            const std::vector<Vec3> u = p.u;
            const std::vector<Vec3> omega = p.omega;
            const std::vector<std::int64_t> id = p.id;
            sim.step(dt);
            if (sim.particles().id != id)
            {
                continue;   // re-sorted by a list rebuild
            }
            for (std::size_t i = 0; i < u.size(); ++i)
            {
                const Vec3 a = (sim.particles().u[i] - u[i])/dt;
                const Vec3 alpha = (sim.particles().omega[i] - omega[i])/dt;
                EXPECT_LE((sim.particles().dudt[i] - a).norm(), 1e-8*(1 + a.norm()));
                EXPECT_LE
                (
                    (sim.particles().domegadt[i] - alpha).norm(),
                    1e-8*(1 + alpha.norm())
                );
            }
        }
        iterations[extrapolate] = sim.implicit()->iterations() - before;
    }
    EXPECT_LT(iterations[true], iterations[false]);
}


TEST(ImplicitContact, BitwiseAcrossThreadCounts)
{
    // The implicit product with contacts and whole steps (right-hand side,
    // solve, kernels) are bitwise the same on one and two threads
    // (core/Parallel.H); from a sheared state with contacts
    const Suspension s(Integrator::implicitEuler);
    const Simulation sheared = s.sheared();
    ASSERT_GT(sheared.implicit()->resistance().nContacts(), 0u);

    const std::size_t minParticles = setParallelMinParticles(0);
    const int threads = omp_get_max_threads();
    std::vector<Particles> result;
    std::vector<Eigen::VectorXd> products;
    for (const int nt : {1, 2})
    {
        omp_set_num_threads(nt);
        Simulation sim(sheared.particles(), sheared.box(), s.flow, s.models, s.params);
        sim.pairs() = sheared.pairs();
        sim.start(sheared.time(), true, sheared.shear());
        sim.step(2e-3);

        // y = A x for a fixed x, after the last step's setStep()
        std::mt19937 gen(3);
        std::normal_distribution<double> normal;
        Eigen::VectorXd x(6*sim.particles().size());
        for (Eigen::Index k = 0; k < x.size(); ++k) x(k) = normal(gen);
        Eigen::VectorXd y;
        sim.implicit()->resistance().apply(x, y);
        products.push_back(y);
        result.push_back(sim.particles());
    }
    omp_set_num_threads(threads);
    setParallelMinParticles(minParticles);

    EXPECT_TRUE(products[0] == products[1]);
    for (std::size_t i = 0; i < result[0].size(); ++i)
    {
        ASSERT_EQ(result[0].id[i], result[1].id[i]);
        EXPECT_EQ(result[0].x[i], result[1].x[i]);
        EXPECT_EQ(result[0].u[i], result[1].u[i]);
        EXPECT_EQ(result[0].omega[i], result[1].omega[i]);
        EXPECT_EQ(result[0].F[i], result[1].F[i]);
    }
}
