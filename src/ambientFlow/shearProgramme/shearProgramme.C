#include "shearProgramme.H"
#include "oscillatoryShear.H"
#include "Constant.H"
#include "OneConstant.H"
#include "ZeroConstant.H"
#include "PolynomialEntry.H"
#include "TableBase.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The table behind f, if it is one (table, tableFile, csv)
const Function1Types::TableBase<scalar>* table(const Function1<scalar>& f)
{
    return dynamic_cast<const Function1Types::TableBase<scalar>*>(&f);
}


//- Whether f is the same at all times
bool isConstant(const Function1<scalar>& f)
{
    return isA<Function1Types::Constant<scalar>>(f)
        || isA<Function1Types::OneConstant<scalar>>(f)
        || isA<Function1Types::ZeroConstant<scalar>>(f);
}

//- The interval over which f's own integral is exact: everywhere for the
//  oscillatory and polynomial types, a table's range, else none
std::pair<scalar, scalar> exactRange(const Function1<scalar>& f)
{
    if
    (
        isA<Function1Types::oscillatoryShear>(f)
     || isA<Function1Types::Polynomial<scalar>>(f)
    )
    {
        return {-GREAT, GREAT};
    }
    if (const Function1Types::TableBase<scalar>* t = table(f))
    {
        const scalarField x(t->x());
        return {min(x), max(x)};
    }
    return {GREAT, -GREAT};
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

namespace
{

//- The Function1 of entry `entryName`, or an error naming it
autoPtr<Function1<scalar>> readRate
(
    const dictionary& dict,
    const word& entryName
)
{
    if (!dict.found(entryName, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << entryName << "' not found in dictionary "
            << dict.name() << ": the mean shear rate, a Function1 of time"
            << " (a number for a constant rate; table, oscillatory, ...)"
            << nl << exit(FatalIOError);
    }
    return Function1<scalar>::New(entryName, dict);
}

} // End anonymous namespace


Foam::shearProgramme::shearProgramme
(
    const dictionary& dict,
    const word& entryName
)
:
    rate_(readRate(dict, entryName)),
    constant_(isConstant(*rate_)),
    exact_(exactRange(*rate_))
{
    const scalar r0 = rate_->value(0);
    if (!std::isfinite(r0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << entryName << "' gives the shear rate " << r0
            << " at t = 0: not a finite number" << nl << exit(FatalIOError);
    }
}


Foam::shearProgramme::shearProgramme(const shearProgramme& p)
:
    rate_(p.rate_->clone().ptr()),
    constant_(p.constant_),
    exact_(p.exact_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::shearProgramme::value(const scalar t) const
{
    return rate_->value(t);
}


Foam::scalar Foam::shearProgramme::mean(const scalar t0, const scalar t1) const
{
    const Function1<scalar>& f = *rate_;
    if (constant_)
    {
        return f.value(t0);
    }

    if (t0 >= exact_.first && t1 <= exact_.second)
    {
        return f.integrate(t0, t1)/(t1 - t0);
    }

    // Five-point Gauss-Legendre on [-1, 1]
    static const scalar x[5] =
        {-0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640};
    static const scalar w[5] =
        {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891};
    const scalar mid = 0.5*(t0 + t1);
    const scalar half = 0.5*(t1 - t0);
    scalar sum = 0;
    for (label k = 0; k < 5; ++k)
    {
        sum += w[k]*f.value(mid + half*x[k]);
    }
    return 0.5*sum;
}


Foam::scalar Foam::shearProgramme::max(const scalar t0, const scalar t1) const
{
    const Function1<scalar>& f = *rate_;
    scalar m = Foam::max(mag(f.value(t0)), mag(f.value(t1)));
    if (constant_)
    {
        return m;
    }
    if (const auto* osc = dynamic_cast<const Function1Types::oscillatoryShear*>(&f))
    {
        return osc->strainAmplitude()*osc->omega();
    }
    if (const Function1Types::TableBase<scalar>* t = table(f))
    {
        const scalarField xs(t->x());
        const scalarField ys(t->y());
        forAll(xs, i)
        {
            if (xs[i] >= t0 && xs[i] <= t1)
            {
                m = Foam::max(m, mag(ys[i]));
            }
        }
        return m;
    }
    const label n = 10000;
    for (label k = 1; k < n; ++k)
    {
        m = Foam::max(m, mag(f.value(t0 + (t1 - t0)*k/n)));
    }
    return m;
}


// ************************************************************************* //
