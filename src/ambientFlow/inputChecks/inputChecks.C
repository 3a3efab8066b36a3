#include "inputChecks.H"

#include <cmath>
#include <cstdlib>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- An end of an interval, GREAT written as inf
Foam::word endName(const Foam::scalar x)
{
    if (x >= Foam::GREAT)
    {
        return "inf";
    }
    if (x <= -Foam::GREAT)
    {
        return "-inf";
    }
    return Foam::name(x);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::interval::contains(const scalar x) const
{
    return
        std::isfinite(x)
     && (loClosed_ ? x >= lo_ : x > lo_)
     && (hiClosed_ ? x <= hi_ : x < hi_);
}


Foam::Ostream& Foam::operator<<(Ostream& os, const interval& range)
{
    os  << (range.loClosed_ ? "[" : "(") << endName(range.lo_).c_str() << ", "
        << endName(range.hi_).c_str() << (range.hiClosed_ ? "]" : ")");
    return os;
}


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::checkEntries(const dictionary& dict, const wordList& valid)
{
    for (const entry& e : dict)
    {
        if (!valid.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown entry '" << e.keyword() << "' in dictionary "
                << dict.name() << nl
                << "Valid entries: " << valid << nl
                << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::getScalarIn
(
    const dictionary& dict,
    const word& key,
    const interval& range
)
{
    const scalar x = dict.get<scalar>(key);
    if (!range.contains(x))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << x << " in dictionary "
            << dict.name() << " is outside the allowed range " << range << nl
            << exit(FatalIOError);
    }
    return x;
}


Foam::scalar Foam::getScalarInOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const interval& range
)
{
    return dict.found(key, keyType::LITERAL) ? getScalarIn(dict, key, range) : deflt;
}


Foam::label Foam::getLabelAtLeast
(
    const dictionary& dict,
    const word& key,
    const label minValue
)
{
    const label n = dict.get<label>(key);
    if (n < minValue)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << n << " in dictionary "
            << dict.name() << " must be >= " << minValue << nl
            << exit(FatalIOError);
    }
    return n;
}


void Foam::raiseEngineError
(
    const dictionary& dict,
    const std::exception& err,
    const string& hint
)
{
    FatalIOErrorInFunction(dict)
        << err.what() << nl;
    if (!hint.empty())
    {
        FatalIOError<< "    " << hint.c_str() << nl;
    }
    FatalIOError
        << "    (from the entries of dictionary " << dict.name() << ")" << nl
        << exit(FatalIOError);

    // FatalIOError has thrown (throwExceptions) or exited
    std::abort();
}


// ************************************************************************* //
