#include "ambientFlow.H"
#include "volFields.H"
#include "processorFvPatch.H"

#include <cstdlib>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(ambientFlow, 0);
    defineRunTimeSelectionTable(ambientFlow, dictionary);
}

const Foam::wordList Foam::ambientFlow::fieldNames
({
    "Uinf", "gradUinf", "shearRateInf"
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- One quantity of the flow (picked from the sample by get) at the points,
//  at the rate now or of the periodic part only; a FatalError names the
//  first point where the flow is not known
template<class Type, class Get>
Foam::tmp<Foam::Field<Type>> evaluate
(
    const Foam::ambientFlow& flow,
    const Foam::pointField& points,
    const Get& get,
    const bool periodic = false
)
{
    using namespace Foam;

    auto tfld = tmp<Field<Type>>::New(points.size());
    Field<Type>& fld = tfld.ref();
    ambientFlowSample values;
    forAll(points, i)
    {
        const bool known = periodic
          ? flow.samplePeriodic(points[i], values)
          : flow.sample(points[i], values);
        if (!known)
        {
            flow.notKnownAt
            (
                "point " + name(i) + " of " + name(points.size()), points[i]
            );
        }
        fld[i] = get(values);
    }
    return tfld;
}


//- Write the field f(points) evaluated at the cell centres and at the
//  boundary face centres (calculated patches) of mesh, at the mesh's
//  current time; a processor patch holds the neighbour cells' values
//  (taken from the neighbour: a flow on the mesh knows them there only)
template<class Type, class Function>
void writeCellAndFaceField
(
    const Foam::fvMesh& mesh,
    const Foam::word& name,
    const Foam::dimensionSet& dims,
    const Function& f
)
{
    using namespace Foam;

    GeometricField<Type, fvPatchField, volMesh> fld
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensioned<Type>(dims, Zero),
        calculatedFvPatchField<Type>::typeName
    );

    const volVectorField& C = mesh.C();

    fld.primitiveFieldRef() = f(C.primitiveField());

    auto& bf = fld.boundaryFieldRef();
    const auto processor = [&mesh](const label patchi)
    {
        return isA<processorFvPatch>(mesh.boundary()[patchi]);
    };
    forAll(bf, patchi)
    {
        if (!processor(patchi))
        {
            bf[patchi] == f(C.boundaryField()[patchi]);
        }
    }
    const UPstream::commsTypes comms = UPstream::commsTypes::nonBlocking;
    forAll(bf, patchi)
    {
        if (processor(patchi))
        {
            bf[patchi].initEvaluate(comms);
        }
    }
    Pstream::waitRequests();
    forAll(bf, patchi)
    {
        if (processor(patchi))
        {
            bf[patchi].evaluate(comms);
        }
    }

    fld.write();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

namespace
{

//- Whether dict sets the shear stress instead of the rate: one of the two
bool stressEntry(const Foam::dictionary& dict)
{
    using namespace Foam;
    const bool stress = dict.found("shearStress", keyType::LITERAL);
    if (stress && dict.found("shearRate", keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'shearRate' and 'shearStress' in dictionary "
            << dict.name() << ": give one, the rate (rate control) or the"
            << " shear stress (stress control)" << nl << exit(FatalIOError);
    }
    return stress;
}

} // End anonymous namespace


Foam::ambientFlow::ambientFlow(const dictionary& dict, const vector& box)
:
    box_(box),
    stressControlled_(stressEntry(dict)),
    programme_(dict, stressControlled_ ? "shearStress" : "shearRate"),
    gammaDot_(stressControlled_ ? 0 : programme_.value(0))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::ambientFlow::sample
(
    const point& p,
    const scalar gammaDot,
    ambientFlowSample& values
) const
{
    if (!samplePeriodic(p, values))
    {
        return false;
    }
    values.U.x() += gammaDot*p.y();
    values.gradU.yx() += gammaDot;
    return true;
}


Foam::ambientFlowSample Foam::ambientFlow::sample(const point& p) const
{
    ambientFlowSample values;
    if (!sample(p, values))
    {
        notKnownAt("point", p);
    }
    return values;
}


Foam::vector Foam::ambientFlow::U(const point& p) const
{
    return sample(p).U;
}


Foam::tensor Foam::ambientFlow::gradU(const point& p) const
{
    return sample(p).gradU;
}


Foam::vector Foam::ambientFlow::laplacianU(const point& p) const
{
    return sample(p).laplacianU;
}


Foam::tensor Foam::ambientFlow::gradLaplacianU(const point& p) const
{
    return sample(p).gradLaplacianU;
}


Foam::boundBox Foam::ambientFlow::bounds() const
{
    return boundBox::greatBox;
}


void Foam::ambientFlow::notKnownAt(const string& what, const point& p) const
{
    FatalErrorInFunction
        << "The ambientFlow " << type() << " is not known at " << what.c_str()
        << " at " << p << ", outside its bounds " << bounds() << nl
        << exit(FatalError);

    // FatalError has thrown (throwExceptions) or exited
    std::abort();
}


Foam::tmp<Foam::vectorField> Foam::ambientFlow::U
(
    const pointField& points
) const
{
    return evaluate<vector>
    (
        *this, points, [](const ambientFlowSample& s) { return s.U; }
    );
}


Foam::tmp<Foam::vectorField> Foam::ambientFlow::periodicU
(
    const pointField& points
) const
{
    return evaluate<vector>
    (
        *this, points, [](const ambientFlowSample& s) { return s.U; }, true
    );
}


Foam::tmp<Foam::tensorField> Foam::ambientFlow::gradU
(
    const pointField& points
) const
{
    return evaluate<tensor>
    (
        *this, points, [](const ambientFlowSample& s) { return s.gradU; }
    );
}


Foam::tmp<Foam::vectorField> Foam::ambientFlow::laplacianU
(
    const pointField& points
) const
{
    return evaluate<vector>
    (
        *this, points, [](const ambientFlowSample& s) { return s.laplacianU; }
    );
}


Foam::tmp<Foam::tensorField> Foam::ambientFlow::gradLaplacianU
(
    const pointField& points
) const
{
    return evaluate<tensor>
    (
        *this, points,
        [](const ambientFlowSample& s) { return s.gradLaplacianU; }
    );
}


Foam::symmTensor Foam::ambientFlow::E(const point& p) const
{
    return symm(gradU(p));
}


Foam::vector Foam::ambientFlow::Omega(const point& p) const
{
    // *skew(T) = (T.yz - T.zy, T.zx - T.xz, T.xy - T.yx)/2 = curl(U)/2
    return *skew(gradU(p));
}


Foam::scalar Foam::ambientFlow::localShearRate(const point& p) const
{
    return gradU(p).yx();
}


void Foam::ambientFlow::writeFields
(
    const fvMesh& mesh,
    const wordHashSet& names
) const
{
    if (names.found("Uinf"))
    {
        writeCellAndFaceField<vector>
        (
            mesh, "Uinf", dimVelocity,
            [this](const pointField& p) { return U(p); }
        );
    }
    if (names.found("gradUinf"))
    {
        writeCellAndFaceField<tensor>
        (
            mesh, "gradUinf", dimless/dimTime,
            [this](const pointField& p) { return gradU(p); }
        );
    }
    if (names.found("shearRateInf"))
    {
        writeCellAndFaceField<scalar>
        (
            mesh, "shearRateInf", dimless/dimTime,
            [this](const pointField& p) { return gradU(p)().component(tensor::YX); }
        );
    }
}


// ************************************************************************* //
