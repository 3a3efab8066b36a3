// Stick-and-slide contact (eqs. 4a-5, 9c, Appendix B): restitution of a
// head-on collision, the Coulomb cap, the stretch on the tangent plane, the
// rolling cap, pair symmetry, the virial and parameter checks
#include "forces/CriticalLoadContact.H"
#include "contactTestTools.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

using namespace suspension;

namespace
{
    using test::advanceContact;
    using test::kinematics;

    FrictionalContact::Params params(double kn, double kt, double gammaN, double muC)
    {
        return test::springs(kn, kt, gammaN, muC);
    }

    //- Tangential part of v
    Vec3 tangential(const Vec3& v, const Vec3& n)
    {
        return v - n.dot(v)*n;
    }

    //- Rotation by angle theta about the unit axis e
    Mat3 rotation(const Vec3& e, double theta)
    {
        return Eigen::AngleAxisd(theta, e).toRotationMatrix();
    }
}


TEST(Contact, HeadOnRestitutionOfDampedOscillator)
{
    // m_red d^2h/dt^2 = -k_n h - gamma_n dh/dt while h < 0: the relative
    // speed comes back scaled by e = exp(-pi zeta/sqrt(1 - zeta^2)) after
    // the damped half period pi/(omega_0 sqrt(1 - zeta^2))
    const double a = 1.0;
    const double m = 1.3;
    const double mRed = m*m/(m + m);
    const double kn = 1e4;
    const double zeta = 0.2;
    const double gammaN = 2*zeta*std::sqrt(kn*mRed);
    const FrictionalContact contact(params(kn, 2.0/7.0*kn, gammaN, 1.0));

    const double eExpected = std::exp(-pi*zeta/std::sqrt(1 - zeta*zeta));
    const double omega0 = std::sqrt(kn/mRed);
    const double tContact = pi/(omega0*std::sqrt(1 - zeta*zeta));
    ASSERT_LT(eExpected, 0.6);

    const Vec3 n = Vec3(1.0, 2.0, -0.5).normalized();
    const double v0 = 0.7;
    Vec3 posi = Vec3(0.3, -0.2, 0.1);
    Vec3 posj = posi + (2*a + 1e-3)*n;
    Vec3 ui = 0.5*v0*n;
    Vec3 uj = -0.5*v0*n;
    ContactState state;

    const double dt = (pi/omega0)/5000;
    bool touched = false;
    int stepsInContact = 0;
    for (int step = 0; step < 100000; ++step)
    {
        const PairGeometry g = PairGeometry::make(posj - posi, a, a);
        if (touched && !(g.h < FrictionalContact::gap()))
        {
            break;
        }
        PairForce f;
        if ((g.h < FrictionalContact::gap()))
        {
            touched = true;
            ++stepsInContact;
            f = advanceContact(contact, g, kinematics(ui, uj, Vec3::Zero(), Vec3::Zero()), state, dt);
        }
        // Symplectic Euler
        ui += f.F/m*dt;
        uj -= f.F/m*dt;
        posi += ui*dt;
        posj += uj*dt;
    }

    ASSERT_TRUE(touched);
    const double e = n.dot(uj - ui)/v0;
    EXPECT_NEAR(e, eExpected, 0.01*eExpected)
        << "e = " << e << ", damped oscillator " << eExpected;
    EXPECT_NEAR(stepsInContact*dt, tContact, 0.01*tContact);
    // Head-on: no tangential spring, no spin
    EXPECT_NEAR(state.xiT.norm(), 0, 1e-15);
}


TEST(Contact, SlidingContactSitsOnCoulombCap)
{
    // j slides past i at a constant tangential velocity: the stretch grows
    // as v t (stick) until k_t |xi| = mu_C |F_n| (slide, eq. 5)
    const double ai = 1.0;
    const double aj = 0.6;
    const double h = -0.01;
    const double kn = 1e4;
    const double kt = 2.0/7.0*kn;
    const double muC = 0.5;
    const FrictionalContact contact(params(kn, kt, 5.0, muC));

    const Vec3 n(1, 0, 0);
    const PairGeometry g = PairGeometry::make((ai + aj + h)*n, ai, aj);
    const Vec3 v(0, 0.3, 0.1);
    const PairKinematics kin = kinematics(Vec3::Zero(), v, Vec3::Zero(), Vec3::Zero());
    const double dt = 1e-4;
    const double FnMag = kn*std::abs(h);

    ContactState state;
    PairForce f;
    for (int step = 1; step <= 3000; ++step)
    {
        f = advanceContact(contact, g, kin, state, dt);
        if (step == 50)
        {
            const double stick = kt*v.norm()*step*dt;
            ASSERT_LT(stick, muC*FnMag);
            EXPECT_NEAR(tangential(f.F, n).norm(), stick, 1e-12*stick);
        }
    }

    const Vec3 Ft = tangential(f.F, n);
    EXPECT_NEAR(Ft.norm(), muC*FnMag, 1e-12*muC*FnMag)
        << "|F_t| = " << Ft.norm() << ", mu_C |F_n| = " << muC*FnMag;
    EXPECT_NEAR(n.dot(f.F), kn*h, 1e-12*FnMag);
    // Friction drags i along the motion of j
    EXPECT_NEAR((Ft.normalized() - v.normalized()).norm(), 0, 1e-12);
    // Torques (4d), (4e)
    const Vec3 Ti = ai*n.cross(Ft);
    EXPECT_NEAR((f.Ti - Ti).norm(), 0, 1e-12*Ti.norm());
    EXPECT_NEAR((f.Tj - aj/ai*Ti).norm(), 0, 1e-12*Ti.norm());
}


TEST(Contact, FrictionOpposesSpinAgainstFixedSphere)
{
    // i spins against a resting j: the friction on i opposes the velocity
    // of its surface at the contact point, and its torque opposes the spin
    const double ai = 0.8;
    const double aj = 1.2;
    const FrictionalContact contact(params(1e4, 3e3, 0, 1.0));
    const Vec3 n = Vec3(0.3, -1.0, 0.4).normalized();
    const PairGeometry g = PairGeometry::make((ai + aj - 0.01)*n, ai, aj);
    const Vec3 omegai = Vec3(1.0, 0.5, -0.2);
    const PairKinematics kin = kinematics(Vec3::Zero(), Vec3::Zero(), omegai, Vec3::Zero());

    ContactState state;
    PairForce f;
    for (int step = 0; step < 10; ++step)
    {
        f = advanceContact(contact, g, kin, state, 1e-4);
    }
    const Vec3 surfaceVelocity = omegai.cross(ai*n);
    const Vec3 Ft = tangential(f.F, n);
    EXPECT_NEAR((Ft.normalized() + surfaceVelocity.normalized()).norm(), 0, 1e-12);
    EXPECT_LT(f.Ti.dot(omegai), 0);
}


TEST(Contact, StretchStaysInTangentPlaneWhenPairRotates)
{
    // The pair rotates rigidly about Omega (no sliding: u_t = 0). The
    // stretch is carried onto each new tangent plane with its length kept
    // (Luding 2008); a stretch in the plane of rotation turns with the pair.
    const double ai = 1.0;
    const double aj = 0.8;
    const double d = ai + aj - 0.005;
    const double w = 0.7;
    const Vec3 axis(0, 0, 1);
    const Vec3 Omega = w*axis;
    const FrictionalContact contact(params(1e4, 2e3, 0, 1.0));
    const Vec3 n0(1, 0, 0);
    const double dt = 1e-4;
    const int nSteps = 15000;        // ~ 60 degrees

    for (const Vec3& xi0 : {Vec3(0, 0.004, 0), Vec3(0, 0.004, -0.003)})
    {
        ContactState state;
        state.xiT = xi0;
        for (int step = 1; step <= nSteps; ++step)
        {
            const Vec3 r = d*(rotation(axis, w*step*dt)*n0);
            const PairGeometry g = PairGeometry::make(r, ai, aj);
            const Vec3 spin = d/(ai + aj)*Omega;
            advanceContact(contact, g, kinematics(Vec3::Zero(), Omega.cross(r), spin, spin), state, dt);
        }
        const Vec3 n = rotation(axis, w*nSteps*dt)*n0;
        EXPECT_NEAR(n.dot(state.xiT), 0, 1e-12*xi0.norm());
        EXPECT_NEAR(state.xiT.norm(), xi0.norm(), 1e-12*xi0.norm());
        if (xi0.z() == 0)
        {
            const Vec3 turned = rotation(axis, w*nSteps*dt)*xi0;
            EXPECT_NEAR((state.xiT - turned).norm(), 0, 1e-9*xi0.norm());
        }
    }
}


TEST(Contact, RollingTorqueObeysItsCap)
{
    // i and j roll on each other without sliding (a_i omega_i + a_j omega_j
    // = 0, so u_t = 0): only the rolling spring acts (Appendix B). Its
    // torque grows as a_ij^2 k_r |omega_i - omega_j| t, opposes the
    // relative rotation and saturates at a_ij mu_r |F_n|.
    const double ai = 1.0;
    const double aj = 0.5;
    const double aij = 2*ai*aj/(ai + aj);
    const double h = -0.01;
    const double kn = 1e4;
    const double kr = 1e3;
    const double muC = 0.5;
    const double FnMag = kn*std::abs(h);
    const Vec3 n(1, 0, 0);
    const PairGeometry g = PairGeometry::make((ai + aj + h)*n, ai, aj);
    const Vec3 omegai(0, 0.2, 0.4);
    const Vec3 omegaj = -ai/aj*omegai;
    const PairKinematics kin = kinematics(Vec3::Zero(), Vec3::Zero(), omegai, omegaj);
    const double dt = 1e-4;

    FrictionalContact::Params p = params(kn, 2e3, 0, muC);
    p.kr = kr;
    for (const double muR : {muC, 0.2})
    {
        if (muR != muC)
        {
            p.muR = muR;
        }
        const FrictionalContact contact(p);
        EXPECT_EQ(contact.muR(), muR);

        ContactState state;
        PairForce f;
        for (int step = 1; step <= 5000; ++step)
        {
            f = advanceContact(contact, g, kin, state, dt);
            if (step == 20)
            {
                const double stick = aij*aij*kr*(omegai - omegaj).norm()*step*dt;
                ASSERT_LT(stick, aij*muR*FnMag);
                EXPECT_NEAR(f.Ti.norm(), stick, 1e-12*stick);
            }
        }
        const double cap = aij*muR*FnMag;
        EXPECT_NEAR(f.Ti.norm(), cap, 1e-12*cap)
            << "|T_r| = " << f.Ti.norm() << ", a_ij mu_r |F_n| = " << cap;
        EXPECT_NEAR((f.Ti.normalized() + (omegai - omegaj).normalized()).norm(), 0, 1e-12);
        EXPECT_NEAR((f.Tj + f.Ti).norm(), 0, 1e-12*cap);       // (B.1c)
        EXPECT_EQ(state.xiT.norm(), 0);
        EXPECT_NEAR((f.F - kn*h*n).norm(), 0, 1e-12*FnMag);
    }

    // Rolling off: the same motion feels no torque
    ContactState state;
    const PairForce f = advanceContact(FrictionalContact(params(kn, 2e3, 0, muC)), g, kin, state, dt);
    EXPECT_EQ(f.Ti.norm(), 0);
}


TEST(Contact, SwappedPairGivesOppositeForceAndSwappedTorques)
{
    // Evaluating (j, i) with the reversed state must mirror (i, j): F -> -F,
    // T_i <-> T_j, same stresslet, state -> -state (ContactState rule)
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> U(-1, 1);
    auto random = [&]() { return Vec3(U(gen), U(gen), U(gen)); };

    const double ai = 1.0;
    const double aj = 1.4;
    FrictionalContact::Params p = params(1e4, 3e3, 20, 0.8);
    p.kr = 500;
    p.muR = 0.3;
    const FrictionalContact contact(p);

    const Vec3 n = random().normalized();
    const Vec3 ui = random();
    const Vec3 uj = random();
    const Vec3 omegai = random();
    const Vec3 omegaj = random();
    ContactState sij;
    ContactState sji;
    const double dt = 1e-4;

    for (int step = 0; step < 200; ++step)
    {
        const Vec3 r = (ai + aj - 0.02)*n + 2e-4*step*tangential(ui, n);
        const PairForce fij = advanceContact
        (
            contact, PairGeometry::make(r, ai, aj), kinematics(ui, uj, omegai, omegaj), sij, dt
        );
        const PairForce fji = advanceContact
        (
            contact, PairGeometry::make(-r, aj, ai), kinematics(uj, ui, omegaj, omegai), sji, dt
        );
        const double scale = fij.F.norm();
        ASSERT_GT(scale, 0);
        EXPECT_NEAR((fji.F + fij.F).norm(), 0, 1e-12*scale);
        EXPECT_NEAR((fji.Ti - fij.Tj).norm(), 0, 1e-12*scale);
        EXPECT_NEAR((fji.Tj - fij.Ti).norm(), 0, 1e-12*scale);
        EXPECT_NEAR((fji.S - fij.S).norm(), 0, 1e-12*scale);
        EXPECT_NEAR((sji.xiT + sij.xiT).norm(), 0, 1e-12*sij.xiT.norm());
        EXPECT_NEAR((sji.xiR + sij.xiR).norm(), 0, 1e-12*sij.xiR.norm());
        if (step == 0)
        {
            ASSERT_GT(sij.xiT.norm(), 0);
            ASSERT_GT(sij.xiR.norm(), 0);
        }
    }
}


TEST(Contact, FrictionTorquesScaleWithRadii)
{
    // Without rolling, T_j = (a_j/a_i) T_i (4e) and both equal a n x F_t
    // about each centre (4d)
    const double ai = 0.7;
    const double aj = 2.1;
    const FrictionalContact contact(params(1e4, 3e3, 1, 1.0));
    const Vec3 n = Vec3(-0.2, 0.5, 0.9).normalized();
    const PairGeometry g = PairGeometry::make((ai + aj - 0.01)*n, ai, aj);
    const PairKinematics kin =
        kinematics(Vec3(0.1, 0.2, 0), Vec3(0, -0.3, 0.5), Vec3(0, 0, 1), Vec3(1, 0, 0));
    ContactState state;
    PairForce f;
    for (int step = 0; step < 5; ++step)
    {
        f = advanceContact(contact, g, kin, state, 1e-4);
    }
    const Vec3 Ft = tangential(f.F, n);
    ASSERT_GT(Ft.norm(), 0);
    EXPECT_NEAR((f.Ti - ai*n.cross(Ft)).norm(), 0, 1e-12*ai*Ft.norm());
    EXPECT_NEAR((f.Tj - aj*n.cross(Ft)).norm(), 0, 1e-12*aj*Ft.norm());
}


TEST(Contact, StaticOverlapVirial)
{
    // S = -r_ij (x) F_ij with r_ij = x_i - x_j and F_ij = k_n h n, by hand
    const double kn = 2e4;
    const FrictionalContact contact(params(kn, 5e3, 3, 0.5));
    const Vec3 xi(1.0, 2.0, 3.0);
    const Vec3 xj(2.2, 2.9, 3.4);
    const double ai = 0.9;
    const double aj = 0.8;

    const double dist = std::sqrt(1.2*1.2 + 0.9*0.9 + 0.4*0.4);
    const double h = dist - ai - aj;
    ASSERT_LT(h, 0);
    const Vec3 rij = xi - xj;
    const Vec3 Fij = kn*h*(xj - xi)/dist;
    const Mat3 S = -rij*Fij.transpose();

    ContactState state;
    const PairForce f = advanceContact
    (
        contact, PairGeometry::make(xj - xi, ai, aj),
        kinematics(Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()),
        state,
        1e-4
    );
    EXPECT_NEAR((f.F - Fij).norm(), 0, 1e-12*Fij.norm());
    EXPECT_NEAR((f.S - S).norm(), 0, 1e-12*S.norm());
    // A compressed contact carries a positive pressure -tr(S)/3
    EXPECT_GT(-f.S.trace(), 0);
}


TEST(Contact, StressletIsSymmetricPartOfVirialWithFriction)
{
    // With a tangential force r (x) F is not symmetric; its antisymmetric
    // part is the couple balanced by the contact torques, not a stresslet
    const FrictionalContact contact(params(1e4, 3e3, 1, 1.0));
    const Vec3 r = Vec3(1.1, -0.9, 0.5);
    const PairGeometry g = PairGeometry::make(r, 0.9, 0.8);
    const PairKinematics kin =
        kinematics(Vec3(0.4, 0.1, 0), Vec3(0, -0.3, 0.5), Vec3(0, 0, 1), Vec3::Zero());
    ContactState state;
    PairForce f;
    for (int step = 0; step < 5; ++step)
    {
        f = advanceContact(contact, g, kin, state, 1e-4);
    }
    const Mat3 virial = r*f.F.transpose();
    ASSERT_GT((virial - virial.transpose()).norm(), 1e-3*virial.norm());
    EXPECT_NEAR((f.S - 0.5*(virial + virial.transpose())).norm(), 0, 1e-14*virial.norm());
}


TEST(Contact, ActsOnlyInContact)
{
    // The pair loop calls a kernel only while h < gap(): for contacts, while
    // the spheres overlap (ForceField tests check that the loop resets the
    // history of a pair that separated)
    EXPECT_EQ(FrictionalContact::gap(), 0);
    EXPECT_EQ(CriticalLoadContact::gap(), 0);
}


TEST(Contact, TimeScales)
{
    // Half periods of the undamped springs (solid spheres, I = 2/5 m a^2)
    const double mi = 2.0;
    const double mj = 0.5;
    const double ai = 1.2;
    const double aj = 0.6;
    const double mRed = mi*mj/(mi + mj);
    const double kn = 1e4;

    // Normal spring fastest
    EXPECT_NEAR
    (
        FrictionalContact::contactTimeScale(params(kn, 0.1*kn, 0, 1), mi, ai, mj, aj),
        pi/std::sqrt(kn/mRed),
        1e-14
    );
    // Tangential spring: omega_t^2 = 7/2 k_t/m_red
    EXPECT_NEAR
    (
        FrictionalContact::contactTimeScale(params(kn, kn, 0, 1), mi, ai, mj, aj),
        pi/std::sqrt(3.5*kn/mRed),
        1e-14
    );
    // Rolling spring: omega_r^2 = a_ij^2 k_r (1/I_i + 1/I_j)
    FrictionalContact::Params p = params(kn, 0.1*kn, 0, 1);
    p.kr = 50*kn;
    const double aij = 2*ai*aj/(ai + aj);
    const double Ii = 0.4*mi*ai*ai;
    const double Ij = 0.4*mj*aj*aj;
    EXPECT_NEAR
    (
        FrictionalContact::contactTimeScale(p, mi, ai, mj, aj),
        pi/std::sqrt(aij*aij*p.kr*(1/Ii + 1/Ij)),
        1e-14
    );
    // Strong dashpot: m_red/gamma_n
    EXPECT_NEAR
    (
        FrictionalContact::contactTimeScale(params(kn, 0.1*kn, 1e4, 1), mi, ai, mj, aj),
        mRed/1e4,
        1e-14
    );
}


TEST(Contact, ParamsFromPaperGroups)
{
    // Table 3: kHat = 4e5, k_t/k_n = 2/7, gamma_n gammaDot/k_n = 1e-7, mu_C = 1
    const FrictionalContact::Params p =
        FrictionalContact::fromGroups(4e5, 2.0/7.0, 1e-7, 1.0);
    EXPECT_DOUBLE_EQ(p.kn, 4e5);
    EXPECT_DOUBLE_EQ(p.kt, 4e5*2.0/7.0);
    EXPECT_DOUBLE_EQ(p.gammaN, 0.04);
    EXPECT_DOUBLE_EQ(p.muC, 1.0);
    EXPECT_EQ(p.kr, 0);
    EXPECT_NO_THROW(FrictionalContact{p});
}


TEST(Contact, RejectsBadParams)
{
    const FrictionalContact::Params good = params(1e4, 3e3, 1, 0.5);
    EXPECT_NO_THROW(FrictionalContact{good});

    auto expectThrow = [](const FrictionalContact::Params& p, const std::string& what)
    {
        try
        {
            FrictionalContact c(p);
            ADD_FAILURE() << "no exception for " << what;
        }
        catch (const std::invalid_argument& e)
        {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };

    FrictionalContact::Params p = good;
    p.kn = 0;
    expectThrow(p, "kn = 0");
    p = good;
    p.kt = -1;
    expectThrow(p, "kt = -1");
    p = good;
    p.gammaN = NAN;
    expectThrow(p, "gammaN = nan");
    p = good;
    p.muC = -0.1;
    expectThrow(p, "muC = -0.1");
    p = good;
    p.kr = -2;
    expectThrow(p, "kr = -2");
    p = good;
    p.muR = -1;
    expectThrow(p, "muR = -1");
    p = good;
    p.kn = INFINITY;
    expectThrow(p, "kn = inf");
    expectThrow(FrictionalContact::Params(), "kn = nan");
}
