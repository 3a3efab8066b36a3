// ambientFlow types (eq. 17): derivatives against central differences of the
// Foam-side U and laplacianU, E and Omega against finite differences,
// periodicity of the wave in y, and the engine adapter.
#include "testAmbientFlowTools.H"
#include "ambientFlowAdapter.H"
#include "mathematicalConstants.H"

#include <cmath>
#include <random>

using namespace Foam;
using ambientFlowTest::makeFlow;

namespace
{

const vector box(10.0, 17.3, 8.0);

//- The flows under test: a negative uniform shear and a two-period wave
//  with the paper's amplitude (table 3, YW: script-U = 20 gammaDot a0)
const char* const flowEntries[] =
{
    "type uniformShear; shearRate -0.7;",
    "type wavyShear; shearRate 1; amplitude 20; periods 2;"
};

//- Random points in and around the box (the flow is defined everywhere)
std::vector<point> randomPoints(unsigned seed, int n)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<scalar> u(-0.5, 1.5);
    std::vector<point> pts;
    for (int s = 0; s < n; ++s)
    {
        pts.emplace_back(u(gen)*box.x(), u(gen)*box.y(), u(gen)*box.z());
    }
    return pts;
}

//- Central difference of f along axis i at p
template<class F>
auto centralDiff(const F& f, const point& p, direction i, scalar h)
{
    vector e(Zero);
    e[i] = h;
    return (f(p + e) - f(p - e))/(2*h);
}

//- Central-difference gradient (grad v)_ij = d_i v_j at p
template<class F>
tensor fdGrad(const F& f, const point& p, scalar h)
{
    tensor g(Zero);
    for (direction i = 0; i < 3; ++i)
    {
        const vector d = centralDiff(f, p, i, h);
        for (direction j = 0; j < 3; ++j)
        {
            g(i, j) = d[j];
        }
    }
    return g;
}

void expectTensorNear(const tensor& a, const tensor& b, scalar relTol)
{
    for (direction c = 0; c < tensor::nComponents; ++c)
    {
        EXPECT_NEAR(a[c], b[c], relTol*(1 + mag(b[c])))
            << "component " << c;
    }
}

void expectVectorNear(const vector& a, const vector& b, scalar relTol)
{
    for (direction c = 0; c < vector::nComponents; ++c)
    {
        EXPECT_NEAR(a[c], b[c], relTol*(1 + mag(b[c])))
            << "component " << c;
    }
}

} // End anonymous namespace


TEST(AmbientFlowDerivatives, GradientsMatchCentralDifferences)
{
    for (const char* entries : flowEntries)
    {
        SCOPED_TRACE(entries);
        const autoPtr<ambientFlow> flow(makeFlow(entries, box));
        const auto U = [&](const point& p) { return flow->U(p); };
        const auto lapU = [&](const point& p) { return flow->laplacianU(p); };

        for (const point& p : randomPoints(11, 25))
        {
            // First differences, h = 1e-4: truncation h^2/6 |d^3 U| ~ 1e-8
            expectTensorNear(flow->gradU(p), fdGrad(U, p, 1e-4), 1e-6);
            expectTensorNear
            (
                flow->gradLaplacianU(p), fdGrad(lapU, p, 1e-4), 1e-6
            );

            // Second differences, h = 1e-3: truncation h^2/12 |d^4 U| ~ 5e-7
            const scalar h = 1e-3;
            vector lapFD(Zero);
            for (direction i = 0; i < 3; ++i)
            {
                vector e(Zero);
                e[i] = h;
                lapFD += (U(p + e) - 2*U(p) + U(p - e))/(h*h);
            }
            expectVectorNear(flow->laplacianU(p), lapFD, 1e-5);
        }
    }
}


TEST(AmbientFlowDerivatives, StrainAndRotationFromFiniteDifferences)
{
    for (const char* entries : flowEntries)
    {
        SCOPED_TRACE(entries);
        const autoPtr<ambientFlow> flow(makeFlow(entries, box));
        const auto U = [&](const point& p) { return flow->U(p); };

        for (const point& p : randomPoints(12, 25))
        {
            const tensor G = fdGrad(U, p, 1e-4);

            // E: symmetric part of the velocity gradient
            const tensor E(flow->E(p));
            expectTensorNear(E, 0.5*(G + G.T()), 1e-6);

            // Omega = curl(U)/2 with (curl U)_x = d_y U_z - d_z U_y, ...
            const vector Om = flow->Omega(p);
            const vector curlFD
            (
                G(1, 2) - G(2, 1),
                G(2, 0) - G(0, 2),
                G(0, 1) - G(1, 0)
            );
            expectVectorNear(Om, 0.5*curlFD, 1e-6);

            // gradU = E + W with the antisymmetric part W dual to Omega:
            // W_yz = Omega_x, W_zx = Omega_y, W_xy = Omega_z
            const tensor W = flow->gradU(p) - E;
            expectTensorNear(W, -W.T(), 1e-12);
            expectVectorNear(vector(W.yz(), W.zx(), W.xy()), Om, 1e-12);

            // Local shear rate (fig. 10) = d_y U_x
            EXPECT_NEAR
            (
                flow->localShearRate(p), G(1, 0), 1e-6*(1 + mag(G(1, 0)))
            );

            // The bound used for the neighbour-list skin holds
            EXPECT_LE(mag(flow->gradU(p)), flow->maxVelocityGradient());
        }
    }
}


TEST(AmbientFlowDerivatives, SimpleShearValues)
{
    const autoPtr<ambientFlow> flow
    (
        makeFlow("type uniformShear; shearRate -0.7;", box)
    );
    const point p(1.3, 2.9, -4.1);

    EXPECT_DOUBLE_EQ(flow->shearRate(), -0.7);
    EXPECT_DOUBLE_EQ(flow->U(p).x(), -0.7*2.9);
    EXPECT_EQ(flow->U(p).y(), 0);
    EXPECT_EQ(flow->U(p).z(), 0);
    EXPECT_DOUBLE_EQ(flow->gradU(p).yx(), -0.7);
    EXPECT_DOUBLE_EQ(flow->E(p).xy(), -0.35);
    EXPECT_DOUBLE_EQ(flow->Omega(p).z(), 0.35);
    EXPECT_EQ(mag(flow->laplacianU(p)), 0);
    EXPECT_EQ(mag(flow->gradLaplacianU(p)), 0);
    EXPECT_DOUBLE_EQ(flow->maxVelocityGradient(), 0.7);
}


TEST(AmbientFlowDerivatives, WavyShearValuesOfEq17)
{
    // U_x = gammaDot y + A sin(2 pi n y / Ly): at y = Ly/(4 n) the sine is 1
    const scalar gammaDot = 1.5, A = 20, n = 2, Ly = box.y();
    const autoPtr<ambientFlow> flow
    (
        makeFlow
        (
            "type wavyShear; shearRate 1.5; amplitude 20; periods 2;", box
        )
    );

    const point crest(0.3, Ly/(4*n), 0.2);
    EXPECT_DOUBLE_EQ(flow->U(crest).x(), gammaDot*crest.y() + A);
    EXPECT_NEAR(flow->localShearRate(crest), gammaDot, 1e-12*A);

    // At y = 0 the wave's slope is maximal: d_y U_x = gammaDot + A 2 pi n/Ly
    const scalar k = 2*constant::mathematical::pi*n/Ly;
    EXPECT_DOUBLE_EQ(flow->localShearRate(point(0.7, 0, 0.4)), gammaDot + A*k);
    EXPECT_DOUBLE_EQ(flow->maxVelocityGradient(), gammaDot + A*k);
    EXPECT_DOUBLE_EQ(flow->shearRate(), gammaDot);

    // The mean of the local shear rate over a period is the mean shear rate
    const label nSamples = 64;
    scalar mean = 0;
    for (label s = 0; s < nSamples; ++s)
    {
        mean += flow->localShearRate(point(0, s*Ly/nSamples, 0))/nSamples;
    }
    EXPECT_NEAR(mean, gammaDot, 1e-12*A);
}


TEST(AmbientFlowDerivatives, WavyShearIsPeriodicInY)
{
    const autoPtr<ambientFlow> flow
    (
        makeFlow(flowEntries[1], box)
    );
    const scalar gammaDot = flow->shearRate();
    const vector shiftY(0, box.y(), 0);
    const scalar tol = 1e-11;

    for (const point& p : randomPoints(13, 25))
    {
        // Only the mean shear jumps across the box: U(y + Ly) - U(y)
        // = gammaDot Ly e_x, as the Lees-Edwards images require (eq. 16)
        expectVectorNear
        (
            flow->U(p + shiftY) - flow->U(p),
            vector(gammaDot*box.y(), 0, 0),
            tol
        );
        expectTensorNear(flow->gradU(p + shiftY), flow->gradU(p), tol);
        expectVectorNear
        (
            flow->laplacianU(p + shiftY), flow->laplacianU(p), tol
        );
        expectTensorNear
        (
            flow->gradLaplacianU(p + shiftY), flow->gradLaplacianU(p), tol
        );
    }
}


TEST(AmbientFlowDerivatives, AdapterGivesTheFoamValues)
{
    for (const char* entries : flowEntries)
    {
        SCOPED_TRACE(entries);
        const autoPtr<ambientFlow> flow(makeFlow(entries, box));
        const ambientFlowAdapter adapter(*flow);
        const suspension::AmbientFlow& engine = adapter;

        EXPECT_EQ(engine.shearRate(0), flow->shearRate());
        EXPECT_EQ
        (
            engine.maxVelocityGradient(flow->shearRate()),
            flow->maxVelocityGradient()
        );

        for (const point& p : randomPoints(14, 10))
        {
            const suspension::FlowSample f =
                engine.sample(suspension::Vec3(p.x(), p.y(), p.z()), flow->shearRate());

            const vector U = flow->U(p);
            const vector lapU = flow->laplacianU(p);
            const tensor G = flow->gradU(p);
            const tensor GL = flow->gradLaplacianU(p);
            const tensor E(flow->E(p));
            const vector Om = flow->Omega(p);
            for (direction i = 0; i < 3; ++i)
            {
                EXPECT_EQ(f.U(i), U[i]);
                EXPECT_EQ(f.laplacianU(i), lapU[i]);
                EXPECT_DOUBLE_EQ(f.Omega()(i), Om[i]);
                for (direction j = 0; j < 3; ++j)
                {
                    // Same (i, j) on both sides: (grad U)_ij = d_i U_j
                    EXPECT_EQ(f.gradU(i, j), G(i, j));
                    EXPECT_EQ(f.gradLaplacianU(i, j), GL(i, j));
                    EXPECT_DOUBLE_EQ(f.E()(i, j), E(i, j));
                }
            }
        }
    }
}


TEST(AmbientFlowDerivatives, FieldsHoldThePointValues)
{
    for (const char* entries : flowEntries)
    {
        SCOPED_TRACE(entries);
        const autoPtr<ambientFlow> flow(makeFlow(entries, box));
        pointField points;
        for (const point& p : randomPoints(15, 20))
        {
            points.append(p);
        }

        const vectorField U(flow->U(points));
        const tensorField G(flow->gradU(points));
        const vectorField lapU(flow->laplacianU(points));
        const tensorField GL(flow->gradLaplacianU(points));
        ASSERT_EQ(U.size(), 20);
        ASSERT_EQ(G.size(), 20);
        ASSERT_EQ(lapU.size(), 20);
        ASSERT_EQ(GL.size(), 20);
        forAll(points, i)
        {
            const ambientFlowSample s = flow->sample(points[i]);
            EXPECT_EQ(U[i], s.U) << "point " << i;
            EXPECT_EQ(G[i], s.gradU) << "point " << i;
            EXPECT_EQ(lapU[i], s.laplacianU) << "point " << i;
            EXPECT_EQ(GL[i], s.gradLaplacianU) << "point " << i;
        }
    }
}
