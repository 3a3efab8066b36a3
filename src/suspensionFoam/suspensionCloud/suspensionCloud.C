#include "suspensionCloud.H"
#include "inputChecks.H"
#include "boundBox.H"
#include "IOdictionary.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "core/Memory.H"
#include "core/Parallel.H"

#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <unordered_map>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(suspensionCloud, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Seconds as h:mm:ss
std::string clockTime(const double seconds)
{
    const long s = std::lround(seconds);
    char buf[32];
    std::snprintf
    (
        buf, sizeof(buf), "%ld:%02ld:%02ld", s/3600, (s/60) % 60, s % 60
    );
    return buf;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::suspensionCloud::startsFromStored(const Time& runTime)
{
    const dictionary& control = runTime.controlDict();
    if (!(runTime.deltaTValue() > 0))
    {
        FatalIOErrorInFunction(control)
            << "Entry 'deltaT' = " << runTime.deltaTValue() << " in "
            << control.name() << " must be positive: it is the"
            << " sampling interval, within which the engine takes its own"
            << " steps (integration/deltaT)" << nl << exit(FatalIOError);
    }
    if
    (
        control.getOrDefault<word>("stopAt", "endTime") == "endTime"
     && runTime.endTime().value() < runTime.value()
    )
    {
        FatalIOErrorInFunction(control)
            << "Entry 'endTime' = " << runTime.endTime().value() << " in "
            << control.name() << " is before the start time "
            << runTime.timeName() << ": nothing would run. Raise endTime to"
            << " continue the run" << nl << exit(FatalIOError);
    }

    const suspensionIO::stored s = suspensionIO::check(runTime.timePath());

    // A parallel run starts alike on every process: from the suspension
    // every processor holds complete, or from a new packing if none holds
    // any part of one
    const bool incomplete = s.state == suspensionIO::stored::incomplete;
    const bool complete = s.state == suspensionIO::stored::complete;
    if (returnReduce(incomplete, orOp<bool>()) && !incomplete)
    {
        FatalErrorInFunction
            << "The start time " << runTime.timeName() << " is incomplete on"
            << " another processor (its log says why); startFrom latestTime"
            << " starts from the latest time complete on all" << nl
            << exit(FatalError);
    }
    if (!incomplete && returnReduce(complete, orOp<bool>()) != complete)
    {
        FatalErrorInFunction
            << "The start time " << runTime.timeName() << " holds a"
            << " suspension on some processors only (this one: "
            << (complete ? "complete" : "none") << "): decompose a complete"
            << " time of the whole case again (decomposePar)" << nl
            << exit(FatalError);
    }
    if (incomplete)
    {
        const fileName stateFile =
            runTime.timePath()/"uniform"/suspensionIO::stateName;
        FatalIOErrorInFunction(stateFile)
            << "The start time " << runTime.timeName() << " holds an"
            << " incomplete suspension: " << s.reason.c_str() << nl
            << "    With startFrom latestTime, wavyShearFoam sets incomplete"
            << " latest times aside and starts from the latest complete one."
            << " Files edited on purpose (a state made by hand): remove the"
            << " entry 'files' (their digests) from " << stateFile << ". To"
            << " pack anew: remove " << runTime.timePath()/"lagrangian"
            << " and " << runTime.timePath()/"uniform" << nl
            << exit(FatalIOError);
    }
    // decomposePar and reconstructPar write the cloud as the case writes
    // its fields: in ascii, at writePrecision
    if
    (
        s.copied
     && runTime.writeFormat() == IOstream::ASCII
     && IOstream::defaultPrecision() < 17
    )
    {
        WarningInFunction
            << "The suspension of time " << runTime.timeName() << " was"
            << " written by decomposePar or reconstructPar (" << s.reason.c_str()
            << ") in ascii at writePrecision " << IOstream::defaultPrecision()
            << " of " << control.name() << ": the run continues from its"
            << " state rounded to that many digits, not from the state"
            << " written. Set writePrecision 17 (or writeFormat binary)"
            << " before decomposing or reconstructing" << nl << endl;
    }
    return s.state == suspensionIO::stored::complete;
}


Foam::suspensionIO::state Foam::suspensionCloud::initialState() const
{
    if (restart_)
    {
        return suspensionIO::readState(runTime_);
    }

    const suspensionPopulation& population = properties_.population();
    suspensionIO::state s;
    s.time = runTime_.value();
    s.steps = 0;
    s.nParticles = population.nParticles();
    s.nContacts = 0;
    s.box = population.box();
    s.offset = 0;
    s.strain = 0;
    s.shearRate = 0;
    s.file = population.dict().name();
    return s;
}


suspension::Domain::Layout Foam::suspensionCloud::readLayout
(
    const Time& runTime
)
{
    if (!Pstream::parRun())
    {
        return {1, 1};
    }
    const IOdictionary dict
    (
        IOobject
        (
            "decomposeParDict",
            runTime.caseSystem(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    const word method = dict.get<word>("method");
    if (method != "simple" && method != "hierarchical")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'method' = " << method << " in " << dict.name()
            << ": the suspension is decomposed into slabs in y and z, each"
            << " spanning the box in x (Lees-Edwards), as method simple (or"
            << " hierarchical) with n (1 ny nz) cuts the mesh" << nl
            << exit(FatalIOError);
    }
    const word coeffs =
        dict.found("coeffs") ? word("coeffs") : word(method + "Coeffs");
    const dictionary& c = dict.subDict(coeffs);
    const Vector<label> n = c.get<Vector<label>>("n");
    if (n.x() != 1 || n.y() < 1 || n.z() < 1 || n.y()*n.z() != Pstream::nProcs())
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << coeffs << "/n' = " << n << " in " << dict.name()
            << " must be (1 ny nz) with ny nz = " << Pstream::nProcs()
            << ", the number of processes: each slab spans the box in x, so"
            << " that the Lees-Edwards boundary shifts whole slabs" << nl
            << exit(FatalIOError);
    }
    return {int(n.y()), int(n.z())};
}


void Foam::suspensionCloud::checkDecomposition() const
{
    if (!Pstream::parRun())
    {
        return;
    }
    // The bounds of this processor's cells (polyMesh::bounds is global)
    const boundBox bb(mesh_.points(), false);
    const vector& L = start_.box;
    const label q = Pstream::myProcNo();
    const label qy = q % layout_.ny;
    const label qz = q / layout_.ny;
    const boundBox slab
    (
        point(0, qy*L.y()/layout_.ny, qz*L.z()/layout_.nz),
        point(L.x(), (qy + 1)*L.y()/layout_.ny, (qz + 1)*L.z()/layout_.nz)
    );
    const scalar tol = 1e-5*cmptMax(L);
    const bool matches =
        mag(bb.min() - slab.min()) < tol && mag(bb.max() - slab.max()) < tol;
    if (!returnReduce(matches, andOp<bool>()))
    {
        const fileName dictFile = runTime_.path()/runTime_.caseSystem()/"decomposeParDict";
        FatalIOErrorInFunction(dictFile)
            << "The mesh of processor " << q << " spans " << bb << ", not"
            << " its slab " << slab << " of the particle box" << nl
            << "    Decompose with method simple and n (1 " << layout_.ny
            << " " << layout_.nz << ") in " << dictFile << ", on a mesh of"
            << " uniform cells whose number in y is a multiple of "
            << layout_.ny << " and in z of " << layout_.nz << nl
            << exit(FatalIOError);
    }
}


void Foam::suspensionCloud::checkSetup(const scalar aMax) const
{
    const vector& L = start_.box;
    const scalar tol = 1e-5*cmptMax(L);

    // Stress control: an implicit integrator, and a stress to drive the flow
    if (flow_->stressControlled())
    {
        const dictionary& flowDict = properties_.ambientFlowDict();
        if
        (
            properties_.simulationParams().integrator
         == suspension::Integrator::velocityVerlet
        )
        {
            FatalIOErrorInFunction(flowDict)
                << "Stress control (entry 'shearStress' of " << flowDict.name()
                << ") needs an implicit integrator: integration/integrator"
                << " implicitEuler or overdamped, whose velocities and"
                << " stress are affine in the rate, so that the rate of the"
                << " target stress is found exactly each step;"
                << " velocityVerlet has no controller" << nl
                << exit(FatalIOError);
        }
        if (!(flow_->programme().max(runTime_.value(), runTime_.endTime().value()) > 0))
        {
            FatalIOErrorInFunction(flowDict)
                << "Entry 'shearStress' of " << flowDict.name() << " is 0"
                << " over the whole run: no stress drives the flow (a"
                << " negative stress shears the other way)" << nl
                << exit(FatalIOError);
        }
    }

    // A flow the solver selected must know the particle box (its periodic
    // part lives in it)
    if (cmptMax(cmptMag(flow_->box() - L)) > tol)
    {
        FatalErrorInFunction
            << "The ambient flow's box " << flow_->box() << " is not the"
            << " particle box " << L << nl << exit(FatalError);
    }

    if (restart_)
    {
        const suspensionPopulation& population = properties_.population();
        if
        (
            start_.nParticles != population.nParticles()
         || mag(start_.box - population.box()) > tol
        )
        {
            FatalIOErrorInFunction(population.dict())
                << "The suspension stored in " << start_.file << " (N = "
                << start_.nParticles << ", box " << start_.box
                << ") was not made from this population (N = "
                << population.nParticles() << ", box " << population.box()
                << "): restore the population, or remove the stored time"
                << " directories to start a new packing" << nl
                << exit(FatalIOError);
        }

        suspension::LeesEdwardsBox box(toEigen(L), start_.shearRate);
        box.setStrain(start_.strain);
        if (mag(box.offset() - start_.offset) > tol)
        {
            FatalIOErrorInFunction(start_.file)
                << "Entry 'offset' = " << start_.offset << " in "
                << start_.file << " is not the Lees-Edwards offset "
                << box.offset() << " of the strain " << start_.strain
                << " (entry 'strain')" << nl << exit(FatalIOError);
        }
    }

    const boundBox& bb = mesh_.bounds();
    if (mag(bb.min()) > tol || mag(bb.max() - L) > tol)
    {
        FatalIOErrorInFunction(start_.file)
            << "The mesh bounds " << bb << " are not the particle box"
            << " [(0 0 0), " << L << "] of " << start_.file << nl
            << "    Make blockMeshDict span the box (makeSuspension -boxOnly"
            << " writes it to constant/particleBox) and run blockMesh" << nl
            << exit(FatalIOError);
    }

    // The one box rule of the run and the packing
    const suspension::BoxRule rule = properties_.boxRule();
    const string hint =
        "Raise population/nParticles (a radius file: give more radii, or"
        " lower population/volumeFraction), or shorten the interaction ranges"
        " (lubrication/delta, electroChemical repulsion/cutoffDebyeLengths"
        " and attraction/cutoffGap, integration/skin)";
    if (!restart_)
    {
        properties_.population().checkBox(rule, hint);
    }
    else
    {
        try
        {
            rule.check(toEigen(L), aMax);
        }
        catch (const std::invalid_argument& err)
        {
            raiseEngineError(properties_, err, hint);
        }
    }
}


void Foam::suspensionCloud::removeInitialOverlaps
(
    suspension::Particles& particles
) const
{
    try
    {
        const scalar moved =
            properties_.population().removeOverlaps
            (
                particles, start_.box, properties_.boxRule()
            );
        if (moved > 0)
        {
            Info<< "    overlaps     the spheres of " << start_.file
                << " overlapped; separated by FIRE relaxation (largest"
                << " displacement " << moved << " a0); the relaxed"
                << " configuration is written at the first write time" << nl;
        }
    }
    catch (const std::exception& err)
    {
        // PackingError (they jam), or a box too small for the relaxation's
        // neighbour search
        FatalIOErrorInFunction(start_.file)
            << "The spheres stored in " << start_.file << " overlap and"
            << " cannot be separated in their box: " << err.what() << nl
            << "    Start from a packing of makeSuspension (remove the time"
            << " directories), or lower population/volumeFraction"
            << exit(FatalIOError);
    }
}


void Foam::suspensionCloud::start(const scalar t, const bool forcesGiven)
{
    try
    {
        if (forcesGiven)
        {
            sim_->start(t, true, suspension::Simulation::Shear{start_.strain, start_.shearRate});
        }
        else
        {
            sim_->start(t);
        }
        flow_->setShearRate(sim_->shearRate());
    }
    catch (const std::invalid_argument& err)
    {
        raiseEngineError(properties_, err);
    }
    catch (const suspension::SimulationError& err)
    {
        FatalErrorInFunction
            << "The suspension cannot start at time " << runTime_.timeName()
            << ": " << err.what() << nl << exit(FatalError);
    }
}


void Foam::suspensionCloud::writeState() const
{
    suspensionIO::write
    (
        mesh_, *sim_, steps(*sim_), particleStresslets(), particleCells(),
        committed_
    );
    writtenIndex_ = runTime_.timeIndex();
    suspension::returnFreedMemory();

    // A run restarted from this time starts by re-sorting the particles and
    // rebuilding the neighbour list; so does this one before its next step
    written_ = true;
}


void Foam::suspensionCloud::failed(const std::string& cause)
{
    // The last good state, continued from as a restart from it would be
    try
    {
        const suspension::NonStopArithmetic nonStop;
        sim_->restore(lastGood_);
    }
    catch (const std::exception& restoreErr)
    {
        FatalErrorInFunction
            << cause.c_str() << nl
            << "    The last good state (time " << lastGoodTime_
            << ") could not be restored, nothing was written: "
            << restoreErr.what() << nl << exit(FatalError);
    }

    // Written unless this run has it on disk: a time on disk, above all
    // the one the run started from, is never written over (nor one an
    // earlier run left there)
    const bool onDisk = lastGoodIndex_ == writtenIndex_;
    runTime_.setTime(lastGoodTime_, lastGoodIndex_);
    const bool taken =
        !onDisk && returnReduce(exists(runTime_.timePath()), orOp<bool>());
    if (!onDisk && !taken)
    {
        runTime_.writeNow();
    }
    // Every process has written before any stops the run (a FatalError in
    // a parallel run aborts them all)
    returnReduce(true, andOp<bool>());

    FatalErrorInFunction
        << cause.c_str() << nl
        << "    The last good state (time " << runTime_.timeName()
        << ", strain " << sim_->strain() << ", step " << steps(*sim_) << ") "
        << (
               onDisk ? "is on disk, unchanged, in "
             : taken ? "is not written: an earlier run's files hold "
             : "is written to "
           )
        << runTime_.timePath() << nl
        << "    To continue from it, lower integration/deltaT or safety, or"
        << " raise contact/stiffness, and run again" << nl
        << exit(FatalError);

    // FatalError has thrown (throwExceptions) or exited
    std::abort();
}


void Foam::suspensionCloud::failedHere(const std::string& cause)
{
    if (!Pstream::parRun())
    {
        failed(cause);
    }
    // Thrown on this process alone: the others cannot join the collectives
    // of a restore and a write, so every process stops (FatalError aborts
    // them all) with the times on disk as they are
    FatalErrorInFunction
        << cause.c_str() << nl
        << "    This error was raised on processor " << Pstream::myProcNo()
        << " alone, so the processes cannot agree on the last good state:"
        << " it is not written; the times written so far are intact" << nl
        << exit(FatalError);
    std::abort();
}


void Foam::suspensionCloud::reportStart() const
{
    const suspension::Simulation& sim = *sim_;
    const suspension::TimeStepLimits& limits = sim.limits();
    // The radii of the owned particles of every processor (on the master,
    // which reports)
    const suspension::Particles& p = sim.particles();
    List<scalarList> radii(Pstream::nProcs());
    DynamicList<scalar> mine(label(p.size()));
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (!p.isGhost(i))
        {
            mine.append(p.a[i]);
        }
    }
    radii[Pstream::myProcNo()] = std::move(mine);
    Pstream::gatherList(radii);
    std::vector<double> all;
    for (const scalarList& r : radii)
    {
        all.insert(all.end(), r.begin(), r.end());
    }
    const scalar aMax =
        all.empty()
      ? sim.particles().maxRadius()
      : *std::max_element(all.begin(), all.end());
    const scalar R = properties_.boxRule().range(aMax);
    const scalar userDeltaT = properties_.simulationParams().deltaT;

    properties_.report(Info);

    Info<< "    start        ";
    if (restart_)
    {
        Info<< "stored suspension of " << start_.file << " (time "
            << start_.time << ", strain " << start_.strain << ", "
            << start_.steps << " steps, "
            << start_.nContacts << " contacts with history)" << nl;
    }
    else
    {
        Info<< "new random packing, seed "
            << properties_.population().dict().get<label>("seed") << nl;
    }
    Info<< "    radii        "
        << suspension::describeRadii(all).c_str()
        << (restart_ ? " (of the stored cloud)" : "") << nl
        << "    neighbours   cut-off R = 2 a_max + gap + skin = " << R
        << ", box = " << start_.box/R << " R" << nl
        << "    time step    dt = " << sim.deltaT() << " ("
        << (userDeltaT > 0 ? "integration/deltaT" : "auto")
        << "); binding limit " << limits.binding().name.c_str() << " = "
        << limits.binding().value << ", safety " << limits.safety() << nl
        << "    limits      ";
    for (const suspension::TimeStepLimit& l : limits.all())
    {
        Info<< ' ' << l.name.c_str() << ' ' << l.value;
    }
    if (sim.implicit())
    {
        const auto& p = properties_.simulationParams();
        Info<< nl << "    normal contact springs "
            << (sim.implicitNormalContact() ? "implicit" : "explicit")
            << (p.implicitNormalContact ? " (integration/normalContact)" : " (auto)");
    }
    // Simulation::advance: steps of deltaT and a shorter last one
    const scalar interval = runTime_.deltaTValue();
    const label outerSteps = label(sim.stepsIn(interval));
    const scalar lastStep = interval - (outerSteps - 1)*sim.deltaT();
    Info<< nl
        << "    outer step   " << interval;
    if (sim.adaptive())
    {
        Info<< " >= " << outerSteps << " steps";
    }
    else if (outerSteps > 1 && lastStep < sim.deltaT()*(1 - 1e-9))
    {
        Info<< " = " << outerSteps - 1 << " steps of dt and one of "
            << lastStep;
    }
    else
    {
        Info<< " = " << outerSteps << " steps";
    }
    // The threads that run: small systems run on one (core/Parallel.H)
    const label threads = omp_get_max_threads();
    const std::size_t N = sim.particles().size();
    Info<< nl << "    threads      ";
    if (threads > 1 && !suspension::threaded(N))
    {
        Info<< "1 (N = " << label(N)
            << (Pstream::parRun() ? " on the master, ghosts included," : "")
            << " is below the "
            << label(suspension::parallelMinParticles()) << " particles of"
            << " the threaded loops; OMP_NUM_THREADS allows " << threads << ")";
    }
    else if (threads > 1 && sim.params().adaptiveThreads)
    {
        Info<< "1 to " << threads << ", the count that runs fastest"
            << " (integration/threads adaptive; starts on 1)";
    }
    else
    {
        Info<< threads;
    }
    Info<< nl << endl;

    if (userDeltaT > limits.deltaT())
    {
        WarningInFunction
            << "integration/deltaT = " << userDeltaT << " is larger than the"
            << " automatic step " << limits.deltaT() << " (safety "
            << limits.safety() << " x the " << limits.binding().name.c_str()
            << " stability limit " << limits.binding().value << ")"
            << (userDeltaT > limits.binding().value ? ": the run is unstable" : "")
            << nl << endl;
    }
}


namespace
{
    //- The process's peak resident set in MB, as /usr/bin/time -v reports
    //  it (getrusage), 0 if unknown
    double peakResidentMB()
    {
        struct rusage usage;
        return getrusage(RUSAGE_SELF, &usage) == 0 ? usage.ru_maxrss/1024.0 : 0;
    }
}


void Foam::suspensionCloud::reportProgress()
{
    const suspension::Simulation& sim = *sim_;
    const suspension::Rheology r = sim.rheology();
    const scalar etaR = r.etaR;
    etaRSum_ += etaR;
    ++etaRSamples_;

    const clock::time_point now = clock::now();
    const double sinceReport =
        std::chrono::duration<double>(now - reported_).count();
    const bool last =
        runTime_.value()
      > runTime_.endTime().value() - 0.5*runTime_.deltaTValue();
    if (sinceReport < 5 && !last)
    {
        return;
    }

    const double elapsed =
        std::chrono::duration<double>(now - started_).count();
    const scalar done = runTime_.value() - start_.time;
    const scalar toGo = runTime_.endTime().value() - runTime_.value();

    // Whole steps per second, two decimals below 10 (large N: < 1 step/s)
    const scalar rate = (sim.steps() - reportedSteps_)/sinceReport;
    Info<< "strain " << sim.strain();
    if (!flow_->programme().constant() || flow_->stressControlled())
    {
        Info<< "  time " << sim.time() << "  rate " << sim.shearRate()
            << "  sigma " << r.sigma;
    }
    Info<< "  etaR " << etaR << " (mean " << etaRSum_/etaRSamples_ << ")  "
        << (rate < 10 ? std::round(100*rate)/100 : std::round(rate))
        << " steps/s";
    if (const suspension::ImplicitEuler* implicit = sim.implicit())
    {
        Info<< "  CG " << label(implicit->statistics().iterations)
            << " iterations, |r|/|rhs| " << implicit->statistics().residual;
    }
    if (sim.adaptive())
    {
        Info<< "  steps set by";
        reportStepLimits();
    }
    if
    (
        sim.params().adaptiveThreads
     && sim.particles().size() >= suspension::parallelMinParticles()
    )
    {
        Info<< "  threads " << sim.threads();
    }
    Info<< "  CPU " << runTime_.elapsedCpuTime() << " s  peak RSS "
        << label(peakResidentMB() + 0.5) << " MB"
        << "  ETA " << clockTime(max(toGo, 0)*elapsed/done).c_str() << endl;

    reported_ = now;
    reportedSteps_ = sim.steps();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::suspensionCloud::suspensionCloud(Time& runTime, const fvMesh& mesh)
:
    suspensionCloud(runTime, mesh, autoPtr<ambientFlow>())
{}


Foam::suspensionCloud::suspensionCloud
(
    Time& runTime,
    const fvMesh& mesh,
    autoPtr<ambientFlow>&& flow
)
:
    regIOobject
    (
        IOobject
        (
            suspensionIO::cloudName,
            runTime.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        )
    ),
    runTime_(runTime),
    mesh_(mesh),
    properties_(mesh),
    restart_(startsFromStored(runTime)),
    start_(initialState()),
    comm_(),
    layout_(readLayout(runTime)),
    flow_
    (
        flow.valid()
      ? std::move(flow)
      : ambientFlow::New(properties_.ambientFlowDict(), start_.box, &mesh)
    ),
    engineFlow_
    (
        *flow_, min(scalar(0), runTime.value()), runTime.endTime().value()
    ),
    committed_(),
    sim_(),
    lastGood_(),
    lastGoodTime_(runTime.value()),
    lastGoodIndex_(runTime.timeIndex()),
    writtenIndex_(runTime.timeIndex()),
    meanDeltaT_(0),
    written_(false),
    S_(),
    SIndex_(-1),
    started_(clock::now()),
    reported_(started_),
    reportedSteps_(0),
    etaRSum_(0),
    etaRSamples_(0)
{
    const suspensionPopulation& population = properties_.population();
    const scalar rho = properties_.simulationParams().rho;
    const suspension::NonStopArithmetic nonStop;

    // Everything is checked before the (possibly long) packing
    suspension::Particles particles;
    if (restart_)
    {
        particles = suspensionIO::readParticles(mesh_, start_, rho);
        checkSetup(particles.maxRadius());
        // (a decomposed start: the serial run relaxes it, not the slabs)
        if (start_.steps == 0 && start_.nContacts == 0 && !Pstream::parRun())
        {
            removeInitialOverlaps(particles);
        }
    }
    else
    {
        checkSetup(population.radii().back());
        particles = population.pack(rho, properties_.boxRule());
        if (Pstream::parRun())
        {
            // Every process packs the whole population alike and keeps
            // the particles of its slab
            const suspension::Domain domain(comm_, layout_, toEigen(start_.box));
            suspension::Particles mine;
            for (std::size_t i = 0; i < particles.size(); ++i)
            {
                if (domain.owner(particles.x[i]) == Pstream::myProcNo())
                {
                    mine.add(particles.x[i], particles.a[i], rho, particles.id[i]);
                }
            }
            particles = std::move(mine);
        }
    }
    checkDecomposition();

    try
    {
        sim_.emplace
        (
            std::move(particles),
            suspension::LeesEdwardsBox(toEigen(start_.box), flow_->shearRate()),
            engineFlow_,
            properties_.models(),
            properties_.simulationParams(),
            Pstream::parRun()
          ? suspension::Decomposition{&comm_, layout_}
          : suspension::Decomposition{}
        );
    }
    catch (const std::invalid_argument& err)
    {
        raiseEngineError(properties_, err);
    }
    if (restart_)
    {
        try
        {
            sim_->setContacts
            (
                suspensionIO::readContacts(mesh_, start_, sim_->particles())
            );
        }
        catch (const std::invalid_argument& err)
        {
            raiseEngineError(properties_, err);
        }
    }
    start(start_.time, restart_);

    // A start that was never stepped, separated by a serial run only
    if
    (
        Pstream::parRun() && restart_ && start_.steps == 0
     && start_.nContacts == 0 && sim_->summary().maxOverlap > 0
    )
    {
        FatalIOErrorInFunction(start_.file)
            << "The spheres of " << start_.file << " overlap (by up to "
            << sim_->summary().maxOverlap << " of the smaller radius): a"
            << " serial run separates them before its first step; a"
            << " decomposed one does not. Run the serial case to its first"
            << " write time, then decompose that" << nl << exit(FatalIOError);
    }

    reportStart();

    if (!restart_)
    {
        writeState();
    }
    sim_->checkpoint(lastGood_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::suspensionCloud& Foam::suspensionCloud::lookup
(
    const objectRegistry& mesh,
    const word& user
)
{
    const suspensionCloud* cloudPtr =
        mesh.findObject<suspensionCloud>(suspensionIO::cloudName);
    if (!cloudPtr)
    {
        FatalErrorInFunction
            << "Function object " << user << " needs the suspension cloud '"
            << suspensionIO::cloudName << "' of wavyShearFoam, which mesh "
            << mesh.name() << " does not hold: run it with wavyShearFoam or"
            << " suspensionCoupledFoam"
            << nl << exit(FatalError);
    }
    return *cloudPtr;
}


const std::vector<suspension::Mat3>&
Foam::suspensionCloud::particleStresslets() const
{
    if (SIndex_ != runTime_.timeIndex())
    {
        // Evaluating the stresslets changes no state of the engine
        // (Simulation::particleStresslets); the state passed its checks.
        // Asked for at every step (the coupled solver), they keep their
        // per-slot scratch for the next; asked for now and then (writes,
        // function objects), they free it at once
        const bool everyStep = SIndex_ == runTime_.timeIndex() - 1;
        try
        {
            const suspension::NonStopArithmetic nonStop;
            suspension::Simulation& sim = const_cast<suspension::Simulation&>(*sim_);
            sim.particleStresslets(S_);
            if (!everyStep)
            {
                sim.releaseStressletScratch();
            }
        }
        catch (const std::exception& err)
        {
            FatalErrorInFunction
                << "The particle stresslets of time " << runTime_.timeName()
                << " cannot be evaluated: " << err.what() << nl
                << exit(FatalError);
        }
        SIndex_ = runTime_.timeIndex();
    }
    return S_;
}


Foam::labelList Foam::suspensionCloud::particleCells() const
{
    return suspensionIO::findCells(mesh_, sim_->particles());
}


bool Foam::suspensionCloud::newPackingWritten() const
{
    return !restart_ && runTime_.timeIndex() == runTime_.startTimeIndex();
}


void Foam::suspensionCloud::evolve()
{
    // The state (and the order of the particles) changes
    SIndex_ = -1;

    // Whatever the engine throws (its SimulationError, or anything else
    // thrown in a step) ends the run with the last good state on disk
    const std::uint64_t before = sim_->steps();
    try
    {
        const suspension::NonStopArithmetic nonStop;
        if (written_)
        {
            sim_->start(sim_->time(), true, sim_->shear());
            written_ = false;
        }
        sim_->advance(runTime_.deltaTValue());
        // Each particle to the process whose slab (and mesh) holds it now,
        // for the writes and the function objects of this time
        sim_->redistribute();
    }
    catch (const suspension::SimulationError& err)
    {
        failed(err.what());
    }
    catch (const std::exception& err)
    {
        failedHere(err.what());
    }
    flow_->setShearRate(sim_->shearRate());
    meanDeltaT_ = runTime_.deltaTValue()/(sim_->steps() - before);

    sim_->checkpoint(lastGood_);
    lastGoodTime_ = runTime_.value();
    lastGoodIndex_ = runTime_.timeIndex();

    reportProgress();
}


bool Foam::suspensionCloud::correctFlow()
{
    if (!flow_->correct())
    {
        return false;
    }
    // The stresslets of this time stay those of the flow the particles
    // moved in: what the solver spread, the function objects and the write
    // see. The engine continues in the new flow as from a restart, which
    // re-sorts the particles (and, decomposed, makes the ghosts anew): the
    // stresslets follow their owned particles (a ghost's is not kept)
    std::unordered_map<std::int64_t, suspension::Mat3> SOf;
    const bool haveS = SIndex_ == runTime_.timeIndex();
    if (haveS)
    {
        const suspension::Particles& p = sim_->particles();
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            if (!p.isGhost(i))
            {
                SOf.emplace(p.id[i], S_[i]);
            }
        }
    }
    try
    {
        const suspension::NonStopArithmetic nonStop;
        sim_->flowChanged();
    }
    catch (const suspension::SimulationError& err)
    {
        failed(err.what());
    }
    catch (const std::exception& err)
    {
        failedHere(err.what());
    }
    if (haveS)
    {
        const suspension::Particles& p = sim_->particles();
        S_.assign(p.size(), suspension::Mat3::Zero());
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            if (!p.isGhost(i))
            {
                S_[i] = SOf.at(p.id[i]);
            }
        }
    }
    written_ = false;
    sim_->checkpoint(lastGood_);
    return true;
}


void Foam::suspensionCloud::commitWith(const regIOobject& io)
{
    committed_.append(&io);
}


void Foam::suspensionCloud::writeLastState()
{
    if (writtenIndex_ != runTime_.timeIndex())
    {
        Info<< "Writing the last state (time " << runTime_.timeName()
            << ", not a write time)" << nl << endl;
        runTime_.writeNow();
    }
}


bool Foam::suspensionCloud::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
{
    writeState();
    return true;
}


void Foam::suspensionCloud::reportStepLimits() const
{
    const std::vector<suspension::Simulation::StepLimitCount>& counts =
        sim_->stepLimitCounts();
    std::uint64_t total = 0;
    for (const auto& c : counts)
    {
        total += c.steps;
    }
    for (const auto& c : counts)
    {
        Info<< ' ' << c.name.c_str() << ' '
            << label(total ? 100.0*c.steps/total + 0.5 : 0) << '%';
    }
}


void Foam::suspensionCloud::reportKernelTimes() const
{
    const suspension::KernelTimes k = sim_->kernelTimes();
    const scalar total = k.total();
    const scalar particleSteps = scalar(sim_->steps())*sim_->particles().size();
    if (!(total > 0) || !(particleSteps > 0))
    {
        return;
    }
    Info<< "Kernel times (s, share, ns per particle-step):" << nl;
    const std::pair<const char*, double> kernels[] =
    {
        {"flowSampling", k.flowSampling}, {"pairLoop", k.pairLoop},
        {"particleTerms", k.particleTerms}, {"search", k.search},
        {"hydrodynamics", k.hydrodynamics}, {"integration", k.integration}
    };
    for (const auto& kernel : kernels)
    {
        Info<< "    " << kernel.first << ' ' << kernel.second << ' '
            << label(100*kernel.second/total + 0.5) << "% "
            << 1e9*kernel.second/particleSteps << nl;
    }
    Info<< "    total " << total << " s over " << label(sim_->steps())
        << " steps, " << 1e9*total/particleSteps << " ns per particle-step"
        << nl;
    Info<< "Peak resident memory " << peakResidentMB() << " MB" << nl;
    if (sim_->adaptive())
    {
        Info<< "Steps set by (share of the steps):";
        reportStepLimits();
        Info<< nl;
    }
    Info<< endl;
}


// ************************************************************************* //
