#include "profilesFile.H"
#include "OFstream.H"
#include "Time.H"
#include "particleFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::profilesFile::profilesFile(const objectRegistry& obr, const label nBins)
:
    functionObjects::writeFile(obr, "profiles", "profiles"),
    nBins_(nBins)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::profilesFile::write
(
    const suspension::Particles& p,
    const std::vector<suspension::Mat3>& S,
    const ambientFlow& flow,
    const scalar eta0
) const
{
    const vector& L = flow.box();
    const scalar h = L.y()/nBins_;
    const scalar binVolume = L.x()*h*L.z();

    labelList n(nBins_, Zero);
    scalarField volume(nBins_, Zero);
    scalarField Ux(nBins_, Zero);
    scalarField Sxy(nBins_, Zero);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const label bin = min(nBins_ - 1, label(p.x[i].y()/h));
        ++n[bin];
        volume[bin] += sphereVolume(p.a[i]);
        Ux[bin] += p.u[i].x();
        Sxy[bin] += 0.5*(S[i](0, 1) + S[i](1, 0));
    }

    autoPtr<OFstream> osPtr = createFile("profiles", fileObr_.time().value());
    OFstream& os = osPtr();
    writeHeader
    (
        os,
        "Profiles across y at time " + fileObr_.time().timeName()
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
        const point centre(0.5*L.x(), (bin + 0.5)*h, 0.5*L.z());
        const scalar shearRate = flow.localShearRate(centre);
        const scalar sigmaXY = eta0*shearRate + Sxy[bin]/binVolume;

        os  << centre.y()
            << tab << n[bin]
            << tab << volume[bin]/binVolume
            << tab << (n[bin] ? Ux[bin]/n[bin] : 0)
            << tab << flow.U(centre).x()
            << tab << shearRate
            << tab << sigmaXY/(eta0*shearRate) << nl;
    }
}


// ************************************************************************* //
