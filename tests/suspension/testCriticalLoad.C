// Critical-load friction (Mari, Seto, Morris & Denn 2014, section II.B;
// CriticalLoadContact) on two spheres, against the analytic stick-and-slide
// stretch: no friction below the critical load, the Coulomb cap
// mu_C (k_n |h| - F_CL) above it, the stretch reset when the load falls
// below, F_CL = 0 as FrictionalContact with the spring load; parameter
// checks, and the registry refusing both contact models at once
#include "flow/ShearFlow.H"
#include "forces/ForceField.H"
#include "contactTestTools.H"
#include "search/NeighbourSearch.H"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace suspension;

namespace
{
    const double ai = 1.0;
    const double aj = 1.4;
    const double kn = 1e4;
    const double kt = 2e3;
    const double muC = 0.5;
    const Vec3 n = Vec3(0.48, 0.6, -0.64);          // unit, from i to j

    using test::advanceContact;
    using test::kinematics;

    FrictionalContact::Params springs(double gammaN)
    {
        return test::springs(kn, kt, gammaN, muC);
    }

    CriticalLoadContact criticalLoad(double FCL, double gammaN = 0)
    {
        return CriticalLoadContact({springs(gammaN), FCL});
    }

    //- The pair at surface gap h along n
    PairGeometry atGap(double h)
    {
        return PairGeometry::make((ai + aj + h)*n, ai, aj);
    }

    //- j slides past i at tangential speed 0.3 and separates at 0.02
    //  (the dashpot then lowers |F_n| below the spring force)
    const Vec3 slide = 0.3*Vec3(0.8, -0.64, 0).normalized().cross(n).normalized();
    const PairKinematics sliding =
        kinematics(Vec3::Zero(), slide + 0.02*n, Vec3::Zero(), Vec3::Zero());

    Vec3 tangential(const Vec3& v)
    {
        return v - n.dot(v)*n;
    }
}


TEST(CriticalLoad, NoFrictionBelowTheCriticalLoad)
{
    // k_n |h| = 1 < F_CL = 2: the contact is frictionless however long it
    // slides (and spins); the normal force is the spring-dashpot (4a)
    const PairGeometry g = atGap(-1e-4);
    const double h = g.h;                       // as the kernel sees it
    const double gammaN = 50;
    const CriticalLoadContact contact = criticalLoad(2.0, gammaN);
    const PairKinematics kin = kinematics
    (
        Vec3(0.1, 0, 0), Vec3(0, 0.2, 0.3), Vec3(0.5, -1, 0), Vec3(0, 0.7, 0.2)
    );
    ContactState state;
    for (int step = 0; step < 200; ++step)
    {
        const PairForce f = advanceContact(contact, g, kin, state, 1e-4);
        const Vec3 Fn = (kn*h + gammaN*n.dot(kin.du))*n;
        EXPECT_LE((f.F - Fn).norm(), 1e-14*Fn.norm()) << "step " << step;
        EXPECT_EQ(f.Ti, Vec3::Zero()) << "step " << step;
        EXPECT_EQ(f.Tj, Vec3::Zero()) << "step " << step;
        EXPECT_FALSE(state.active()) << "step " << step << ": xiT " << state.xiT.transpose();
    }
}


TEST(CriticalLoad, AboveTheCriticalLoadFrictionGrowsToItsCap)
{
    // k_n |h| = 10 > F_CL = 4. Stick: |F_t| = k_t |u_t| t after t/dt
    // steps; slide: |F_t| = mu_C (k_n |h| - F_CL) = 3, the spring force
    // alone being the load: the dashpot (separating, |F_n| = 9) would give
    // 2.5, and Coulomb on |F_n| 4.5. Torques T_i = a_i n x F_t (4d),
    // T_j = (a_j/a_i) T_i (4e).
    const PairGeometry g = atGap(-1e-3);
    const double h = g.h;                       // as the kernel sees it
    const double FCL = 4;
    const double gammaN = 50;
    const CriticalLoadContact contact = criticalLoad(FCL, gammaN);
    const double dt = 1e-4;
    const double cap = muC*(kn*std::abs(h) - FCL);
    ASSERT_NEAR(std::abs(kn*h + gammaN*0.02), 9, 1e-9);

    ContactState state;
    PairForce f;
    for (int step = 1; step <= 200; ++step)
    {
        f = advanceContact(contact, g, sliding, state, dt);
        const double stick = kt*slide.norm()*step*dt;
        if (stick < cap)
        {
            EXPECT_NEAR(tangential(f.F).norm(), stick, 1e-12*stick) << "step " << step;
        }
    }
    const Vec3 Ft = tangential(f.F);
    EXPECT_NEAR(Ft.norm(), cap, 1e-12*cap)
        << "|F_t| = " << Ft.norm() << ", mu_C (k_n |h| - F_CL) = " << cap;
    EXPECT_LE((Ft.normalized() - slide.normalized()).norm(), 1e-12);
    EXPECT_NEAR(kt*state.xiT.norm(), cap, 1e-12*cap);
    EXPECT_LE((f.Ti - ai*n.cross(Ft)).norm(), 1e-12*ai*cap);
    EXPECT_LE((f.Tj - aj*n.cross(Ft)).norm(), 1e-12*aj*cap);
    const double fn = kn*h + gammaN*0.02;
    EXPECT_NEAR(n.dot(f.F), fn, 1e-12*std::abs(fn));

    // Rolling without sliding (a_i omega_i + a_j omega_j = 0): the rolling
    // torque saturates at a_ij mu_r (k_n |h| - F_CL) (appendix B)
    FrictionalContact::Params p = springs(gammaN);
    p.kr = 500;
    p.muR = 0.2;
    const CriticalLoadContact rolling({p, FCL});
    const double aij = 2*ai*aj/(ai + aj);
    const Vec3 omegai = 0.5*Vec3(0.8, -0.64, 0).normalized();
    const PairKinematics kin = kinematics(Vec3::Zero(), Vec3::Zero(), omegai, -ai/aj*omegai);
    ContactState rollState;
    for (int step = 0; step < 2000; ++step)
    {
        f = advanceContact(rolling, g, kin, rollState, dt);
    }
    const double rollCap = aij*0.2*(kn*std::abs(h) - FCL);
    EXPECT_NEAR(f.Ti.norm(), rollCap, 1e-12*rollCap)
        << "|T_r| = " << f.Ti.norm() << ", a_ij mu_r (k_n |h| - F_CL) = " << rollCap;
    EXPECT_LE((f.Ti + f.Tj).norm(), 1e-12*rollCap);              // (B.1c)
}


TEST(CriticalLoad, FallingBelowTheCriticalLoadResetsTheStretch)
{
    // A capped stretch, then one step at k_n |h| = 1 < F_CL = 4: no
    // friction and no stretch; back above, the friction builds up afresh
    // from zero (one step: k_t |u_t| dt), not from the old cap
    const CriticalLoadContact contact = criticalLoad(4.0);
    const double dt = 1e-4;
    ContactState state;
    for (int step = 0; step < 200; ++step)
    {
        advanceContact(contact, atGap(-1e-3), sliding, state, dt);
    }
    ASSERT_NEAR(kt*state.xiT.norm(), muC*(10 - 4), 1e-9);

    PairForce f = advanceContact(contact, atGap(-1e-4), sliding, state, dt);
    // F = F_n n: its tangential part is the round-off of n.n = 1
    EXPECT_LT(tangential(f.F).norm(), 1e-15*f.F.norm());
    EXPECT_FALSE(state.active());

    f = advanceContact(contact, atGap(-1e-3), sliding, state, dt);
    const double oneStep = kt*slide.norm()*dt;
    EXPECT_NEAR(tangential(f.F).norm(), oneStep, 1e-12*oneStep);

    // The same through the pair loop: ForceField::advance drops the history
    // of the slot when the load falls below F_CL (the pair still overlaps)
    ForceModels models;
    models.set(contact);
    const LeesEdwardsBox box(Vec3(12, 12, 12), 0);
    const ShearFlow flow(0);
    Particles p;
    const Vec3 xi(6, 6, 6);
    p.add(xi, ai, 1.0, 1);
    p.add(xi + (ai + aj - 1e-3)*n, aj, 1.0, 2);
    p.u[1] = slide;
    ForceField field(models, p.a);
    NeighbourSearch search({field.nearGap(), 0.1});
    PairList near;
    search.rebuild(p, box, near);
    ASSERT_EQ(near.nPairs(), 1u);
    for (int step = 0; step < 10; ++step)
    {
        field.advance(p, box, flow, near, search.far(), dt);
    }
    EXPECT_TRUE(near.history(0).active());

    const std::size_t j = p.id[0] == 2 ? 0 : 1;     // sphere 2 (the list sorted them)
    p.x[j] = p.x[1 - j] + (ai + aj - 1e-4)*n;
    field.advance(p, box, flow, near, search.far(), dt);
    EXPECT_FALSE(near.history(0).active())
        << "xiT " << near.history(0).xiT.transpose();
}


TEST(CriticalLoad, ZeroCriticalLoadIsFrictionalContactWithTheSpringLoad)
{
    // F_CL = 0 and no dashpot: the load k_n |h| is FrictionalContact's
    // |F_n|, so both give the same forces, torques, stresslets and states
    // along a path that slides, rolls, turns and changes its overlap
    FrictionalContact::Params p = springs(0);
    p.kr = 500;
    const FrictionalContact frictional(p);
    const CriticalLoadContact critical({p, 0.0});
    ContactState sf, sc;
    const double dt = 1e-4;
    for (int step = 0; step < 400; ++step)
    {
        const double t = step*dt;
        const Vec3 r = (ai + aj - 1e-3*(1 + std::sin(300*t)))
                     * Eigen::AngleAxisd(50*t, Vec3(0, 0, 1)).toRotationMatrix()*n;
        const PairGeometry g = PairGeometry::make(r, ai, aj);
        const PairKinematics kin = kinematics
        (
            Vec3(0.1, -0.2, 0.05), Vec3(-0.3, 0.1, 0.2),
            Vec3(1, 0.5, -2), Vec3(-0.4, 2, 0.3)
        );
        const PairForce ff = advanceContact(frictional, g, kin, sf, dt);
        const PairForce fc = advanceContact(critical, g, kin, sc, dt);
        const double scale = ff.F.norm();
        EXPECT_LE((fc.F - ff.F).norm(), 1e-14*scale) << "step " << step;
        EXPECT_LE((fc.Ti - ff.Ti).norm(), 1e-14*scale) << "step " << step;
        EXPECT_LE((fc.Tj - ff.Tj).norm(), 1e-14*scale) << "step " << step;
        EXPECT_LE((fc.S - ff.S).norm(), 1e-14*scale*r.norm()) << "step " << step;
        EXPECT_LE((sc.xiT - sf.xiT).norm(), 1e-14*sf.xiT.norm()) << "step " << step;
        EXPECT_LE((sc.xiR - sf.xiR).norm(), 1e-14*sf.xiR.norm()) << "step " << step;
    }
    EXPECT_GT(sf.xiT.norm(), 0);
    EXPECT_GT(sf.xiR.norm(), 0);
}


TEST(CriticalLoad, RejectsInvalidCriticalLoad)
{
    EXPECT_NO_THROW(criticalLoad(0));
    for (const double FCL :
         {-1.0, std::numeric_limits<double>::quiet_NaN(),
          std::numeric_limits<double>::infinity()})
    {
        try
        {
            criticalLoad(FCL);
            ADD_FAILURE() << "no exception for F_CL = " << FCL;
        }
        catch (const std::invalid_argument& e)
        {
            EXPECT_NE(std::string(e.what()).find("FCL"), std::string::npos) << e.what();
        }
    }
    // Left unset (required), and bad springs
    CriticalLoadContact::Params unset;
    unset.springs = springs(0);
    EXPECT_THROW(CriticalLoadContact{unset}, std::invalid_argument);
    FrictionalContact::Params bad = springs(0);
    bad.kn = -1;
    EXPECT_THROW(CriticalLoadContact({bad, 1.0}), std::invalid_argument);
}


TEST(CriticalLoad, RegistryRefusesBothContactModels)
{
    // Both are the stress contribution "contact": alternatives, at most
    // one on (ForceModels::set), whichever comes first stays on
    const FrictionalContact frictional(springs(0));
    const CriticalLoadContact critical = criticalLoad(1.0);

    ForceModels a;
    a.set(frictional);
    EXPECT_THROW(a.set(critical), std::invalid_argument);
    EXPECT_NE(a.get<FrictionalContact>(), nullptr);
    EXPECT_EQ(a.get<CriticalLoadContact>(), nullptr);

    ForceModels b;
    b.set(critical);
    try
    {
        b.set(frictional);
        ADD_FAILURE() << "FrictionalContact switched on next to CriticalLoadContact";
    }
    catch (const std::invalid_argument& e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find(FrictionalContact::typeName), std::string::npos) << what;
        EXPECT_NE(what.find(CriticalLoadContact::typeName), std::string::npos) << what;
    }
    EXPECT_EQ(b.get<FrictionalContact>(), nullptr);
    EXPECT_NE(b.get<CriticalLoadContact>(), nullptr);

    // Switching one off makes room for the other
    b.reset<CriticalLoadContact>();
    EXPECT_NO_THROW(b.set(frictional));
    EXPECT_NE(b.get<FrictionalContact>(), nullptr);
}
