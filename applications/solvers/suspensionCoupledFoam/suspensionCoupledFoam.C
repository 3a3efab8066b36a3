/*---------------------------------------------------------------------------*\
Application
    suspensionCoupledFoam

Group
    grpLagrangianSolvers

Description
    Two-way coupled dense suspension: the particles of wavyShearFoam
    (Monti, Rathee, Shen & Rosti 2021) in a mean flow that answers their
    stress. The mean flow obeys the mixture momentum balance of Stokes flow

        0 = -grad p + eta0 lap U + div Sigma_p + f,    div U = 0,

    with Sigma_p the coarse-grained particle stress (every stresslet of
    eq. 8: Stokes, lubrication, contact, electro-chemical) and f a body
    force (bodyForce: none, kolmogorov). In the Lees-Edwards box
    U = gammaDot y e_x + u', u' periodic.

    The problem solved is one-dimensional: Sigma_p is averaged over the
    planes of constant y before it acts, so u' = u'(y), which a mesh cyclic
    in x, y and z carries exactly under the Lees-Edwards shift (a shift in
    x maps a u' independent of x onto itself). Then div U = 0 holds with
    u'_y = 0, the pressure balances the y component of the source
    (p = <Sigma_p,yy>), and the x and z components solve

        eta0 d2u'/dy2 = -d<Sigma_p,xy>/dy - f_x    (and z),

    with fvm::laplacian and fvc::div (system/fvSchemes, solver Uprime of
    system/fvSolution), the mean of u' set to zero (the periodic problem
    fixes u' up to a constant; the mean of the source is removed, so the
    singular system is consistent).

    Each outer step (the OpenFOAM deltaT):
      1. the particles advance in the flow of the last step
         (suspensionCloud::evolve);
      2. their stresslets and volumes are spread onto the mesh
         (coarseGraining: sigmaP, alphaP; conservative);
      3. the stress that acts relaxes towards the instantaneous one over
         the coupling strain gammaDot tau (the particle stress is noisy):
         sigmaPRelaxed += (1 - exp(-deltaT/tau)) (sigmaP - sigmaPRelaxed);
         only its variation across the box acts, and its mean is set to the
         instantaneous mean (the bulk particle stress of eq. 8), so that the
         profiles' total stress is the bulk one, not one that lags;
      4. u' is solved (feedback off: from f alone, the particle-free
         fluid);
      5. the particles' flow (ambientFlow meshField on Uprime) takes u'
         and the engine continues in it (suspensionCloud::correctFlow).
    The log reports, each step, how much u' changed, the budget of the
    balance (the largest viscous, particle and body forces over the cells
    and the residual of the discrete balance relative to its source), how well the spread stress is conserved and
    the mean particle shear stress; at the end, the wall seconds of the
    particles' steps and of the mesh side (the coarse-graining, with the
    per-particle stresslets it needs: one more force evaluation; the
    solve; the flow update, in which the engine continues in the new flow
    as a restart would: a re-sort, a list rebuild and a force evaluation).

    Start: Uprime and sigmaPRelaxed stored at the start time (written with
    every state, inside its commit: a restart continues bitwise), or, if
    the time holds neither (a new packing, a state of wavyShearFoam),
    sigmaPRelaxed is uniform, the mean particle stress at the start (which
    does not act: its divergence is zero), and u' that of the force alone.
    Starting from the instantaneous profile instead would impose its noise
    at once (for N = 500 in 16 rows, shear rates of 10 gammaDot), before
    the relaxation can average it.

    Stability: the flow answers a stress the particles built in the flow
    before it. With the particle stress following the local rate at once,
    Sigma_p = (etaR - 1) eta0 gammaDot_local, the relaxed stress evolves
    as Sigma <- Sigma (1 - r etaR) + ..., r = 1 - exp(-deltaT/tau): stable
    for r < 2/etaR. Without the relaxation (r = 1) a suspension with
    etaR > 2 would diverge; deltaT = 0.01 and tau = 1 allow etaR < 200.

    Set-up: constant/suspensionProperties as for wavyShearFoam, with
    ambientFlow type meshField on the field Uprime; constant/
    couplingProperties (below); a mesh of blockMesh with one block and
    three cyclic pairs spanning the particle box.

Usage
    constant/couplingProperties:
    \verbatim
    feedback        on;     // the particle stress acts on the flow
    couplingStrain  1;      // gammaDot tau of the relaxation, > 0
    coarseGraining
    {
        width       4;      // kernel width [a0], >= 2 a_max
    }
    bodyForce
    {
        type        kolmogorov;     // none | kolmogorov
        amplitude   0.1;            // F [eta0 gammaDot/a0]
        periods     1;              // n
    }
    \endverbatim

    Output: that of wavyShearFoam, and the function object
    suspensionCoupling (U, u', Sigma_p instantaneous and relaxed, the
    plane-averaged total shear stress and phi across y; the amplitude of
    u' and the effective viscosity against strain).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "suspensionCloud.H"
#include "core/Memory.H"
#include "meshField.H"
#include "bodyForce.H"
#include "coarseGraining.H"
#include "inputChecks.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"

#include <chrono>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Every patch of the mesh cyclic (or, decomposed, between processors),
//  with a cyclic pair across each direction (on some processor): else a
//  FatalIOError naming the boundary file and the patch
void checkPeriodic(const fvMesh& mesh)
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const fileName file = patches.objectPath();
    bool across[3] = {false, false, false};
    for (const polyPatch& pp : patches)
    {
        const bool periodic =
            isA<cyclicPolyPatch>(pp) || isA<processorCyclicPolyPatch>(pp);
        if (!periodic && !isA<processorPolyPatch>(pp))
        {
            FatalIOErrorInFunction(file)
                << "Patch '" << pp.name() << "' of " << file << " is of type "
                << pp.type() << ": suspensionCoupledFoam solves u' periodic"
                << " in the Lees-Edwards box, on a mesh whose faces are three"
                << " cyclic pairs (blockMeshDict of tutorials/coupled/"
                << "kolmogorov)" << nl << exit(FatalIOError);
        }
        if (periodic && pp.size())
        {
            const vector n = cmptMag(pp.faceAreas()[0]/mag(pp.faceAreas()[0]));
            for (direction d = 0; d < 3; ++d)
            {
                across[d] = across[d] || n[d] > 1 - 1e-6;
            }
        }
    }
    for (direction d = 0; d < 3; ++d)
    {
        if (!returnReduce(across[d], orOp<bool>()))
        {
            FatalIOErrorInFunction(file)
                << "The mesh of " << file << " has no cyclic pair across"
                << " direction " << label(d) << ": suspensionCoupledFoam"
                << " needs the box periodic in x, y and z" << nl
                << exit(FatalIOError);
        }
    }
}


//- Whether the start time holds the flow's state: both fields, or neither
//  (on every processor)
bool storedFlow(IOobject& U, IOobject& sigma)
{
    const bool hasU = U.typeHeaderOk<volVectorField>(true);
    const bool hasSigma = sigma.typeHeaderOk<volSymmTensorField>(true);

    // Decomposed: each processor reads its own time, and all must agree
    // (the flow is solved anew collectively, or not at all)
    const IOobject* fields[2] = {&U, &sigma};
    const bool here[2] = {hasU, hasSigma};
    for (label k = 0; k < 2; ++k)
    {
        if
        (
            returnReduce(here[k], orOp<bool>())
         != returnReduce(here[k], andOp<bool>())
        )
        {
            FatalIOErrorInFunction(fields[k]->objectPath())
                << "The start time holds " << fields[k]->name() << " on some"
                << " processors only (" << fields[k]->objectPath()
                << (here[k] ? " is there" : " is not") << "): decompose the"
                << " time again" << nl << exit(FatalIOError);
        }
    }

    if (hasU != hasSigma)
    {
        const IOobject& missing = hasU ? sigma : U;
        FatalIOErrorInFunction(missing.objectPath())
            << "The start time holds " << (hasU ? U : sigma).name()
            << " but not " << missing.objectPath() << ": the coupled flow's"
            << " state is both. Remove the other to solve the flow anew from"
            << " the particles" << nl << exit(FatalIOError);
    }
    return hasU;
}


//- The particles' flow must be the solved one, ambientFlow meshField (on
//  another field than U it would have stopped already: the mesh holds
//  no other), at an imposed rate
void checkFlow(const suspensionCloud& particles, const volVectorField& U)
{
    if (!isA<meshField>(particles.flow()))
    {
        FatalIOErrorInFunction(particles.properties().ambientFlowDict())
            << "suspensionCoupledFoam solves the ambient flow: the entry"
            << " 'type' of ambientFlow must be " << meshField::typeName
            << " with field " << U.name() << ", not "
            << particles.flow().type() << nl << exit(FatalIOError);
    }
    if (particles.flow().stressControlled())
    {
        FatalIOErrorInFunction(particles.properties().ambientFlowDict())
            << "suspensionCoupledFoam takes the mean shear rate (entry"
            << " 'shearRate', any Function1 of time), not stress control"
            << " (entry 'shearStress'): the perturbation's balance is"
            << " solved about an imposed mean shear" << nl
            << exit(FatalIOError);
    }
}


//- The particles' stresslets and volumes spread onto the mesh (each
//  processor's owned particles); the relative difference of the field's
//  integral from their sum
scalar coarseGrain
(
    const suspensionCloud& particles,
    const coarseGraining& kernel,
    volSymmTensorField& sigmaP,
    volScalarField& alphaP
)
{
    const suspension::Simulation& sim = particles.simulation();
    const suspension::Particles& p = sim.particles();
    const std::vector<suspension::Mat3>& S = particles.particleStresslets();
    DynamicList<point> x(label(p.size()));
    DynamicList<symmTensor> Q(x.capacity());
    DynamicList<scalar> V(x.capacity());
    symmTensor total(Zero);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (!p.isGhost(i))
        {
            x.append(toFoam(p.x[i]));
            Q.append(symm(toFoam(S[i])));
            V.append(sphereVolume(p.a[i]));
            total += Q.last();
        }
    }
    reduce(total, sumOp<symmTensor>());
    kernel.spread(x, Q, sim.box().offset(), sigmaP);
    kernel.spread(x, V, sim.box().offset(), alphaP);
    return
        mag(fvc::domainIntegrate(sigmaP).value() - total)
       /max(mag(total), VSMALL);
}


//- Wall seconds of the parts of the outer steps
struct stepTimes
{
    using clock = std::chrono::steady_clock;

    double particles = 0;
    double coarseGraining = 0;
    double solve = 0;
    double flowUpdate = 0;
    clock::time_point last = clock::now();

    //- Add the seconds since the last call to t
    void add(double& t)
    {
        const clock::time_point now = clock::now();
        t += std::chrono::duration<double>(now - last).count();
        last = now;
    }

    void report() const
    {
        const double mesh = coarseGraining + solve + flowUpdate;
        const double total = particles + mesh;
        Info<< "Coupling: wall seconds of the outer steps " << total
            << ": particles " << particles << ", mesh side " << mesh << " ("
            << label(1000*mesh/max(total, VSMALL) + 0.5)/10.0 << " %:"
            << " coarse-graining " << coarseGraining << ", solve " << solve
            << ", flow update (the engine continuing in the new flow) "
            << flowUpdate << ")" << nl << endl;
    }
};


//- The volume-weighted mean of a field over the mesh
template<class Type>
dimensioned<Type> mean(const GeometricField<Type, fvPatchField, volMesh>& f)
{
    return
        fvc::domainIntegrate(f)
       /dimensionedScalar("V", dimVolume, gSum(f.mesh().V()));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    suspension::useSystemForLargeArrays();
    argList::addNote
    (
        "Dense suspension of rigid spheres in a mean flow that answers the"
        " particle stress (two-way coupled Stokes mixture)"
    );
    #include "setRootCase.H"

    // An incomplete latest time (a write stopped by a kill or a crash) is
    // set aside, so that the run starts from the latest complete time
    suspensionIO::selectStartTime(args);

    #include "createTime.H"
    #include "createMesh.H"

    checkPeriodic(mesh);

    #include "createFields.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    scalar conservation = coarseGrain(particles, kernel, sigmaP, alphaP);
    if (!flowStored)
    {
        sigmaPRelaxed = mean(sigmaP);
        sigmaPRelaxed.correctBoundaryConditions();
        #include "UEqn.H"
    }
    particles.correctFlow();

    Info<< "\nStarting time loop\n" << endl;

    stepTimes times;
    while (runTime.run())
    {
        ++runTime;

        times.last = stepTimes::clock::now();
        particles.evolve();
        times.add(times.particles);

        conservation = coarseGrain(particles, kernel, sigmaP, alphaP);
        sigmaPRelaxed +=
            (1 - std::exp(-runTime.deltaTValue()/couplingStrain))
           *(sigmaP - sigmaPRelaxed);
        sigmaPRelaxed += mean(sigmaP) - mean(sigmaPRelaxed);
        sigmaPRelaxed.correctBoundaryConditions();
        times.add(times.coarseGraining);

        #include "UEqn.H"
        times.add(times.solve);

        particles.correctFlow();
        times.add(times.flowUpdate);

        runTime.write();
    }
    particles.writeLastState();

    times.report();
    particles.reportKernelTimes();
    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
