// ambientFlow::writeFields on a blockMesh box: the written Uinf, gradUinf
// and shearRateInf, read back from disk, hold the analytic values at the cell
// centres and the boundary face centres. The meshSampled flow on such boxes:
// exact for simple shear, converging at second order for the wavy shear,
// bitwise the same from one and many threads, found on the boundary, and a
// point or particle outside is an error naming it.
#include "testAmbientFlowTools.H"
#include "ambientFlowAdapter.H"
#include "core/Particles.H"
#include "Time.H"
#include "fvMesh.H"
#include "volFields.H"
#include "mathematicalConstants.H"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>

using namespace Foam;
using ambientFlowTest::contains;
using ambientFlowTest::flowDict;
using ambientFlowTest::ioErrorOf;
using ambientFlowTest::makeFlow;
using ambientFlowTest::str;
namespace fs = std::filesystem;

namespace
{

// Box 4 x 6 x 2 meshed with 4 x 8 x 2 cells, all sides one patch 'walls'
const vector box(4, 6, 2);

const char* const foamHeader =
    "FoamFile { version 2.0; format ascii; class dictionary; object ";

const char* const controlDict =
    "controlDict; }\n"
    "application none; startFrom startTime; startTime 0;\n"
    "stopAt endTime; endTime 1; deltaT 0.5;\n"
    "writeControl timeStep; writeInterval 1;\n"
    "writeFormat ascii; writePrecision 17; writeCompression off;\n"
    "timeFormat general; timePrecision 6; runTimeModifiable false;\n";

const char* const blockMeshDict =
    "blockMeshDict; }\n"
    "scale 1;\n"
    "vertices ((0 0 0) (4 0 0) (4 6 0) (0 6 0)"
    " (0 0 2) (4 0 2) (4 6 2) (0 6 2));\n"
    "blocks (hex (0 1 2 3 4 5 6 7) (4 8 2) simpleGrading (1 1 1));\n"
    "edges ();\n"
    "boundary ();\n"
    "defaultPatch { name walls; type patch; }\n";

const char* const fvSchemes =
    "fvSchemes; }\n"
    "ddtSchemes { default steadyState; }\n"
    "gradSchemes { default Gauss linear; }\n"
    "divSchemes { default none; }\n"
    "laplacianSchemes { default Gauss linear corrected; }\n"
    "interpolationSchemes { default linear; }\n"
    "snGradSchemes { default corrected; }\n";

const char* const fvSolution = "fvSolution; }\n";


//- Temporary case directory, removed at the end of the test
class AmbientFlowFields
:
    public ::testing::Test
{
protected:

    fs::path caseDir_;

    void SetUp() override
    {
        std::string tmpl =
            (fs::temp_directory_path()/"testAmbientFlowXXXXXX").string();
        ASSERT_NE(mkdtemp(tmpl.data()), nullptr);
        caseDir_ = tmpl;

        fs::create_directories(caseDir_/"system");
        writeDict("controlDict", controlDict);
        writeDict("blockMeshDict", blockMeshDict);
        writeDict("fvSchemes", fvSchemes);
        writeDict("fvSolution", fvSolution);
    }

    void TearDown() override
    {
        if (!caseDir_.empty())
        {
            fs::remove_all(caseDir_);
        }
    }

    void writeDict(const std::string& name, const std::string& body) const
    {
        std::ofstream(caseDir_/"system"/name) << foamHeader << body;
    }

    //- Mesh the box with nx x ny x nz cells and read it
    std::unique_ptr<fvMesh> mesh(const Time& runTime, int nx, int ny, int nz) const
    {
        std::string dict = blockMeshDict;
        const std::string cells = "(4 8 2)";
        dict.replace
        (
            dict.find(cells), cells.size(),
            "(" + std::to_string(nx) + " " + std::to_string(ny) + " "
          + std::to_string(nz) + ")"
        );
        writeDict("blockMeshDict", dict);
        const std::string blockMesh =
            "blockMesh -case '" + caseDir_.string() + "' > '"
          + (caseDir_/"log.blockMesh").string() + "' 2>&1";
        EXPECT_EQ(std::system(blockMesh.c_str()), 0)
            << "see " << (caseDir_/"log.blockMesh");
        return std::make_unique<fvMesh>
        (
            IOobject
            (
                fvMesh::defaultRegion,
                runTime.timeName(),
                runTime,
                IOobject::MUST_READ
            )
        );
    }

    //- The case's Time
    std::unique_ptr<Time> time() const
    {
        return std::make_unique<Time>
        (
            Time::controlDictName,
            caseDir_.parent_path().string(),
            caseDir_.filename().string(),
            "system",
            "constant",
            false,      // no function objects
            false       // no libraries
        );
    }
};


//- Compare fld, cells and boundary faces, with f at the centres;
//  every patch is calculated
template<class Type, class Function>
void expectAnalytic
(
    const GeometricField<Type, fvPatchField, volMesh>& fld,
    const Function& f
)
{
    SCOPED_TRACE(fld.name());
    const volVectorField& C = fld.mesh().C();
    const scalar tol = 1e-13;

    forAll(fld, celli)
    {
        const Type expected = f(C[celli]);
        EXPECT_LE(mag(fld[celli] - expected), tol*(1 + mag(expected)))
            << "cell " << celli;
    }

    forAll(fld.boundaryField(), patchi)
    {
        const fvPatchField<Type>& pf = fld.boundaryField()[patchi];
        const fvPatchVectorField& Cf = C.boundaryField()[patchi];
        EXPECT_EQ(pf.type(), "calculated");
        EXPECT_GT(pf.size(), 0);
        forAll(pf, facei)
        {
            const Type expected = f(Cf[facei]);
            EXPECT_LE(mag(pf[facei] - expected), tol*(1 + mag(expected)))
                << "patch " << pf.patch().name() << " face " << facei;
        }
    }
}

} // End anonymous namespace


TEST_F(AmbientFlowFields, WrittenFieldsHoldTheAnalyticValues)
{
    const std::unique_ptr<Time> runTimePtr = time();
    Time& runTime = *runTimePtr;
    const std::unique_ptr<fvMesh> meshPtr = mesh(runTime, 4, 8, 2);
    const fvMesh& mesh = *meshPtr;
    ASSERT_EQ(mesh.nCells(), 4*8*2);

    const autoPtr<ambientFlow> flow
    (
        makeFlow
        (
            "type wavyShear; shearRate 1; amplitude 2.5; periods 1;", box
        )
    );

    // Written at the mesh's current time
    runTime.setTime(0.5, 1);
    flow->writeFields(mesh, wordHashSet(ambientFlow::fieldNames));
    for (const char* name : {"Uinf", "gradUinf", "shearRateInf"})
    {
        EXPECT_TRUE(fs::is_regular_file(caseDir_/"0.5"/name)) << name;
    }

    // Read back from disk as ParaView's reader would see them
    const auto readBack = [&](const word& name)
    {
        return IOobject
        (
            name, runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
    };
    const volVectorField Uinf(readBack("Uinf"), mesh);
    const volTensorField gradUinf(readBack("gradUinf"), mesh);
    const volScalarField shearRateInf(readBack("shearRateInf"), mesh);

    // Eq. (17) written out: U_x = gammaDot y + A sin(k y), k = 2 pi n/Ly
    const scalar k = constant::mathematical::twoPi/box.y();
    const auto dUxdy = [&](const point& p)
    {
        return 1 + 2.5*k*std::cos(k*p.y());
    };
    expectAnalytic
    (
        Uinf,
        [&](const point& p)
        {
            return vector(p.y() + 2.5*std::sin(k*p.y()), 0, 0);
        }
    );
    expectAnalytic
    (
        gradUinf,
        [&](const point& p)
        {
            tensor g(Zero);
            g.yx() = dUxdy(p);
            return g;
        }
    );
    expectAnalytic(shearRateInf, dUxdy);

    EXPECT_EQ(Uinf.dimensions(), dimVelocity);
    EXPECT_EQ(gradUinf.dimensions(), dimless/dimTime);
    EXPECT_EQ(shearRateInf.dimensions(), dimless/dimTime);
}


TEST_F(AmbientFlowFields, MeshSampledFlowIsExactForShearAndConvergesForTheWave)
{
    const std::unique_ptr<Time> runTime = time();
    const dictionary shear =
        flowDict("type meshSampled; flow { type uniformShear; shearRate 1.5; }");
    const dictionary wave = flowDict
    (
        "type meshSampled;"
        " flow { type wavyShear; shearRate 1; amplitude 0.5; periods 1; }"
    );
    const autoPtr<ambientFlow> exact
    (
        makeFlow("type wavyShear; shearRate 1; amplitude 0.5; periods 1;", box)
    );

    // Points inside the box, at least 1.5 coarse cells (0.75 of 6/12) from
    // the walls in y, where the boundary values of the derivatives enter
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<point> points;
    for (int k = 0; k < 50; ++k)
    {
        points.push_back(point(4*u(gen), 1.125 + 3.75*u(gen), 2*u(gen)));
    }

    // Largest errors of U and grad U over the points, n cells across y
    auto errors = [&](const dictionary& dict, const ambientFlow& reference, int n)
    {
        const std::unique_ptr<fvMesh> m = mesh(*runTime, n/2, n, n/2);
        const autoPtr<ambientFlow> sampled(ambientFlow::New(dict, box, m.get()));
        EXPECT_EQ(sampled->shearRate(), reference.shearRate());
        scalar eU = 0, eGradU = 0;
        for (const point& p : points)
        {
            eU = max(eU, mag(sampled->U(p) - reference.U(p)));
            eGradU = max(eGradU, mag(sampled->gradU(p) - reference.gradU(p)));
        }
        return std::pair<scalar, scalar>(eU, eGradU);
    };

    // Simple shear is linear: sampled, differentiated and interpolated exactly
    const autoPtr<ambientFlow> linear(makeFlow("type uniformShear; shearRate 1.5;", box));
    const std::pair<scalar, scalar> e0 = errors(shear, linear(), 8);
    EXPECT_LT(e0.first, 1e-12);
    EXPECT_LT(e0.second, 1e-12);

    // The wave: second order in the cell size
    const std::pair<scalar, scalar> e16 = errors(wave, exact(), 16);
    const std::pair<scalar, scalar> e32 = errors(wave, exact(), 32);
    EXPECT_GT(e16.first, 1e-6);
    EXPECT_GT(e16.first/e32.first, 3);
    EXPECT_GT(e16.second/e32.second, 3);

    // Without a mesh the type refuses, naming why
    const std::string message = ioErrorOf([&]() { ambientFlow::New(wave, box); });
    EXPECT_PRED2(contains, message, "samples its flow on the case mesh");
}


TEST_F(AmbientFlowFields, MeshSampledFlowIsTheSameFromManyThreads)
{
    // The engine samples the flow from OpenMP threads: the demand-driven
    // mesh data that the search and the interpolation use is built when
    // the flow is made, and a fresh flow sampled at 4000 points (some on
    // the box faces) on two and on four threads gives bitwise what one
    // thread gives
    const std::unique_ptr<Time> runTime = time();
    const dictionary wave = flowDict
    (
        "type meshSampled;"
        " flow { type wavyShear; shearRate 1; amplitude 0.5; periods 1; }"
    );
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<point> points(4000);
    for (point& p : points)
    {
        p = point(4*u(gen), 6*u(gen), 2*u(gen));
    }
    for (std::size_t k = 0; k < points.size(); k += 100)
    {
        points[k].x() = 0;
        points[k + 1].y() = 6;
    }
    auto sampleAll = [&](int threads)
    {
        const std::unique_ptr<fvMesh> m = mesh(*runTime, 8, 16, 8);
        const autoPtr<ambientFlow> flow(ambientFlow::New(wave, box, m.get()));
        EXPECT_TRUE(m->hasCellPoints() && m->hasPointCells());
        std::vector<ambientFlowSample> f(points.size());
        std::vector<char> found(points.size());
        #pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
        for (std::size_t k = 0; k < points.size(); ++k)
        {
            found[k] = flow->sample(points[k], f[k]);
        }
        for (std::size_t k = 0; k < points.size(); ++k)
        {
            EXPECT_TRUE(found[k]) << "point " << k << " at " << str(points[k]);
        }
        return f;
    };
    const std::vector<ambientFlowSample> one = sampleAll(1);
    for (const int threads : {2, 4})
    {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        const std::vector<ambientFlowSample> many = sampleAll(threads);
        for (std::size_t k = 0; k < points.size(); ++k)
        {
            EXPECT_EQ(one[k].U, many[k].U) << "point " << k;
            EXPECT_EQ(one[k].gradU, many[k].gradU) << "point " << k;
            EXPECT_EQ(one[k].laplacianU, many[k].laplacianU) << "point " << k;
            EXPECT_EQ(one[k].gradLaplacianU, many[k].gradLaplacianU)
                << "point " << k;
        }
    }
}


TEST_F(AmbientFlowFields, SelectedForAMeshSpanningTheBox)
{
    // New(mesh, dict), as another solver would call it: the box is the
    // mesh's span, so the wave's period is the mesh height
    const std::unique_ptr<Time> runTime = time();
    const std::unique_ptr<fvMesh> m = mesh(*runTime, 4, 8, 2);
    const autoPtr<ambientFlow> wave
    (
        ambientFlow::New
        (
            *m, flowDict("type wavyShear; shearRate 1; amplitude 2; periods 1;")
        )
    );
    EXPECT_EQ(wave->box(), box);
    EXPECT_DOUBLE_EQ(wave->U(point(1, 1.5, 1)).x(), 1.5 + 2);

    const autoPtr<ambientFlow> sampled
    (
        ambientFlow::New
        (
            *m,
            flowDict
            (
                "type meshSampled; flow { type uniformShear; shearRate 1; }"
            )
        )
    );
    EXPECT_EQ(sampled->type(), "meshSampled");
    EXPECT_EQ(sampled->bounds(), m->bounds());
}


TEST_F(AmbientFlowFields, MeshSampledFlowIsFoundOnTheBoundaryOnly)
{
    // The box 4 x 6 x 2 is the mesh: its faces, edges and corners (within
    // round-off) are sampled, with the values of the cell they bound; a
    // point beyond the boundary by more than the tolerance is not, and
    // asking for its values is a Foam::error naming the point and the mesh
    const std::unique_ptr<Time> runTime = time();
    const std::unique_ptr<fvMesh> m = mesh(*runTime, 4, 8, 2);
    const autoPtr<ambientFlow> flow
    (
        ambientFlow::New
        (
            flowDict
            (
                "type meshSampled; flow { type wavyShear;"
                " shearRate 1; amplitude 0.5; periods 1; }"
            ),
            box,
            m.get()
        )
    );
    EXPECT_EQ(flow->bounds(), m->bounds());

    const scalar eps = 1e-14;
    ambientFlowSample values;
    for
    (
        const point& p :
        {
            point(0, 3.1, 1.3), point(4, 3.1, 1.3), point(2.2, 0, 1.3),
            point(2.2, 6, 1.3), point(2.2, 3.1, 0), point(2.2, 3.1, 2),
            point(0, 0, 0), point(4, 6, 2), point(-eps, 3.1, 1.3),
            point(2.2, 6 + 4*eps, 1.3)
        }
    )
    {
        EXPECT_TRUE(flow->sample(p, values)) << "at " << str(p);
        // Interpolated within the cell next to the face: a point just
        // inside has nearly the same values
        const point inside = p + 1e-9*(point(2, 3, 1) - p);
        EXPECT_LT(mag(values.U - flow->U(inside)), 1e-6) << "at " << str(p);
    }

    const scalar diagonal = mag(m->bounds().span());
    for
    (
        const point& p :
        {
            point(-1e-6*diagonal, 3.1, 1.3), point(2.2, 6.01, 1.3),
            point(2.2, 3.1, -0.5), point(40, 60, 20)
        }
    )
    {
        EXPECT_FALSE(flow->sample(p, values)) << "at " << str(p);
        try
        {
            flow->U(p);
            ADD_FAILURE() << "no Foam::error for a point outside at " << str(p);
        }
        catch (const Foam::error& err)
        {
            const std::string msg = err.message();
            EXPECT_PRED2(contains, msg, "is not known at point");
            EXPECT_PRED2(contains, msg, "outside its bounds (0 0 0) (4 6 2)");
        }
    }
}


TEST_F(AmbientFlowFields, ParticleOutsideTheMeshStopsTheRunNamingIt)
{
    // The engine samples every particle (from threads), then calls
    // sampled(): the adapter records a particle outside the mesh and there
    // raises a Foam::error naming the first one (id, index, position) and
    // the mesh bounds; particles inside, or on the boundary, pass
    const std::unique_ptr<Time> runTime = time();
    const std::unique_ptr<fvMesh> m = mesh(*runTime, 4, 8, 2);
    const autoPtr<ambientFlow> flow
    (
        ambientFlow::New
        (
            flowDict
            (
                "type meshSampled; flow { type uniformShear; shearRate 1; }"
            ),
            box,
            m.get()
        )
    );
    const ambientFlowAdapter adapter(*flow);
    const suspension::AmbientFlow& engine = adapter;

    // Two inside (one on the corner of two faces), then two outside
    suspension::Particles inside;
    inside.add(suspension::Vec3(1, 2, 1), 1, 1, 10);
    inside.add(suspension::Vec3(0, 6, 1), 1, 1, 11);
    suspension::Particles all = inside;
    all.add(suspension::Vec3(3, 7.5, 1), 1, 1, 12);
    all.add(suspension::Vec3(3, -1, 1), 1, 1, 13);

    auto sampleAll = [&](const suspension::Particles& p)
    {
        std::vector<suspension::FlowSample> f(p.size());
        #pragma omp parallel for num_threads(2)
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            f[i] = engine.sample(p.x[i], 1.0);
        }
        return f;
    };

    // Inside: the values of simple shear; on the boundary: those of the
    // cell it touches (interpolated with the boundary point values)
    const std::vector<suspension::FlowSample> f = sampleAll(inside);
    EXPECT_NO_THROW(engine.sampled(inside));
    EXPECT_NEAR(f[0].U.x(), 2, 1e-12);
    EXPECT_LT(mag(toFoam(f[1].U) - flow->U(point(1e-9, 6 - 1e-9, 1))), 1e-6);

    // Two outside: the first is named
    sampleAll(all);
    try
    {
        engine.sampled(all);
        ADD_FAILURE() << "no Foam::error for particles outside the mesh";
    }
    catch (const Foam::error& err)
    {
        const std::string msg = err.message();
        EXPECT_PRED2
        (
            contains, msg, "particle id 12 (index 2 of 4) at (3 7.5 1)"
        );
        EXPECT_PRED2(contains, msg, "outside its bounds (0 0 0) (4 6 2)");
    }

    // Reported once: the next loop starts afresh
    sampleAll(inside);
    EXPECT_NO_THROW(engine.sampled(inside));
}


TEST_F(AmbientFlowFields, MeshFieldIsTheShearPlusTheRegisteredFieldAndFollowsIt)
{
    // meshField: gammaDot y e_x plus the field a solver registers; the
    // samples of a zero field are bitwise those of uniformShear, correct()
    // reports a change only when the registered field differs bitwise from
    // the one in use, and then the samples and the bound follow it
    const std::unique_ptr<Time> runTime = time();
    const std::unique_ptr<fvMesh> m = mesh(*runTime, 4, 32, 2);     // k dy = 0.2
    const dictionary dict = flowDict("type meshField; shearRate 1; field Uprime;");

    // No field registered: an error naming the entry and the solver
    const std::string missing =
        ioErrorOf([&]() { ambientFlow::New(dict, box, m.get()); });
    EXPECT_PRED2(contains, missing, "'Uprime' (entry 'field')");
    EXPECT_PRED2(contains, missing, "suspensionCoupledFoam");

    volVectorField Uprime
    (
        IOobject("Uprime", runTime->timeName(), *m), *m,
        dimensionedVector(dimVelocity, Zero)
    );
    autoPtr<ambientFlow> flow(ambientFlow::New(dict, box, m.get()));
    const autoPtr<ambientFlow> shear(makeFlow("type uniformShear; shearRate 1;", box));
    const point p(1.3, 2.7, 0.9);
    EXPECT_EQ(str(flow->U(p)), str(shear->U(p)));
    EXPECT_EQ(flow->gradU(p), shear->gradU(p));
    EXPECT_EQ(flow->maxVelocityGradient(), 1);
    EXPECT_FALSE(flow->correct()) << "the same field is no change";

    // A wave u' = A sin(k y) e_x at the cell and boundary face centres
    const scalar k = constant::mathematical::twoPi/box.y();
    const auto wave = [&](const point& c) { return vector(0.3*std::sin(k*c.y()), 0, 0); };
    forAll(Uprime, celli)
    {
        Uprime[celli] = wave(m->C()[celli]);
    }
    forAll(Uprime.boundaryField(), patchi)
    {
        forAll(Uprime.boundaryField()[patchi], facei)
        {
            Uprime.boundaryFieldRef()[patchi][facei] =
                wave(m->C().boundaryField()[patchi][facei]);
        }
    }
    EXPECT_EQ(flow->U(p).x(), shear->U(p).x()) << "not taken before correct()";
    EXPECT_TRUE(flow->correct());
    EXPECT_FALSE(flow->correct());
    EXPECT_NEAR(flow->U(p).x(), p.y() + 0.3*std::sin(k*p.y()), 0.005);
    EXPECT_NEAR(flow->gradU(p).yx(), 1 + 0.3*k*std::cos(k*p.y()), 0.01);
    EXPECT_GT(flow->maxVelocityGradient(), 1 + 0.2*k);
    EXPECT_LE(flow->maxVelocityGradient(), 1 + 0.3*k*1.01 + 0.3*k)
        << "|gammaDot| + max |grad u'|";
}
