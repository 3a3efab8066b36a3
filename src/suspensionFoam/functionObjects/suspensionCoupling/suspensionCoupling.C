#include "suspensionCoupling.H"
#include "suspensionCloud.H"
#include "inputChecks.H"
#include "OFstream.H"
#include "fvcGrad.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(suspensionCoupling, 0);
    addToRunTimeSelectionTable(functionObject, suspensionCoupling, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class FieldType>
const FieldType& Foam::functionObjects::suspensionCoupling::field
(
    const word& name
) const
{
    const FieldType* f = mesh_.findObject<FieldType>(name);
    if (!f)
    {
        FatalErrorInFunction
            << "Function object " << this->name() << " needs the field '"
            << name << "' of suspensionCoupledFoam, which mesh "
            << mesh_.name() << " does not hold: run it with"
            << " suspensionCoupledFoam" << nl << exit(FatalError);
    }
    return *f;
}


void Foam::functionObjects::suspensionCoupling::writeProfile() const
{
    const suspensionCloud& cloud = suspensionCloud::lookup(mesh_, name());
    const scalar gammaDot = cloud.flow().shearRate();
    const scalar eta0 = cloud.eta0();
    const volVectorField& Uprime = field<volVectorField>("Uprime");

    const scalarField Ux(grid_.rowMeans(Uprime.component(vector::X)()()));
    const scalarField shearRate
    (
        gammaDot
      + grid_.rowMeans(fvc::grad(Uprime)().primitiveField().component(tensor::YX)())
    );
    const scalarField Sxy
    (
        grid_.rowMeans
        (
            field<volSymmTensorField>("sigmaP").primitiveField()
           .component(symmTensor::XY)()
        )
    );
    const scalarField SRxy
    (
        grid_.rowMeans
        (
            field<volSymmTensorField>("sigmaPRelaxed").primitiveField()
           .component(symmTensor::XY)()
        )
    );
    const scalarField fx
    (
        grid_.rowMeans
        (
            field<volVectorField>("bodyForce").primitiveField()
           .component(vector::X)()
        )
    );
    const scalarField phi
    (
        grid_.rowMeans(field<volScalarField>("alphaP").primitiveField())
    );

    // tau = <tau> - (int_0^y f_x - mean): the integral of the row values
    // to each row centre (midpoint rule)
    const scalarList& e = grid_.edges(1);
    const scalar Ly = e.last() - e.first();
    const scalarField tau(eta0*shearRate + SRxy);
    scalarField integral(fx.size());
    scalar below = 0;
    scalar tauMean = 0;
    scalar integralMean = 0;
    forAll(fx, j)
    {
        const scalar dy = e[j + 1] - e[j];
        integral[j] = below + 0.5*dy*fx[j];
        below += dy*fx[j];
        tauMean += dy*tau[j]/Ly;
        integralMean += dy*integral[j]/Ly;
    }

    autoPtr<OFstream> osPtr = createFile("profile", time_.value());
    if (!osPtr.valid())
    {
        return;
    }
    OFstream& os = osPtr();
    writeHeader
    (
        os,
        "Coupled flow across y at time " + time_.timeName() + ": "
      + Foam::name(grid_.n(1)) + " rows of cells; reduced units"
    );
    writeCommented(os, "y");
    for
    (
        const char* column
      : {
            "Ux", "shearRate", "sigmaPxy", "sigmaPRelaxedxy", "tau",
            "tauInstant", "tauExact", "phi"
        }
    )
    {
        writeTabbed(os, column);
    }
    os  << endl;
    forAll(Ux, j)
    {
        const scalar y = grid_.rowCentre(j);
        os  << y
            << tab << gammaDot*y + Ux[j]
            << tab << shearRate[j]
            << tab << Sxy[j]
            << tab << SRxy[j]
            << tab << tau[j]
            << tab << eta0*shearRate[j] + Sxy[j]
            << tab << tauMean - (integral[j] - integralMean)
            << tab << phi[j] << nl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::suspensionCoupling::suspensionCoupling
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "amplitude"),
    grid_
    (
        mesh_,
        suspensionCloud::lookup(mesh_, name).flow().box(),
        "Function object " + name
    ),
    n_(1),
    writeFields_(true),
    amplitudeFile_()
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::suspensionCoupling::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    n_ = dict.found("periods") ? getLabelAtLeast(dict, "periods", 1) : 1;
    writeFields_ = dict.getOrDefault<bool>("writeFields", true);
    return true;
}


bool Foam::functionObjects::suspensionCoupling::execute()
{
    return true;
}


bool Foam::functionObjects::suspensionCoupling::write()
{
    const suspensionCloud& cloud = suspensionCloud::lookup(mesh_, name());
    const volVectorField& Uprime = field<volVectorField>("Uprime");
    const volVectorField& f = field<volVectorField>("bodyForce");
    const volSymmTensorField& sigmaP = field<volSymmTensorField>("sigmaP");
    const volSymmTensorField& sigmaPRelaxed =
        field<volSymmTensorField>("sigmaPRelaxed");
    const volScalarField& alphaP = field<volScalarField>("alphaP");

    const vector& L = cloud.flow().box();
    const scalar k = constant::mathematical::twoPi*n_/L.y();
    const scalarField& V = mesh_.V();
    const scalar volume = gSum(V);
    scalar A = 0;
    scalar B = 0;
    scalar F = 0;
    forAll(V, celli)
    {
        const scalar y = mesh_.C()[celli].y();
        A += 2*V[celli]*Uprime[celli].x()*std::sin(k*y)/volume;
        B += 2*V[celli]*Uprime[celli].x()*std::cos(k*y)/volume;
        F += 2*V[celli]*f[celli].x()*std::sin(k*y)/volume;
    }
    reduce(A, sumOp<scalar>());
    reduce(B, sumOp<scalar>());
    reduce(F, sumOp<scalar>());
    const scalar etaEff = F != 0 ? F/(cloud.eta0()*k*k*A) : 0;

    // The particles' own mode of the shear stress, without the kernel
    const suspension::Particles& p = cloud.simulation().particles();
    const std::vector<suspension::Mat3>& S = cloud.particleStresslets();
    // and of the volume fraction (migration)
    // and the sine mode of the particles' velocity beyond the mean shear
    const scalar gammaDot = cloud.flow().shearRate();
    scalar Sk = 0;
    scalar phik = 0;
    scalar Ap = 0;
    label count = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (p.isGhost(i))
        {
            continue;
        }
        const scalar y = p.x[i].y();
        const scalar c = std::cos(k*y);
        Sk += (S[i](0, 1) + S[i](1, 0))*c;
        phik += 2*sphereVolume(p.a[i])*c;
        Ap += 2*(p.u[i].x() - gammaDot*y)*std::sin(k*y);
        ++count;
    }
    reduce(Sk, sumOp<scalar>());
    reduce(phik, sumOp<scalar>());
    reduce(Ap, sumOp<scalar>());
    reduce(count, sumOp<label>());
    Ap /= max(count, label(1));
    Sk /= L.x()*L.y()*L.z();
    phik /= L.x()*L.y()*L.z();
    const scalarField phi(grid_.rowMeans(alphaP.primitiveField()));
    const scalar sigmaPxy =
        gSum(V*sigmaP.primitiveField().component(symmTensor::XY)())/volume;
    const scalar sigmaPRelaxedxy =
        gSum(V*sigmaPRelaxed.primitiveField().component(symmTensor::XY)())
       /volume;

    if (Pstream::master() && writeToFile())
    {
        if (!amplitudeFile_.valid())
        {
            amplitudeFile_ = createFile("amplitude");
            OFstream& os = amplitudeFile_();
            writeHeader
            (
                os,
                "Amplitudes of u' and f at k = 2 pi " + Foam::name(n_)
              + "/Ly = " + Foam::name(k) + "; reduced units"
            );
            writeCommented(os, "Time");
            for
            (
                const char* column
              : {
                    "A", "B", "F", "etaEff", "Ap", "sigmaPk", "sigmaPxy",
                    "sigmaPRelaxedxy", "phik", "phiMin", "phiMax"
                }
            )
            {
                writeTabbed(os, column);
            }
            os  << endl;
        }
        amplitudeFile_()
            << time_.value()
            << tab << A << tab << B << tab << F << tab << etaEff
            << tab << Ap << tab << Sk
            << tab << sigmaPxy << tab << sigmaPRelaxedxy
            << tab << phik << tab << min(phi) << tab << max(phi) << endl;
    }

    if (time_.writeTime())
    {
        writeProfile();
        if (writeFields_)
        {
            volVectorField U
            (
                IOobject
                (
                    "U", time_.timeName(), mesh_, IOobject::NO_READ,
                    IOobject::NO_WRITE, false
                ),
                Uprime
            );
            const volScalarField y(mesh_.C().component(vector::Y));
            U.replace
            (
                vector::X,
                Uprime.component(vector::X)
              + dimensionedScalar
                (
                    "gammaDot", dimless/dimTime, cloud.flow().shearRate()
                )*y
            );
            U.write();
            sigmaP.write();
            alphaP.write();
        }
    }
    return true;
}


// ************************************************************************* //
