#include "suspensionIO.H"
#include "inputChecks.H"
#include "ambientFlowAdapter.H"
#include "passiveParticleCloud.H"
#include "IOField.H"
#include "IOdictionary.H"
#include "DynamicList.H"
#include "cloud.H"
#include "treeDataCell.H"
#include "indexedOctree.H"

#include <algorithm>
#include <unordered_map>
#include <utility>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::suspensionIO::cloudName("suspension");
const Foam::word Foam::suspensionIO::contactsName("suspensionContacts");
const Foam::word Foam::suspensionIO::stateName("suspensionState");


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using suspension::Vec3;

//- At least 17 significant digits for ascii output while alive: doubles
//  then read back exactly
class fullPrecision
{
    const unsigned int old_;

public:

    fullPrecision()
    :
        old_
        (
            IOstream::defaultPrecision
            (
                std::max(17u, IOstream::defaultPrecision())
            )
        )
    {}

    ~fullPrecision()
    {
        IOstream::defaultPrecision(old_);
    }
};


//- A file of the current time directory in folder `local`
IOobject timeFile
(
    const objectRegistry& db,
    const fileName& local,
    const word& name,
    const IOobject::readOption r
)
{
    return IOobject
    (
        name,
        db.time().timeName(),
        local,
        db,
        r,
        IOobject::NO_WRITE,
        false
    );
}


IOobject particleFile
(
    const fvMesh& mesh,
    const word& name,
    const IOobject::readOption r
)
{
    return timeFile(mesh, cloud::prefix/suspensionIO::cloudName, name, r);
}


IOobject contactFile
(
    const fvMesh& mesh,
    const word& name,
    const IOobject::readOption r
)
{
    return timeFile(mesh, cloud::prefix/suspensionIO::contactsName, name, r);
}


//- Read an IOField that must hold n entries, as the state file says
template<class Type>
Field<Type> readField
(
    const IOobject& io,
    const label n,
    const suspensionIO::state& s
)
{
    IOField<Type> fld(io);
    if (fld.size() != n)
    {
        FatalIOErrorInFunction(fld.objectPath())
            << "File " << fld.objectPath() << " holds " << fld.size()
            << " entries, but " << s.file << " gives " << n
            << " for time " << io.instance() << nl
            << exit(FatalIOError);
    }
    Field<Type> values;
    values.transfer(fld);
    return values;
}


//- As readField, or n zeros when the file is absent (a field added since
//  the cloud was written)
template<class Type>
Field<Type> readFieldOrZero
(
    const IOobject& io,
    const label n,
    const suspensionIO::state& s
)
{
    IOobject probe(io);
    if (!probe.typeHeaderOk<IOField<Type>>(true))
    {
        return Field<Type>(n, Zero);
    }
    return readField<Type>(io, n, s);
}


vectorField toFoamField(const std::vector<Vec3>& v)
{
    vectorField f(label(v.size()));
    forAll(f, i)
    {
        f[i] = Foam::toFoam(v[i]);
    }
    return f;
}


template<class Type>
void writeField(const IOobject& io, const Field<Type>& values)
{
    IOField<Type>(io, values).write();
}


//- Write a dictionary as ascii with full precision
void writeAscii(const IOdictionary& dict)
{
    const fullPrecision precision;
    dict.regIOobject::writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        IOstream::UNCOMPRESSED,
        true
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bool Foam::suspensionIO::found(const Time& runTime)
{
    return
        isFile(runTime.timePath()/"uniform"/stateName)
     || isDir(runTime.timePath()/cloud::prefix/cloudName);
}


Foam::suspensionIO::state Foam::suspensionIO::readState(const Time& runTime)
{
    const IOdictionary dict
    (
        timeFile(runTime, "uniform", stateName, IOobject::MUST_READ)
    );
    checkEntries
    (
        dict, {"time", "steps", "nParticles", "nContacts", "box", "offset"}
    );

    state s;
    s.time = dict.get<scalar>("time");
    s.steps = dict.get<std::uint64_t>("steps");
    s.nParticles = getLabelAtLeast(dict, "nParticles", 1);
    s.nContacts = getLabelAtLeast(dict, "nContacts", 0);
    s.box = dict.get<vector>("box");
    s.offset = dict.get<scalar>("offset");
    s.file = dict.objectPath();

    if (cmptMin(s.box) <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'box' = " << s.box << " in " << s.file
            << " must have positive lengths" << nl << exit(FatalIOError);
    }
    // A time directory holds the state of its own time
    if (mag(s.time - runTime.value()) > 0.5*runTime.deltaTValue())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'time' = " << s.time << " in " << s.file
            << " is not the time " << runTime.timeName()
            << " of its directory" << nl << exit(FatalIOError);
    }
    return s;
}


suspension::Particles Foam::suspensionIO::readParticles
(
    const fvMesh& mesh,
    const state& s,
    const scalar rho
)
{
    const label n = s.nParticles;
    const auto read = [&](const word& name)
    {
        return particleFile(mesh, name, IOobject::MUST_READ);
    };
    const vectorField x(readField<vector>(read("x"), n, s));
    const scalarField d(readField<scalar>(read("d"), n, s));
    const vectorField U(readField<vector>(read("U"), n, s));
    const vectorField omega(readField<vector>(read("omega"), n, s));
    const vectorField F(readField<vector>(read("F"), n, s));
    const vectorField T(readField<vector>(read("T"), n, s));
    const vectorField dUdt(readFieldOrZero<vector>(read("dUdt"), n, s));
    const vectorField dOmegadt(readFieldOrZero<vector>(read("dOmegadt"), n, s));
    const labelField id(readField<label>(read("origId"), n, s));

    suspension::Particles p;
    forAll(x, i)
    {
        const bool inside =
            x[i].x() >= 0 && x[i].x() < s.box.x()
         && x[i].y() >= 0 && x[i].y() < s.box.y()
         && x[i].z() >= 0 && x[i].z() < s.box.z();
        if (!inside)
        {
            FatalIOErrorInFunction(read("x").objectPath())
                << "Particle " << i << " (origId " << id[i] << ") at "
                << x[i] << " is outside the box [0, " << s.box << ") of "
                << s.file << nl << exit(FatalIOError);
        }
        if (!(d[i] > 0) || !std::isfinite(d[i]))
        {
            FatalIOErrorInFunction(read("d").objectPath())
                << "Particle " << i << " (origId " << id[i]
                << ") has diameter " << d[i] << "; diameters must be positive"
                << nl << exit(FatalIOError);
        }
        if (id[i] < 0)
        {
            FatalIOErrorInFunction(read("origId").objectPath())
                << "Particle " << i << " has the negative id " << id[i] << nl
                << exit(FatalIOError);
        }
        p.add(toEigen(x[i]), 0.5*d[i], rho, id[i]);
        p.u.back() = toEigen(U[i]);
        p.omega.back() = toEigen(omega[i]);
        p.F.back() = toEigen(F[i]);
        p.T.back() = toEigen(T[i]);
        p.dudt.back() = toEigen(dUdt[i]);
        p.domegadt.back() = toEigen(dOmegadt[i]);
    }

    std::vector<std::int64_t> ids(p.id);
    std::sort(ids.begin(), ids.end());
    const auto repeated = std::adjacent_find(ids.begin(), ids.end());
    if (repeated != ids.end())
    {
        FatalIOErrorInFunction(read("origId").objectPath())
            << "The id " << label(*repeated) << " occurs more than once;"
            << " particle ids must be unique" << nl << exit(FatalIOError);
    }
    return p;
}


suspension::PairList Foam::suspensionIO::readContacts
(
    const fvMesh& mesh,
    const state& s,
    const suspension::Particles& p
)
{
    const label n = s.nContacts;
    const auto read = [&](const word& name)
    {
        return contactFile(mesh, name, IOobject::MUST_READ);
    };
    const labelField idI(readField<label>(read("idI"), n, s));
    const labelField idJ(readField<label>(read("idJ"), n, s));
    const vectorField xiT(readField<vector>(read("xiT"), n, s));
    const vectorField xiR(readField<vector>(read("xiR"), n, s));

    std::unordered_map<std::int64_t, std::uint32_t> index;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        index.emplace(p.id[i], std::uint32_t(i));
    }
    const auto indexOf = [&](const label id, const label k)
    {
        const auto it = index.find(id);
        if (it == index.end())
        {
            FatalIOErrorInFunction(read("idI").objectPath())
                << "Contact " << k << " names the particle " << id
                << ", which the cloud " << cloudName << " does not hold" << nl
                << exit(FatalIOError);
        }
        return it->second;
    };

    // Contacts as (row, slot) in a compressed-row list of the particles
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs(n);
    std::vector<std::pair<label, label>> keys(n);
    forAll(idI, k)
    {
        pairs[k] = {indexOf(idI[k], k), indexOf(idJ[k], k)};
        keys[k] = {min(idI[k], idJ[k]), max(idI[k], idJ[k])};
        if (idI[k] == idJ[k])
        {
            FatalIOErrorInFunction(read("idJ").objectPath())
                << "Contact " << k << " pairs particle " << idI[k]
                << " with itself" << nl << exit(FatalIOError);
        }
    }
    std::sort(keys.begin(), keys.end());
    const auto twice = std::adjacent_find(keys.begin(), keys.end());
    if (twice != keys.end())
    {
        FatalIOErrorInFunction(read("idI").objectPath())
            << "The pair (" << twice->first << ", " << twice->second
            << ") holds two contact histories" << nl << exit(FatalIOError);
    }

    suspension::PairList list;
    list.offset.assign(p.size() + 1, 0);
    for (const auto& ij : pairs)
    {
        ++list.offset[ij.first + 1];
    }
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        list.offset[i + 1] += list.offset[i];
    }
    list.j.resize(n);
    list.contactOf.assign(n, suspension::PairList::noContact);
    std::vector<std::uint32_t> next(list.offset.begin(), list.offset.end() - 1);
    forAll(idI, k)
    {
        const std::uint32_t slot = next[pairs[k].first]++;
        list.j[slot] = pairs[k].second;
        list.setHistory
        (
            slot, suspension::ContactState{toEigen(xiT[k]), toEigen(xiR[k])}
        );
    }
    return list;
}


Foam::labelList Foam::suspensionIO::findCells
(
    const polyMesh& mesh,
    const suspension::Particles& p
)
{
    labelList cells(label(p.size()));
    forAll(cells, i)
    {
        const point x = toFoam(p.x[i]);
        cells[i] = mesh.cellTree().findInside(x);
        if (cells[i] < 0)
        {
            // On a cell face of the box boundary
            cells[i] = mesh.findNearestCell(x);
        }
    }
    return cells;
}


void Foam::suspensionIO::writeBox(const Time& runTime, const vector& box)
{
    IOdictionary dict
    (
        IOobject
        (
            "particleBox",
            runTime.constant(),
            runTime,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    dict.add("Lx", box.x());
    dict.add("Ly", box.y());
    dict.add("Lz", box.z());
    writeAscii(dict);
}


void Foam::suspensionIO::write
(
    const fvMesh& mesh,
    const suspension::Simulation& sim,
    const std::uint64_t steps,
    const std::vector<suspension::Mat3>& S,
    const labelList& cells
)
{
    const fullPrecision precision;
    const suspension::Particles& p = sim.particles();

    // The cloud: positions (for ParaView), coordinates, origId
    passiveParticleCloud cloud(mesh, cloudName, IDLList<passiveParticle>());
    forAll(cells, i)
    {
        passiveParticle* pp =
            new passiveParticle(mesh, toFoam(p.x[i]), cells[i]);
        pp->origId() = label(p.id[i]);
        cloud.addParticle(pp);
    }
    // OpenFOAM numbers new particles from particleCount (written to
    // uniform/lagrangian/<cloud>/cloudProperties); every construction above
    // raised it, so a cloud written twice would claim twice its particles:
    // the particles created are those with the ids in use
    label nextId = 0;
    for (const std::int64_t id : p.id)
    {
        nextId = max(nextId, label(id) + 1);
    }
    passiveParticle::particleCount_ = nextId;
    cloud.write();

    const auto particleOut = [&](const word& name)
    {
        return particleFile(mesh, name, IOobject::NO_READ);
    };
    scalarField d(label(p.size()));
    symmTensorField Sp(label(p.size()));
    forAll(d, i)
    {
        d[i] = 2*p.a[i];
        Sp[i] = symm(Foam::toFoam(S[i]));
    }
    writeField(particleOut("x"), toFoamField(p.x));
    writeField(particleOut("d"), d);
    writeField(particleOut("U"), toFoamField(p.u));
    writeField(particleOut("omega"), toFoamField(p.omega));
    writeField(particleOut("F"), toFoamField(p.F));
    writeField(particleOut("T"), toFoamField(p.T));
    writeField(particleOut("dUdt"), toFoamField(p.dudt));
    writeField(particleOut("dOmegadt"), toFoamField(p.domegadt));
    writeField(particleOut("S"), Sp);

    // Contact history, oriented as the slots of the pair list
    const suspension::PairList& pairs = sim.pairs();
    DynamicList<label> idI;
    DynamicList<label> idJ;
    DynamicList<vector> xiT;
    DynamicList<vector> xiR;
    for (std::size_t i = 0; i < pairs.nParticles(); ++i)
    {
        for (std::size_t k = pairs.offset[i]; k < pairs.offset[i + 1]; ++k)
        {
            const suspension::ContactState& c = pairs.history(k);
            if (c.active())
            {
                idI.append(label(p.id[i]));
                idJ.append(label(p.id[pairs.j[k]]));
                xiT.append(toFoam(c.xiT));
                xiR.append(toFoam(c.xiR));
            }
        }
    }
    const auto contactOut = [&](const word& name)
    {
        return contactFile(mesh, name, IOobject::NO_READ);
    };
    writeField(contactOut("idI"), labelField(idI));
    writeField(contactOut("idJ"), labelField(idJ));
    writeField(contactOut("xiT"), vectorField(xiT));
    writeField(contactOut("xiR"), vectorField(xiR));

    IOdictionary dict
    (
        timeFile(mesh.time(), "uniform", stateName, IOobject::NO_READ)
    );
    dict.add("time", sim.time());
    dict.add("steps", steps);
    dict.add("nParticles", label(p.size()));
    dict.add("nContacts", idI.size());
    dict.add("box", toFoam(sim.box().L()));
    dict.add("offset", sim.box().offset());
    writeAscii(dict);
}


// ************************************************************************* //
