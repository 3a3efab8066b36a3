// Engine driver of the linear-solve measurements (docs/performance.md,
// "The linear solve"): Table 1 FR, N spheres (1 : 1.4, equal volumes),
// phi 0.5, mu_C = 1 (MU), k_hat = 4e5, kt/kn = 2/7, gamma_n/kn = 1e-7,
// eps = 1e-3, delta = 0.05 (DELTA), St = 1e-3; runs warmupStrain, then
// measureStrain in outputs of interval, and prints the CPU seconds, the
// steps, the CG iterations per step and the mean eta_r of the window.
// DT: fixed step; TOL: CG tolerance; NORMAL=implicit or explicit: the
// normal contact springs (integration/normalContact). With alternatives.patch applied to
// the engine, PRECOND=ic or ldlt selects the preconditioner or the direct
// solve (the patch is against commit 147477c).
//   g++ -O3 -DNDEBUG -fopenmp -std=c++17 -I src/suspension -I /usr/include/eigen3 \
//       frDriver.C -L <build>/lib -lsuspension -o frDriver
// usage: frDriver integrator warmupStrain measureStrain [N] [interval]
#include "dynamics/Simulation.H"
#include "flow/ShearFlow.H"
#include "packing/RandomPacking.H"
#include "packing/SizeDistribution.H"
#include <sys/resource.h>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <cmath>
#include <algorithm>
using namespace suspension;
static double cpu()
{
    rusage u; getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + 1e-6*u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6*u.ru_stime.tv_usec;
}
int main(int argc, char** argv)
{
    const std::string integ = argv[1];
    const double warm = std::atof(argv[2]); double meas = std::atof(argv[3]);
    const std::size_t N = argc > 4 ? std::atoi(argv[4]) : 200;
    const double interval = argc > 5 ? std::atof(argv[5]) : 0.01;
    const double rho = 1e-3;
    ForceModels m;
    Lubrication::Params lub; lub.epsilon = 1e-3; lub.deltaLub = 0.05;
    m.set(Lubrication(lub));
    m.set(FrictionalContact(FrictionalContact::fromGroups(4e5, 2.0/7.0, 1e-7, std::getenv("MU") ? std::atof(std::getenv("MU")) : 1.0)));
    RandomPacking::Params pp; pp.phi = 0.5; pp.seed = 1;
    pp.reach = m.interactionGap() + Simulation::Params().skin;
    if (std::getenv("DELTA")) { lub.deltaLub = std::atof(std::getenv("DELTA")); m.set(Lubrication(lub)); pp.reach = m.interactionGap() + Simulation::Params().skin; }
    RandomPacking::Result packed = RandomPacking(pp).pack(SizeDistribution::bidisperse(1.0, 1.4, 1.0).radii(N), rho);
    const ShearFlow flow(1.0);
    Simulation::Params sp; sp.rho = rho;
    sp.integrator = integ == "overdamped" ? Integrator::overdamped
        : integ == "implicitEuler" ? Integrator::implicitEuler : Integrator::velocityVerlet;
    if (std::getenv("DT")) { sp.deltaT = std::atof(std::getenv("DT")); }
    if (std::getenv("TOL")) { sp.solver.tolerance = std::atof(std::getenv("TOL")); }
    if (std::getenv("NORMAL")) { sp.implicitNormalContact = std::string(std::getenv("NORMAL")) == "implicit"; }
    Simulation sim(std::move(packed.particles), LeesEdwardsBox(packed.box.L(), 1.0), flow, m, sp);
    sim.start(0);
    std::printf("deltaT %.4g binding %s %.4g\n", sim.deltaT(), sim.limits().binding().name.c_str(), sim.limits().binding().value);
    for (double t = 0; t < warm - 1e-12; t += interval) sim.advance(interval);
    const std::uint64_t it0 = sim.implicit()->iterations();
    const std::uint64_t s0 = sim.steps();
    double cgSample = 0, etaR = 0, maxOv = 0; int samples = 0;
    const double c0 = cpu();
    for (double t = 0; t < meas - 1e-12; t += interval)
    {
        sim.advance(interval);
        cgSample += sim.implicit() ? sim.implicit()->statistics().iterations : 0;
        etaR += sim.rheology().etaR; maxOv = std::max(maxOv, sim.summary().maxOverlap); ++samples;
    }
    const double c1 = cpu();
    const std::uint64_t steps = sim.steps() - s0;
    std::printf("integrator %s N %zu strain %.3g steps %llu mean_dt %.4g cpu_s %.3f cpu_s_per_strain %.3f\n",
        integ.c_str(), N, meas, (unsigned long long)steps, meas/steps, c1 - c0, (c1 - c0)/meas);
    std::printf("cg_its_mean(before: every step; after: last step of each interval) %.1f", cgSample/samples);
    std::printf(" cg_its_per_step %.1f", double(sim.implicit()->iterations() - it0)/steps);
    for (const auto& c : sim.stepLimitCounts()) std::printf(" %s:%llu", c.name.c_str(), (unsigned long long)c.steps);
    std::printf("\nmean_etaR %.4f max_overlap %.4g contacts %zu\n", etaR/samples, maxOv, sim.summary().nContacts);

}
