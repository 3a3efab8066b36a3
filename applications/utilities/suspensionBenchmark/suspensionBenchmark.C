/*---------------------------------------------------------------------------*\
Application
    suspensionBenchmark

Description
    Times the engine on the paper's suspensions and prints one CSV row
    (header with -header): neighbour-search rebuild times for the half and
    full stencils and brute force, time per full step, ns per
    particle-step, peak resident memory of the packing and the simulation
    (before the rebuild timings copy the state), the bytes per particle of the
    pair list with contact history next to the paper's N x M table, and
    the ns per particle-step of each kernel (core/KernelTimes.H: flow
    sampling, pair loop, particle terms, search, implicit hydrodynamics,
    integration; means over the timed steps, rebuild steps included).
    -off switches a force model off (repeatable); the pair range `gap`
    then shrinks to what the remaining models need. -preshear S times a
    sheared state instead of the fresh packing: the packing is first
    sheared to strain S with implicitEuler at its automatic step (the
    explicit step would take millions of steps), and the timed integrator
    continues from that state with its contact history (Simulation::
    restore); contacts_per_particle then counts the contacts of the
    sheared state, and peak_rss_MB includes the shearing.

    -roofline (an implicit integrator) prints instead a row of its own
    (header with -roofline -header): after the timed steps, the time of
    the implicit operator's product y = A x and of one CG iteration
    (HydrodynamicResistance, ConjugateGradient; the difference of 30 and
    10 iterations, over 20) per particle, each the shortest of its
    repeats (STREAM's rule, as for the bandwidths), the bytes they move per
    particle and their flops, and the bandwidth of this machine on the
    same threads: a STREAM-like triad a = b + s c (24 bytes an entry, as
    STREAM counts) and a read-only sum over arrays of 128 MB, well
    beyond the caches. Bytes: each array the kernel streams, once, as the
    operator's (its per-particle and per-entry data; operator_MB in all)
    and the vectors' (those it reads, and twice what it writes: read for
    ownership, or read in place, then written back; vectors_MB for the
    five of the CG), since one may fit in the last-level cache and the
    other not; the partners' x_j, which the spatial order mostly finds in
    cache, as a separate upper bound (48 bytes an entry). Flops: counted from the
    kernels (HydrodynamicResistance.C, ConjugateGradient.H): 67 per
    coupling, 78 per particle for the drag and the self block, 60 per
    contact entry; 150 per particle for the vector updates, the
    preconditioner and the dot products of an iteration.

    Cases (paper tables, all in reduced units a0 = eta0 = gammaDot = 1):
      table3  bidisperse a2/a1 = 3, V2/V1 = 0.25, phi = 0.5; St = 1e-3,
              k = 4e5, kt/kn = 2/7, gamma_n/kn = 1e-7, mu_C = 1, rolling
              kr/kn = 0.1, gammaDot/gammaDot0 = 1, delta_lub = 0.25,
              lambda_D = 0.02, F^R/F^A = 19: every force on
      table1  bidisperse a2/a1 = 1.4, V2/V1 = 1, phi = 0.5, mu_C = 1,
              delta_lub = 0.05: lubrication and frictional contact

Usage
    suspensionBenchmark [-case table3|table1] [-N 4096] [-steps 20]
        [-phi 0.5] [-attractionCutoff 4] [-brute] [-header] [-seed 1]
        [-friction 1] [-contactModel frictionalContact|criticalLoadContact]
        [-criticalLoad 0.1] [-writePacking DIR]
        [-integrator velocityVerlet|implicitEuler|overdamped]
        [-off lubrication|contact|rolling|repulsion|attraction]...
        [-preshear 1] [-roofline] [-safety 0.2] [-rollingFriction 1]
        [-genericPasses]

    Threads: OMP_NUM_THREADS. The particles start from a random
    non-overlapping packing; a few steps are taken before timing.
    -friction sets mu_C (0: the frictionless Table 1 FL); -contactModel
    criticalLoadContact uses the critical-load friction with -criticalLoad
    F_CL. -writePacking DIR writes the packing before any step as
    DIR/box.dat (Lx Ly Lz), DIR/radii.dat (one radius per line) and
    DIR/positions.dat (x y z per line), for other codes to start from.
    -safety sets the automatic step's fraction of its stability limit
    (Simulation::Params, also for the shearing of -preshear);
    -rollingFriction sets mu_r of table3's rolling springs (default mu_C).
    -genericPasses runs the generic pair passes whatever the set of models
    (ForceField::PairPasses; the same results): what a set of
    SpecialisedNearSets (forces/ForceModels.H) saves.
\*---------------------------------------------------------------------------*/

#include "core/Memory.H"
#include "dynamics/Simulation.H"
#include "flow/ShearFlow.H"
#include "forces/ElectroChemicalScales.H"
#include "packing/RandomPacking.H"
#include "packing/SizeDistribution.H"

#include <omp.h>
#include <optional>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

using namespace suspension;

namespace
{
    using Clock = std::chrono::steady_clock;

    double seconds(Clock::time_point a, Clock::time_point b)
    {
        return std::chrono::duration<double>(b - a).count();
    }

    //- The wall times of `repeats` calls of f, sorted
    template<class F>
    std::vector<double> sortedTimes(int repeats, F f)
    {
        std::vector<double> t;
        for (int r = 0; r < repeats; ++r)
        {
            const auto t0 = Clock::now();
            f();
            t.push_back(seconds(t0, Clock::now()));
        }
        std::sort(t.begin(), t.end());
        return t;
    }

    //- Median wall time of `repeats` calls of f
    template<class F>
    double medianTime(int repeats, F f)
    {
        const std::vector<double> t = sortedTimes(repeats, f);
        return t[t.size()/2];
    }

    //- Shortest wall time of `repeats` calls of f: what a kernel bound by
    //  bandwidth can reach on a machine shared with others (STREAM's rule)
    template<class F>
    double bestTime(int repeats, F f)
    {
        return sortedTimes(repeats, f).front();
    }

    double peakRSSMB()
    {
        rusage u;
        getrusage(RUSAGE_SELF, &u);
        return u.ru_maxrss/1024.0;
    }

    struct Options
    {
        std::string caseName = "table3";
        std::size_t N = 4096;
        int steps = 20;
        double phi = 0.5;
        double attractionCutoff = 4;
        double friction = 1;
        std::string contactModel = "frictionalContact";
        double criticalLoad = 0.1;
        double preshear = 0;                // strain before the timing
        double safety = Simulation::Params().safety;
        std::optional<double> rollingFriction;  // mu_r, unset: mu_C
        std::string packingDir;
        bool brute = false;
        bool genericPasses = false;
        bool header = false;
        bool roofline = false;
        std::uint64_t seed = 1;
        Integrator integrator = Integrator::velocityVerlet;
        std::string integratorName = "velocityVerlet";
        std::vector<std::string> off;       // models switched off

        bool on(const std::string& model) const
        {
            return std::find(off.begin(), off.end(), model) == off.end();
        }
    };

    Options parse(int argc, char** argv)
    {
        Options o;
        for (int k = 1; k < argc; ++k)
        {
            const std::string a = argv[k];
            auto value = [&]() -> std::string
            {
                if (k + 1 >= argc)
                {
                    std::cerr << "suspensionBenchmark: " << a << " needs a value\n";
                    std::exit(2);
                }
                return argv[++k];
            };
            if (a == "-case") o.caseName = value();
            else if (a == "-N") o.N = std::stoul(value());
            else if (a == "-steps") o.steps = std::stoi(value());
            else if (a == "-phi") o.phi = std::stod(value());
            else if (a == "-attractionCutoff") o.attractionCutoff = std::stod(value());
            else if (a == "-seed") o.seed = std::stoull(value());
            else if (a == "-friction") o.friction = std::stod(value());
            else if (a == "-criticalLoad") o.criticalLoad = std::stod(value());
            else if (a == "-writePacking") o.packingDir = value();
            else if (a == "-preshear") o.preshear = std::stod(value());
            else if (a == "-safety") o.safety = std::stod(value());
            else if (a == "-rollingFriction") o.rollingFriction = std::stod(value());
            else if (a == "-contactModel")
            {
                o.contactModel = value();
                if
                (
                    o.contactModel != FrictionalContact::typeName
                 && o.contactModel != CriticalLoadContact::typeName
                )
                {
                    std::cerr << "suspensionBenchmark: -contactModel takes "
                        << FrictionalContact::typeName << " or "
                        << CriticalLoadContact::typeName << "\n";
                    std::exit(2);
                }
            }
            else if (a == "-integrator")
            {
                o.integratorName = value();
                if (o.integratorName == "velocityVerlet") o.integrator = Integrator::velocityVerlet;
                else if (o.integratorName == "implicitEuler") o.integrator = Integrator::implicitEuler;
                else if (o.integratorName == "overdamped") o.integrator = Integrator::overdamped;
                else
                {
                    std::cerr << "suspensionBenchmark: unknown integrator " << o.integratorName << "\n";
                    std::exit(2);
                }
            }
            else if (a == "-off")
            {
                // a stress contribution (every model of it) or "rolling"
                const std::string m = value();
                const std::vector<std::string>& names = contributionNames();
                if
                (
                    m != "rolling"
                 && (m == "stokes" || std::find(names.begin(), names.end(), m) == names.end())
                )
                {
                    std::cerr << "suspensionBenchmark: -off takes rolling or one of";
                    for (std::size_t c = 1; c < names.size(); ++c)
                    {
                        std::cerr << " " << names[c];
                    }
                    std::cerr << ", not " << m << "\n";
                    std::exit(2);
                }
                o.off.push_back(m);
            }
            else if (a == "-brute") o.brute = true;
            else if (a == "-genericPasses") o.genericPasses = true;
            else if (a == "-header") o.header = true;
            else if (a == "-roofline") o.roofline = true;
            else
            {
                std::cerr << "suspensionBenchmark: unknown option " << a << "\n";
                std::exit(2);
            }
        }
        if (o.caseName != "table3" && o.caseName != "table1")
        {
            std::cerr << "suspensionBenchmark: -case must be table3 or table1\n";
            std::exit(2);
        }
        if
        (
            o.rollingFriction
         && (o.caseName != "table3" || !o.on("rolling") || !o.on("contact"))
        )
        {
            std::cerr << "suspensionBenchmark: -rollingFriction needs table3's"
                " rolling springs (-case table3, rolling and contact not -off)\n";
            std::exit(2);
        }
        return o;
    }

    ForceModels models(const Options& o)
    {
        const bool t3 = o.caseName == "table3";
        ForceModels m;
        if (o.on("lubrication"))
        {
            Lubrication::Params lub;
            lub.epsilon = 1e-3;
            lub.deltaLub = t3 ? 0.25 : 0.05;
            m.set(Lubrication(lub));
        }
        if (o.on("contact"))
        {
            FrictionalContact::Params c =
                FrictionalContact::fromGroups(4e5, 2.0/7.0, 1e-7, o.friction);
            if (t3 && o.on("rolling"))
            {
                c.kr = 0.1*c.kn;
                c.muR = o.rollingFriction;
            }
            if (o.contactModel == CriticalLoadContact::typeName)
            {
                m.set(CriticalLoadContact({c, o.criticalLoad}));
            }
            else
            {
                m.set(FrictionalContact(c));
            }
        }
        if (t3)
        {
            const ElectroChemicalScales scales({1.0, 19.0, 0.01});
            if (o.on("repulsion"))
            {
                m.set(ElectrostaticRepulsion(scales.repulsion(0.02)));
            }
            if (o.on("attraction"))
            {
                VanDerWaalsAttraction::Params att = scales.attraction();
                att.cutoffGap = o.attractionCutoff;
                m.set(VanDerWaalsAttraction(att));
            }
        }
        return m;
    }

    //- The packing as plain text files (see Usage)
    void writePacking(const std::string& dir, const RandomPacking::Result& packed)
    {
        std::ofstream box(dir + "/box.dat");
        std::ofstream radii(dir + "/radii.dat");
        std::ofstream positions(dir + "/positions.dat");
        box.precision(17);
        radii.precision(17);
        positions.precision(17);
        const Vec3& L = packed.box.L();
        box << L.x() << ' ' << L.y() << ' ' << L.z() << '\n';
        const Particles& p = packed.particles;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            radii << p.a[i] << '\n';
            positions << p.x[i].x() << ' ' << p.x[i].y() << ' ' << p.x[i].z() << '\n';
        }
        if (!box || !radii || !positions)
        {
            std::cerr << "suspensionBenchmark: cannot write the packing to " << dir << "\n";
            std::exit(1);
        }
    }

    //- STREAM-like bandwidths of this machine on the current threads, GB/s
    struct Bandwidth
    {
        double triad;       // a = b + s c: 24 bytes an entry
        double read;        // sum of b: 8 bytes an entry
    };

    Bandwidth bandwidth()
    {
        const std::size_t n = std::size_t(1) << 24;
        const int repeats = 10;
        std::vector<double> a(n), b(n), c(n);
        #pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < n; ++i)
        {
            a[i] = 0;
            b[i] = 1;
            c[i] = 2;
        }
        const double tTriad = bestTime(repeats, [&]()
        {
            #pragma omp parallel for schedule(static)
            for (std::size_t i = 0; i < n; ++i)
            {
                a[i] = b[i] + 3*c[i];
            }
        });
        // Eight entries a step into the sum, so that the latency of its
        // adds does not bound the loop
        double total = 0;
        const double tRead = bestTime(repeats, [&]()
        {
            double sum = 0;
            #pragma omp parallel for schedule(static) reduction(+:sum)
            for (std::size_t i = 0; i < n; i += 8)
            {
                double s[8];
                for (int k = 0; k < 8; ++k)
                {
                    s[k] = b[i + k];
                }
                sum += ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
            }
            total += sum;
        });
        if (total != repeats*double(n) || a[n - 1] != 7)
        {
            std::cerr << "suspensionBenchmark: the bandwidth loops computed wrong sums\n";
            std::exit(1);
        }
        return {24e-9*n/tTriad, 8e-9*n/tRead};
    }

    //- The -roofline row (Description) of the operator of sim
    void roofline(const Options& o, const Simulation& sim)
    {
        using Resistance = HydrodynamicResistance;
        const Resistance& R = sim.implicit()->resistance();
        const std::size_t N = sim.particles().size();
        const double entries = 2.0*R.nPairs()/N;       // row entries of
        const double contacts = 2.0*R.nContacts()/N;   // each kind
        const double vector = 6*sizeof(double);

        // The operator's data per particle: the product's (the drag and
        // M/dt, the self block, the row offsets, the row entries), then
        // the preconditioner's inverse block
        const double productOperator =
            2*sizeof(double) + sizeof(Resistance::SelfBlock) + 2*sizeof(std::uint32_t)
          + entries*(sizeof(Resistance::Coupling) + sizeof(std::uint32_t))
          + contacts*(sizeof(Resistance::Contact) + 2*sizeof(std::uint32_t));
        const double iterationOperator = productOperator + 21*sizeof(float);

        // Vectors per particle: the product reads x and writes y; an
        // iteration adds p.Ap (p, Ap), the fused pass (x, r in and out, z
        // out, p, Ap in) and the direction (z in, p in and out)
        const double productVectors = 3*vector;
        const double iterationVectors = productVectors + 2*vector + 8*vector + 3*vector;
        const double gather = (entries + contacts)*vector;
        const double productFlops = 78 + 67*entries + 60*contacts;
        const double iterationFlops = productFlops + 150;

        const Eigen::VectorXd x = Eigen::VectorXd::Random(6*N);
        Eigen::VectorXd y;
        const double tProduct = bestTime(21, [&]() { R.apply(x, y); });
        auto solve = [&](std::size_t iterations)
        {
            ConjugateGradient cg({1e-300, iterations});
            return bestTime(5, [&]()
            {
                Eigen::VectorXd v = Eigen::VectorXd::Zero(6*N);
                const ConjugateGradient::Result r = cg.solve(R, x, v);
                if (r.iterations != iterations)
                {
                    std::cerr << "suspensionBenchmark: the CG stopped after "
                        << r.iterations << " of " << iterations << " iterations\n";
                    std::exit(1);
                }
            });
        };
        const double tIteration = (solve(30) - solve(10))/20;

        const Bandwidth bw = bandwidth();
        const double ns = 1e9/N;
        std::printf
        (
            "%s,%s,%zu,%d,%.3f,%.3f,%.1f,%.1f,"
            "%.2f,%.0f,%.0f,%.0f,%.0f,%.2f,%.0f,%.0f,%.0f,%.2f,%.2f,%.2f,%.2f\n",
            o.caseName.c_str(), o.integratorName.c_str(), N, omp_get_max_threads(),
            entries, contacts, 1e-6*N*iterationOperator, 1e-6*N*5*vector,
            tProduct*ns, productOperator, productVectors, gather, productFlops,
            tIteration*ns, iterationOperator, iterationVectors, iterationFlops,
            (productOperator + productVectors)/(tProduct*ns),
            (iterationOperator + iterationVectors)/(tIteration*ns),
            bw.triad, bw.read
        );
    }

    std::string joined(const std::vector<std::string>& names)
    {
        std::string s;
        for (const std::string& n : names)
        {
            s += (s.empty() ? "" : "+") + n;
        }
        return s.empty() ? "none" : s;
    }
}


int main(int argc, char** argv)
{
    suspension::useSystemForLargeArrays();
    const Options o = parse(argc, argv);
    const bool t3 = o.caseName == "table3";
    const double rho = 1e-3;

    if (o.header && o.roofline)
    {
        std::cout
            << "case,integrator,N,threads,entries_per_particle,contact_entries_per_particle,"
               "operator_MB,vectors_MB,product_ns,product_operator_bytes,"
               "product_vector_bytes,gather_bytes,product_flops,iteration_ns,"
               "iteration_operator_bytes,iteration_vector_bytes,iteration_flops,"
               "product_GBs,iteration_GBs,triad_GBs,read_GBs\n";
        return 0;
    }
    if (o.roofline && o.integrator == Integrator::velocityVerlet)
    {
        std::cerr << "suspensionBenchmark: -roofline needs an implicit integrator\n";
        return 2;
    }
    if (o.header)
    {
        std::cout
            << "case,integrator,N,threads,phi,attractionCutoff,pairs_per_particle,"
               "contacts_per_particle,build_half_ms,build_full_ms,build_brute_ms,"
               "step_ms,ns_per_particle_step,dt,dt_limit,list_bytes_per_particle,"
               "paper_NxM_bytes_per_particle,pack_s,peak_rss_MB,s_per_strain,cg_iterations,"
               "steps,rebuilds,off,gap,flow_ns,pairs_ns,particle_ns,search_ns,"
               "hydrodynamics_ns,integration_ns,preshear\n";
        return 0;
    }

    // Initial configuration
    const SizeDistribution dist = t3
        ? SizeDistribution::bidisperse(1.0, 3.0, 0.25)
        : SizeDistribution::bidisperse(1.0, 1.4, 1.0);
    const std::vector<double> radii = dist.radii(o.N);
    const ForceModels forceModels = models(o);
    RandomPacking::Params pp;
    pp.phi = o.phi;
    pp.seed = o.seed;
    pp.reach = forceModels.interactionGap() + Simulation::Params().skin;
    const auto tp = Clock::now();
    RandomPacking::Result packed = RandomPacking(pp).pack(radii, rho);
    const double packSeconds = seconds(tp, Clock::now());
    if (!o.packingDir.empty())
    {
        writePacking(o.packingDir, packed);
    }

    const ShearFlow flow(1.0);
    LeesEdwardsBox box(packed.box.L(), 1.0);
    Simulation::Params sp;
    sp.rho = rho;
    sp.integrator = o.integrator;
    sp.safety = o.safety;
    if (o.genericPasses)
    {
        sp.pairPasses = ForceField::PairPasses::generic;
    }
    Simulation::Checkpoint sheared;
    if (o.preshear > 0)
    {
        Simulation::Params implicitParams = sp;
        implicitParams.integrator = Integrator::implicitEuler;
        Simulation shearing
        (
            std::move(packed.particles), box, flow, forceModels, implicitParams
        );
        shearing.start(0);
        shearing.advance(o.preshear/flow.meanShearRate(0, 1));
        shearing.checkpoint(sheared);
    }
    Simulation sim
    (
        o.preshear > 0 ? sheared.particles : std::move(packed.particles),
        box, flow, forceModels, sp
    );
    if (o.preshear > 0)
    {
        // Its positions fit the box's offset at that strain only
        sim.restore(sheared);
        sheared = Simulation::Checkpoint();
    }
    else
    {
        sim.start(0);
    }
    const double dt = sim.deltaT();
    for (int s = 0; s < 5; ++s)
    {
        sim.step(dt);
    }

    // Full steps, with the time of each kernel
    sim.resetKernelTimes();
    std::vector<double> stepTimes;
    double cgIterations = 0;
    const std::size_t buildsBefore = sim.search().statistics().builds;
    for (int s = 0; s < o.steps; ++s)
    {
        const auto t0 = Clock::now();
        sim.step(dt);
        stepTimes.push_back(seconds(t0, Clock::now()));
        if (sim.implicit())
        {
            cgIterations += double(sim.implicit()->statistics().iterations)/o.steps;
        }
    }
    if (o.roofline)
    {
        roofline(o, sim);
        return 0;
    }
    const std::size_t rebuilds = sim.search().statistics().builds - buildsBefore;
    std::sort(stepTimes.begin(), stepTimes.end());
    // (the median step excludes the rare rebuild steps: see `rebuilds`)
    const double tStep = stepTimes[stepTimes.size()/2];

    // Peak memory of the packing and the simulation, before the copies
    // that the rebuild timings below make
    const double simulationRSS = peakRSSMB();

    // Neighbour-search rebuilds: sort, find pairs, carry history
    auto buildTime = [&](Stencil stencil)
    {
        Particles p = sim.particles();
        PairList list = sim.pairs();
        NeighbourSearch::Params sp = sim.search().params();
        sp.stencil = stencil;
        NeighbourSearch search(sp);
        return medianTime(stencil == Stencil::bruteForce ? 1 : 5, [&]()
        {
            search.rebuild(p, sim.box(), list);
        });
    };
    const double tHalf = buildTime(Stencil::half);
    const double tFull = buildTime(Stencil::full);
    const double tBrute = o.brute ? buildTime(Stencil::bruteForce) : NAN;


    // Memory: the list with history, and the paper's N x M table where M
    // is the number of smallest spheres in a shell 2 a0 thick around the
    // largest, each entry a partner index and a stretch (4 + 48 bytes)
    const std::size_t N = sim.particles().size();
    const double aMin = radii.front();
    const double aMax = radii.back();
    const double M = std::ceil
    (
        (std::pow(aMax + 2, 3) - std::pow(aMax, 3))/std::pow(aMin, 3)
    );
    const double listBytes =
        double(sim.pairs().bytes() + sim.search().bytes())/N;

    std::printf
    (
        "%s,%s,%zu,%d,%.4f,%g,%.3f,%.3f,%.3f,%.3f,%.3f,%.4f,%.1f,%.4g,%s,%.1f,%.1f,%.2f,%.1f,%.4g,%g,%d,%zu",
        o.caseName.c_str(), o.integratorName.c_str(), N, omp_get_max_threads(),
        solidVolume(radii)/sim.box().volume(), t3 ? o.attractionCutoff : 0.0,
        double(sim.pairs().nPairs())/N,
        double(sim.summary().nContacts)/N,
        1e3*tHalf, 1e3*tFull, 1e3*tBrute,
        1e3*tStep, 1e9*tStep/N, dt, sim.limits().binding().name.c_str(),
        listBytes, M*(4 + sizeof(ContactState)), packSeconds, simulationRSS,
        tStep/dt, cgIterations, o.steps, rebuilds
    );
    const KernelTimes k = sim.kernelTimes();
    const double perParticleStep = 1e9/(double(N)*o.steps);
    std::printf
    (
        ",%s,%.4g,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%g\n",
        joined(o.off).c_str(), sim.search().params().gap,
        k.flowSampling*perParticleStep, k.pairLoop*perParticleStep,
        k.particleTerms*perParticleStep, k.search*perParticleStep,
        k.hydrodynamics*perParticleStep, k.integration*perParticleStep,
        o.preshear
    );
    return 0;
}
