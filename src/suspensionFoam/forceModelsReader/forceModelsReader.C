#include "forceModelsReader.H"
#include "inputChecks.H"

#include <cstring>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The engine's range as an interval (infinity as GREAT)
interval toInterval(const suspension::ModelInput::Range& r)
{
    return interval
    (
        r.min, !r.minOpen, r.max > GREAT ? GREAT : r.max, !r.maxOpen
    );
}


//- The sub-dictionary at a path "a/b" below dict, null if absent
const dictionary* findPath(const dictionary& dict, const std::string& path)
{
    const dictionary* d = &dict;
    std::size_t begin = 0;
    while (d && begin <= path.size())
    {
        const std::size_t end = std::min(path.find('/', begin), path.size());
        const word part(path.substr(begin, end - begin));
        d = d->isDict(part, keyType::LITERAL) ? &d->subDict(part) : nullptr;
        begin = end + 1;
    }
    return d;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Input  * * * * * * * * * * * * * * * * //

Foam::forceModelsReader::input::input
(
    const dictionary& dict,
    forceModelsReader& reader
)
:
    dict_(dict),
    reader_(reader),
    asked_()
{}


void Foam::forceModelsReader::input::ask(const std::string& name) const
{
    if (!asked_.found(name))
    {
        asked_.append(name);
    }
}


double Foam::forceModelsReader::input::scalar
(
    const std::string& name,
    const Range& range,
    const std::string&
) const
{
    ask(name);
    return getScalarIn(dict_, name, toInterval(range));
}


double Foam::forceModelsReader::input::scalarOr
(
    const std::string& name,
    double defaultValue,
    const Range& range,
    const std::string&
) const
{
    ask(name);
    return getScalarInOrDefault(dict_, name, defaultValue, toInterval(range));
}


std::string Foam::forceModelsReader::input::word
(
    const std::string& name,
    const std::vector<std::string>& choices,
    bool optional,
    const std::string&
) const
{
    ask(name);
    if (optional && !found(name))
    {
        return choices.front();
    }
    const Foam::word value = dict_.get<Foam::word>(name);
    for (const std::string& c : choices)
    {
        if (value == c)
        {
            return c;
        }
    }
    wordList valid;
    for (const std::string& c : choices)
    {
        valid.append(c);
    }
    FatalIOErrorInFunction(dict_)
        << "Entry '" << name << "' = " << value << " in dictionary "
        << dict_.name() << " is not one of " << valid << nl
        << exit(FatalIOError);
    return value;
}


bool Foam::forceModelsReader::input::found(const std::string& name) const
{
    return dict_.found(name, keyType::LITERAL);
}


const suspension::ModelInput&
Foam::forceModelsReader::input::parent() const
{
    return reader_.inputOf(dict_.parent());
}



// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::forceModelsReader::input&
Foam::forceModelsReader::inputOf(const dictionary& dict)
{
    for (const std::unique_ptr<input>& in : inputs_)
    {
        if (&in->dict() == &dict)
        {
            return *in;
        }
    }
    inputs_.push_back(std::make_unique<input>(dict, *this));
    return *inputs_.back();
}


void Foam::forceModelsReader::checkUnknownEntries() const
{
    for (const std::unique_ptr<input>& in : inputs_)
    {
        wordList valid(in->asked());
        valid.append(word("active"));
        valid.append(word("type"));
        for (const entry& e : in->dict())
        {
            if (e.isDict())
            {
                valid.append(e.keyword());
            }
        }
        checkEntries(in->dict(), valid);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::forceModelsReader::forceModelsReader(const dictionary& dict)
{
    auto readModel = [&](auto tag)
    {
        using M = typename decltype(tag)::type;
        if constexpr (M::dictName[0] != '\0')
        {
            read<M>(dict);
        }
    };
    suspension::forEachParticleModelType(readModel);
    suspension::forEachPairModelType(readModel);
    checkUnknownEntries();
}


Foam::wordList Foam::forceModelsReader::dictionaries()
{
    wordList names;
    auto add = [&](auto tag)
    {
        using M = typename decltype(tag)::type;
        const std::string path(M::dictName);
        const word top(path.substr(0, path.find('/')));
        if (!top.empty() && !names.found(top))
        {
            names.append(top);
        }
    };
    suspension::forEachParticleModelType(add);
    suspension::forEachPairModelType(add);
    return names;
}


template<class M>
void Foam::forceModelsReader::read(const dictionary& dict)
{
    const dictionary* d = findPath(dict, M::dictName);
    if (!d || !d->get<bool>("active"))
    {
        return;
    }

    // Alternatives read from the same dictionary: selected by `type`
    wordList types;
    auto alternative = [&](auto other)
    {
        using O = typename decltype(other)::type;
        if (std::strcmp(O::dictName, M::dictName) == 0)
        {
            types.append(O::typeName);
        }
    };
    suspension::forEachParticleModelType(alternative);
    suspension::forEachPairModelType(alternative);
    if (types.size() > 1)
    {
        const word type = d->getOrDefault<word>("type", types.first());
        if (!types.found(type))
        {
            FatalIOErrorInFunction(*d)
                << "Entry 'type' = " << type << " in dictionary "
                << d->name() << " is not one of " << types << nl
                << exit(FatalIOError);
        }
        if (type != M::typeName)
        {
            return;
        }
    }

    const input& in = inputOf(*d);
    models_.set(engineCall(*d, [&]{ return M(M::read(in)); }));
}


// ************************************************************************* //
