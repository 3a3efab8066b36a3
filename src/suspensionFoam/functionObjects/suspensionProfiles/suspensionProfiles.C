#include "suspensionProfiles.H"
#include "suspensionCloud.H"
#include "inputChecks.H"
#include "OFstream.H"
#include "addToRunTimeSelectionTable.H"

#include <limits>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(suspensionProfiles, 0);
    addToRunTimeSelectionTable(functionObject, suspensionProfiles, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::suspensionProfiles::suspensionProfiles
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "profiles"),
    nBins_(1)
{
    read(dict);

    if
    (
        dict.getOrDefault<bool>("writeAtStart", true)
     && suspensionCloud::lookup(mesh_, name).newPackingWritten()
    )
    {
        write();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::suspensionProfiles::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    // Default: bins one reference diameter 2 a0 high
    const scalar Ly = suspensionCloud::lookup(mesh_, name()).flow().box().y();
    nBins_ =
        dict.found("nBins", keyType::LITERAL)
      ? getLabelAtLeast(dict, "nBins", 1)
      : max(label(1), label(Ly/2));

    return true;
}


bool Foam::functionObjects::suspensionProfiles::execute()
{
    return true;
}


bool Foam::functionObjects::suspensionProfiles::write()
{
    const suspensionCloud& cloud = suspensionCloud::lookup(mesh_, name());
    const suspension::Particles& p = cloud.simulation().particles();
    const std::vector<suspension::Mat3>& S = cloud.particleStresslets();
    const ambientFlow& flow = cloud.flow();
    const scalar eta0 = cloud.eta0();

    const vector& L = flow.box();
    const scalar h = L.y()/nBins_;
    const scalar binVolume = L.x()*h*L.z();

    labelList n(nBins_, Zero);
    scalarField volume(nBins_, Zero);
    scalarField Ux(nBins_, Zero);
    scalarField Sxy(nBins_, Zero);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (p.isGhost(i))
        {
            continue;       // another process's (a parallel run)
        }
        const label bin = min(nBins_ - 1, label(p.x[i].y()/h));
        ++n[bin];
        volume[bin] += sphereVolume(p.a[i]);
        Ux[bin] += p.u[i].x();
        Sxy[bin] += 0.5*(S[i](0, 1) + S[i](1, 0));
    }

    // The flow at the bins' centres, from the first processor that knows
    // it (a flow on the mesh is known on each processor's cells; an
    // analytic one on the master)
    const auto centre = [&L, h](const label bin)
    {
        return point(0.5*L.x(), (bin + 0.5)*h, 0.5*L.z());
    };
    List<ambientFlowSample> values(nBins_);
    labelList knownBy(nBins_, Pstream::nProcs());
    forAll(knownBy, bin)
    {
        if (flow.sample(centre(bin), values[bin]))
        {
            knownBy[bin] = Pstream::myProcNo();
        }
    }
    Pstream::listCombineGather(knownBy, minEqOp<label>());
    Pstream::listCombineScatter(knownBy);
    scalarField UinfX(nBins_, Zero);
    scalarField shearRate(nBins_, Zero);
    forAll(knownBy, bin)
    {
        if (knownBy[bin] == Pstream::myProcNo())
        {
            UinfX[bin] = values[bin].U.x();
            shearRate[bin] = values[bin].gradU.yx();
        }
    }

    // The sums over the processes of a parallel run, on the master
    Pstream::listCombineGather(n, plusEqOp<label>());
    Pstream::listCombineGather(volume, plusEqOp<scalar>());
    Pstream::listCombineGather(Ux, plusEqOp<scalar>());
    Pstream::listCombineGather(Sxy, plusEqOp<scalar>());
    Pstream::listCombineGather(UinfX, plusEqOp<scalar>());
    Pstream::listCombineGather(shearRate, plusEqOp<scalar>());

    autoPtr<OFstream> osPtr = createFile("profiles", time_.value());
    if (!osPtr.valid())
    {
        // Not the master, or writeToFile off
        return true;
    }
    OFstream& os = osPtr();
    writeHeader
    (
        os,
        "Profiles across y at time " + time_.timeName()
      + " (fig. 10 of Monti et al. 2021): " + Foam::name(nBins_)
      + " bins of height " + Foam::name(h) + "; reduced units"
    );
    writeCommented(os, "y");
    for
    (
        const char* column
      : {"nParticles", "phi", "Ux", "Uinf", "shearRate", "etaR"}
    )
    {
        writeTabbed(os, column);
    }
    os  << endl;

    forAll(n, bin)
    {
        if (knownBy[bin] == Pstream::nProcs())
        {
            flow.notKnownAt
            (
                "the centre of profile bin " + Foam::name(bin), centre(bin)
            );
        }
        const scalar rate = shearRate[bin];
        const scalar sigmaXY = eta0*rate + Sxy[bin]/binVolume;

        os  << centre(bin).y()
            << tab << n[bin]
            << tab << volume[bin]/binVolume
            << tab << (n[bin] ? Ux[bin]/n[bin] : 0)
            << tab << UinfX[bin]
            << tab << rate
            << tab
            << (
                   rate != 0
                 ? sigmaXY/(eta0*rate)
                 : std::numeric_limits<scalar>::quiet_NaN()
               )
            << nl;
    }

    return true;
}


// ************************************************************************* //
