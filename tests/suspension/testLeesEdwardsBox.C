// Lees-Edwards box (eq. 16): images, wraps and the velocity jump
#include "core/LeesEdwardsBox.H"
#include "core/Particles.H"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace suspension;


TEST(LeesEdwardsBox, OffsetGrowsWithStrainModuloLx)
{
    LeesEdwardsBox box(Vec3(10, 8, 6), 0.5);
    box.setStrain(1.5);
    // delta = gamma Ly = 1.5*8 = 12 -> 2 (mod 10); jump gammaDot Ly
    // = 0.5*8
    EXPECT_NEAR(box.offset(), 2.0, 1e-12);
    EXPECT_NEAR(box.imageVelocity(), 4.0, 1e-15);
}


TEST(LeesEdwardsBox, ParticleLeavingTopReentersShifted)
{
    LeesEdwardsBox box(Vec3(10, 8, 6), 1.0);
    box.setStrain(0.3);                     // delta = 2.4
    Vec3 x(5.0, 8.25, 1.0);
    Vec3 u(8.3, 0.1, 0.0);
    const int crossings = box.wrap(x, u);
    EXPECT_EQ(crossings, 1);
    // x - delta, y - Ly, u_x - gammaDot Ly (hand values)
    EXPECT_NEAR(x.x(), 2.6, 1e-12);
    EXPECT_NEAR(x.y(), 0.25, 1e-12);
    EXPECT_NEAR(u.x(), 0.3, 1e-12);
    EXPECT_NEAR(u.y(), 0.1, 1e-15);

    // and back through the bottom
    Vec3 x2(1.0, -0.5, 6.5);
    Vec3 u2(0.0, -0.1, 0.0);
    EXPECT_EQ(box.wrap(x2, u2), -1);
    EXPECT_NEAR(x2.x(), 3.4, 1e-12);
    EXPECT_NEAR(x2.y(), 7.5, 1e-12);
    EXPECT_NEAR(x2.z(), 0.5, 1e-12);
    EXPECT_NEAR(u2.x(), 8.0, 1e-12);
}


TEST(LeesEdwardsBox, MinimumImageAcrossShearedBoundary)
{
    LeesEdwardsBox box(Vec3(10, 8, 6), 1.0);
    box.setStrain(0.3);                     // delta = 2.4
    // i near the top, j near the bottom: j's image above sits at
    // (x_j + delta, y_j + Ly)
    const Vec3 xi(5.0, 7.8, 3.0);
    const Vec3 xj(3.0, 0.1, 3.2);
    Vec3 r = xj - xi;
    const int m = box.minimumImage(r);
    EXPECT_EQ(m, 1);
    EXPECT_NEAR(r.x(), 3.0 + 2.4 - 5.0, 1e-12);
    EXPECT_NEAR(r.y(), 0.1 + 8.0 - 7.8, 1e-12);
    EXPECT_NEAR(r.z(), 0.2, 1e-12);

    // The reverse pair gives the opposite vector and image
    Vec3 s = xi - xj;
    EXPECT_EQ(box.minimumImage(s), -1);
    EXPECT_NEAR((s + r).norm(), 0, 1e-12);
}


TEST(LeesEdwardsBox, RejectsNonPositiveLengths)
{
    EXPECT_THROW(LeesEdwardsBox(Vec3(1, 0, 1), 1.0), std::invalid_argument);
}


TEST(LeesEdwardsBox, PositionThatCannotBeWrappedIsLeftAsItIs)
{
    // A NaN, an infinity or a coordinate 2^40 box lengths out cannot be
    // wrapped: left as it is, u too, no crossing (no conversion of it to
    // an integer: the sanitized build runs this). Just inside the bound
    // the wrap still lands in the box with its crossings
    LeesEdwardsBox box(Vec3(10, 8, 6), 1.0);
    box.setStrain(0.3);
    const double NaN = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const double far = LeesEdwardsBox::maxWrapLengths;
    auto same = [](const Vec3& a, const Vec3& b)    // NaN where NaN
    {
        return ((a.array() == b.array()) || (a.array().isNaN() && b.array().isNaN())).all();
    };
    for (const Vec3& x0 :
        {Vec3(NaN, 1, 1), Vec3(1, NaN, 1), Vec3(1, 1, NaN), Vec3(-inf, 1, 1),
         Vec3(1, inf, 1), Vec3(far*10, 1, 1), Vec3(1, -far*8, 1),
         Vec3(1, 1, far*6), Vec3(1e300, 2e300, 1)})
    {
        EXPECT_FALSE(box.wrappable(x0)) << x0.transpose();
        Vec3 x = x0;
        Vec3 u(1, 2, 3);
        EXPECT_EQ(box.wrap(x, u), 0) << x0.transpose();
        EXPECT_TRUE(same(x, x0)) << x0.transpose() << " -> " << x.transpose();
        EXPECT_EQ(u, Vec3(1, 2, 3)) << x0.transpose();
    }

    const Vec3 x0(0.5*far*10 + 3.0, -0.5*far*8 + 0.25, 0.5*far*6 + 1.0);
    ASSERT_TRUE(box.wrappable(x0));
    Vec3 x = x0;
    Vec3 u(1, 2, 3);
    EXPECT_EQ(box.wrap(x, u), -static_cast<long>(0.5*far));
    EXPECT_TRUE(box.contains(x)) << x.transpose();
    EXPECT_NEAR(u.x(), 1 + 0.5*far*8, 1e-3);
}


TEST(LeesEdwardsBox, OffsetThatCannotBeWrappedThrows)
{
    LeesEdwardsBox box(Vec3(10, 8, 6), 1.0);
    EXPECT_THROW(box.setStrain(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
    EXPECT_THROW(box.setStrain(std::numeric_limits<double>::infinity()), std::invalid_argument);
    EXPECT_THROW(box.setOffset(1e300), std::invalid_argument);
    EXPECT_NO_THROW(box.setStrain(1e6));
    EXPECT_GE(box.offset(), 0);
    EXPECT_LT(box.offset(), 10);
}


TEST(Particles, MassInertiaAndPermutation)
{
    Particles p;
    p.add(Vec3(1, 2, 3), 1.0, 2.0, 7);
    p.add(Vec3(4, 5, 6), 2.0, 2.0, 9);
    EXPECT_NEAR(p.m[0], 4.0/3.0*pi*2.0, 1e-14);
    EXPECT_NEAR(p.I[1], 0.4*p.m[1]*4.0, 1e-12);
    EXPECT_NEAR(p.solidVolume(), 4.0/3.0*pi*9.0, 1e-12);

    p.u[0] = Vec3(1, 0, 0);
    p.permute({1, 0});
    EXPECT_EQ(p.id[0], 9);
    EXPECT_EQ(p.id[1], 7);
    EXPECT_EQ(p.u[1], Vec3(1, 0, 0));
    EXPECT_EQ(p.x[0], Vec3(4, 5, 6));
    EXPECT_THROW(p.add(Vec3::Zero(), -1.0, 1.0, 3), std::invalid_argument);
}
