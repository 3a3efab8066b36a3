// HarmonicRepulsion (tests/extensibility/HarmonicRepulsion.H), the model
// tests/extensibility/addModel.sh adds to a scratch copy: on two spheres
// through the pair loop, against its analytic force and stresslet, and
// its own column of the stress contributions
#include "flow/ShearFlow.H"
#include "forces/ForceField.H"
#include "search/NeighbourSearch.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>

using namespace suspension;

TEST(HarmonicRepulsion, TwoSpheresThroughThePairLoop)
{
    const double ai = 1.0, aj = 1.4, k = 100, range = 0.1;
    const Vec3 n = Vec3(0.48, 0.6, -0.64);
    ForceModels models;
    models.set(HarmonicRepulsion({k, range}));
    const LeesEdwardsBox box(Vec3(12, 12, 12), 0);
    const ShearFlow flow(0);
    const std::vector<std::string>& names = contributionNames();
    const auto column = std::find(names.begin(), names.end(), "harmonic");
    ASSERT_NE(column, names.end()) << "no stress contribution 'harmonic'";

    for (const double h : {0.04, 0.15})
    {
        Particles p;
        p.add(Vec3(6, 6, 6), ai, 1.0, 1);
        p.add(Vec3(6, 6, 6) + (ai + aj + h)*n, aj, 1.0, 2);
        ForceField field(models, p.a);
        NeighbourSearch search({field.nearGap(), 0.1});
        PairList near;
        search.rebuild(p, box, near);
        std::vector<Vec3> F;
        ForceField::Output out;
        out.F = &F;
        const ForceSummary s = field.evaluate
        (
            p, box, flow, near, search.far(), out,
            ForceField::Forces::nonHydrodynamic
        );
        const std::size_t i = p.id[0] == 1 ? 0 : 1;     // sphere 1
        const double abar = 2*ai*aj/(ai + aj);
        const double f = h < range ? -k*abar*(range - h) : 0;
        EXPECT_NEAR((F[i] - f*n).norm(), 0, 1e-12*k) << "h = " << h;
        EXPECT_NEAR((F[1 - i] + f*n).norm(), 0, 1e-12*k) << "h = " << h;
        const Mat3 S = (ai + aj + h)*f*n*n.transpose();
        EXPECT_NEAR
        (
            (s.stresslet[std::distance(names.begin(), column)] - S).norm(),
            0, 1e-12*k
        ) << "h = " << h;
    }
}
