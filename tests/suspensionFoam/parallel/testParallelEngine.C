// The engine decomposed over MPI processes through OpenFOAM's Pstream
// (pstreamCommunicator), against the serial run on every rank: run as
//     mpirun -np P testParallelEngine -parallel
// (ctest: P = 2, 3, 4, oversubscribed). Layouts: P slabs in y, and 2 x 2 in
// y and z at P = 4; explicit and implicit steps.
#include "pstreamCommunicator.H"
#include "argList.H"
#include "Pstream.H"
#include "decompositionTestTools.H"

#include <gtest/gtest.h>

using namespace suspension;

TEST(ParallelEngine, RunsGiveTheSerialTrajectory)
{
    // 100 explicit steps and 20 implicitEuler steps
    const Foam::pstreamCommunicator comm;
    const Vec3 L(12, 12, 12);
    const Particles start = test::decompositionParticles(L, 300, 7);
    std::vector<Domain::Layout> layouts{{comm.size(), 1}};
    if (comm.size() == 4)
    {
        layouts.push_back({2, 2});
    }
    const test::RunCase cases[] =
    {
        {100, 0.5, Integrator::velocityVerlet, nullptr},
        {20, 0.5, Integrator::implicitEuler, nullptr}
    };
    for (const test::RunCase& run : cases)
    {
        SCOPED_TRACE(run.integrator == Integrator::velocityVerlet ? "velocityVerlet" : "implicitEuler");
        const test::RankOutcome serial = test::decomposedRun(start, L, nullptr, {}, run);
        ASSERT_GT(serial.builds, 1u);
        for (const Domain::Layout& layout : layouts)
        {
            SCOPED_TRACE("layout " + std::to_string(layout.ny) + " x " + std::to_string(layout.nz));
            const test::RankOutcome mine = test::decomposedRun(start, L, &comm, layout, run);
            test::expectSerial(serial, mine, comm, 1e-9);
        }
    }
}


int main(int argc, char* argv[])
{
    ::testing::InitGoogleTest(&argc, argv);
    Foam::argList::noBanner();
    Foam::argList::noJobInfo();
    Foam::argList::noCheckProcessorDirectories();
    Foam::argList args(argc, argv);
    if (!Foam::Pstream::parRun())
    {
        std::cerr << "testParallelEngine: run it with mpirun and -parallel\n";
        return 2;
    }
    const int failed = RUN_ALL_TESTS() != 0;
    // Every rank's verdict
    Foam::label any = failed;
    Foam::reduce(any, Foam::maxOp<Foam::label>());
    return any ? 1 : 0;
}
