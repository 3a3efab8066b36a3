// The cost of a decomposed run (not a test): Table 1 FR spheres (radii 1
// and 1.4, equal volumes, phi = 0.5, lubrication and frictional contacts)
// or Table 3 (radii 1 and 3, V2/V1 = 0.25, phi = 0.5, every force of the
// paper, the attraction to 4 a0: suspensionBenchmark -case table3), the
// same packing on every process, decomposed in P slabs in y; the time
// per step, the part of it spent in communication (every Communicator
// call, waits included), the halo (ghosts per owned particle) and the bytes
// sent per step, the largest over the processes. One CSV row on the master:
//     mpirun -np P parallelBenchmark -parallel [-N 8000] [-steps 20]
//         [-case table1|table3] [-integrator implicitEuler|velocityVerlet]
//         [-header]
// Without -parallel, the serial run (P = 1). docs/performance/parallel.sh
// pairs it with the threaded run.
#include "pstreamCommunicator.H"
#include "argList.H"
#include "Pstream.H"
#include "modelTestTools.H"
#include "flow/ShearFlow.H"

#include <chrono>
#include <iostream>
#include <omp.h>

using namespace suspension;

namespace
{
    using Clock = std::chrono::steady_clock;

    //- A Communicator that times another and counts the bytes it sends
    class TimedCommunicator final : public Communicator
    {
        const Communicator& comm_;
        mutable double seconds_ = 0;
        mutable double bytes_ = 0;

        template<class F>
        void timed(F f) const
        {
            const auto t0 = Clock::now();
            f();
            seconds_ += std::chrono::duration<double>(Clock::now() - t0).count();
        }

    public:

        explicit TimedCommunicator(const Communicator& comm) : comm_(comm) {}

        int rank() const override { return comm_.rank(); }
        int size() const override { return comm_.size(); }
        void sum(double* v, std::size_t n) const override
        {
            timed([&] { comm_.sum(v, n); });
        }
        void max(double* v, std::size_t n) const override
        {
            timed([&] { comm_.max(v, n); });
        }
        void exchange(const std::vector<Buffer>& send, std::vector<Buffer>& receive) const override
        {
            for (const Buffer& b : send)
            {
                bytes_ += double(b.size());
            }
            timed([&] { comm_.exchange(send, receive); });
        }

        void reset() const { seconds_ = 0; bytes_ = 0; }
        double seconds() const { return seconds_; }
        double bytes() const { return bytes_; }
    };
}


int main(int argc, char* argv[])
{
    Foam::argList::noBanner();
    Foam::argList::noJobInfo();
    Foam::argList::noCheckProcessorDirectories();
    Foam::argList::addOption("N", "label", "particles (8000)");
    Foam::argList::addOption("steps", "label", "timed steps (20)");
    Foam::argList::addOption("integrator", "word", "implicitEuler or velocityVerlet");
    Foam::argList::addOption("case", "word", "table1 (default) or table3");
    Foam::argList::addBoolOption("header", "print the CSV header only");
    Foam::argList args(argc, argv);
    if (args.found("header"))
    {
        std::cout << "case,P,threads,integrator,N,steps,s_per_step,comm_s_per_step,"
                     "comm_fraction,ghosts_per_owned,MB_sent_per_step,cg_iterations\n";
        return 0;
    }
    const int N = args.opt<Foam::label>("N", 8000);
    const int steps = args.opt<Foam::label>("steps", 20);
    const std::string integrator = args.opt<Foam::word>("integrator", "implicitEuler");

    const Foam::pstreamCommunicator pstream;
    const TimedCommunicator comm(pstream);
    const int P = comm.size();
    const double rho = 1e-3;
    const std::string caseName = args.opt<Foam::word>("case", "table1");
    if (caseName != "table1" && caseName != "table3")
    {
        std::cerr << "parallelBenchmark: -case takes table1 or table3\n";
        return 2;
    }
    const bool table3 = caseName == "table3";
    const ForceModels models =
        table3 ? test::allModels(4) : test::lubricatedContacts(0.05, 4e5, 1.0);
    RandomPacking::Params pp;
    pp.phi = 0.5;
    pp.seed = 1;
    pp.reach = models.interactionGap() + Simulation::Params().skin;
    const RandomPacking::Result packed = RandomPacking(pp).pack
    (
        (
            table3
          ? SizeDistribution::bidisperse(1.0, 3.0, 0.25)
          : SizeDistribution::bidisperse(1.0, 1.4, 1.0)
        ).radii(N),
        rho
    );
    Particles mine;
    const Particles& all = packed.particles;
    for (std::size_t i = comm.rank(); i < all.size(); i += P)
    {
        mine.add(all.x[i], all.a[i], rho, all.id[i]);
    }
    Simulation::Params params;
    params.rho = rho;
    params.integrator = integrator == "velocityVerlet"
      ? Integrator::velocityVerlet : Integrator::implicitEuler;
    const ShearFlow flow(1.0);
    Simulation sim
    (
        std::move(mine), LeesEdwardsBox(packed.box.L(), 1.0), flow, models,
        params, P > 1 ? Decomposition{&comm, {P, 1}} : Decomposition{}
    );
    sim.start(0);
    const double dt = sim.deltaT();
    for (int s = 0; s < 5; ++s)
    {
        sim.step(dt);
    }
    comm.reset();
    double cg = 0;
    const auto t0 = Clock::now();
    for (int s = 0; s < steps; ++s)
    {
        sim.step(dt);
        cg += sim.implicit() ? double(sim.implicit()->statistics().iterations) : 0;
    }
    double worst[4] =
    {
        std::chrono::duration<double>(Clock::now() - t0).count()/steps,
        comm.seconds()/steps,
        sim.domain() ? double(sim.domain()->nGhosts())/double(sim.particles().size() - sim.domain()->nGhosts()) : 0,
        comm.bytes()/steps/1e6
    };
    pstream.max(worst, 4);
    if (comm.rank() == 0)
    {
        std::cout << caseName << ',' << P << ',' << omp_get_max_threads() << ',' << integrator << ','
                  << N << ',' << steps << ',' << worst[0] << ',' << worst[1] << ','
                  << worst[1]/worst[0] << ',' << worst[2] << ',' << worst[3] << ','
                  << cg/steps << '\n';
    }
    return 0;
}
