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
#include "OFstream.H"
#include "IFstream.H"
#include "OStringStream.H"
#include "SHA1.H"
#include "core/Parallel.H"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <functional>
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


//- Why the last system call failed
std::string systemError()
{
    return errno ? std::strerror(errno) : "unknown error";
}


//- Write io to the file `path` (its objectPath() unless given) as
//  regIOobject::writeObject does, but flushed and checked before the
//  stream closes: a short write (a full disk, a file size limit) is a
//  FatalError naming the file
void writeChecked
(
    const regIOobject& io,
    const IOstream::streamFormat fmt,
    const IOstream::compressionType cmp,
    const fileName& path = fileName::null
)
{
    const fileName file = path.empty() ? io.objectPath() : path;
    mkDir(file.path());
    errno = 0;
    bool ok;
    {
        OFstream os(file, fmt, IOstream::currentVersion, cmp);
        ok = os.good() && io.writeHeader(os) && io.writeData(os);
        if (ok)
        {
            IOobject::writeEndDivider(os);
            os.flush();
            ok = os.good();
        }
    }
    if (!ok)
    {
        FatalErrorInFunction
            << "Cannot write " << file << ": " << systemError().c_str()
            << nl << "    A time whose write fails has no uniform/"
            << suspensionIO::stateName << ": a restart does not take it, and"
            << " the earlier times are intact" << nl << exit(FatalError);
    }
}


template<class Type>
void writeField(const IOobject& io, const Field<Type>& values)
{
    const Time& runTime = io.time();
    writeChecked
    (
        IOField<Type>(io, values),
        runTime.writeFormat(),
        runTime.writeCompression()
    );
}


//- Write a dictionary as ascii with full precision to `path` (its own
//  objectPath() unless given)
void writeAscii(const IOdictionary& dict, const fileName& path = fileName::null)
{
    const fullPrecision precision;
    writeChecked(dict, IOstream::ASCII, IOstream::UNCOMPRESSED, path);
}


// The commit of a time (suspensionIO.H): its files, their digests, the state

//- Flush a file or folder to disk (fsync); with all, every file of its
//  file system (syncfs: one flush for the many files of a time)
void syncToDisk(const fileName& path, const bool all = false)
{
    const int fd = ::open(path.c_str(), O_RDONLY);
    const bool ok = fd >= 0 && (all ? ::syncfs(fd) : ::fsync(fd)) == 0;
    if (fd >= 0)
    {
        ::close(fd);
    }
    if (!ok)
    {
        FatalErrorInFunction
            << "Cannot flush " << path << " to disk: "
            << systemError().c_str() << nl << exit(FatalError);
    }
}


//- SHA-1 digest of a file's bytes, as 40 hex digits
word digestOf(const fileName& path)
{
    std::ifstream is(path, std::ios::binary);
    SHA1 sha;
    std::vector<char> buf(1 << 20);
    while (is)
    {
        is.read(buf.data(), buf.size());
        sha.append(buf.data(), size_t(is.gcount()));
    }
    return sha.digest().str();
}


//- Whether an OpenFOAM file ends with the end divider that
//  IOobject::writeEndDivider writes after the data (ascii and binary); a
//  compressed one (.gz) is read through, so that a truncated stream fails
bool endsWithDivider(const fileName& path)
{
    OStringStream os;
    IOobject::writeEndDivider(os);
    const std::string divider = os.str().substr(2);   // after its "\n\n"
    std::string tail;
    if (path.hasExt("gz"))
    {
        IFstream gz(path.lessExt());
        std::istream& is = gz.stdStream();
        std::vector<char> buf(1 << 16);
        while (is)
        {
            is.read(buf.data(), buf.size());
            tail.append(buf.data(), size_t(is.gcount()));
            if (tail.size() > divider.size())
            {
                tail.erase(0, tail.size() - divider.size());
            }
        }
        return !is.bad() && tail == divider;
    }
    std::ifstream is(path, std::ios::binary);
    is.seekg(0, std::ios::end);
    const std::streamoff size = is.tellg();
    if (size < std::streamoff(divider.size()))
    {
        return false;
    }
    tail.assign(divider.size(), ' ');
    is.seekg(size - std::streamoff(divider.size()));
    is.read(&tail[0], tail.size());
    return bool(is) && tail == divider;
}


//- The files of timeDir, relative to it, that its state lists: the
//  solver's fields, those of uniform (OpenFOAM's time; not the state
//  itself or its temporary), of the cloud and the contact history, and of
//  the cloud's properties
fileNameList committedFiles
(
    const fileName& timeDir,
    const UList<const regIOobject*>& fields
)
{
    const fileName folders[] =
    {
        "uniform",
        cloud::prefix/suspensionIO::cloudName,
        cloud::prefix/suspensionIO::contactsName,
        "uniform"/cloud::prefix/suspensionIO::cloudName
    };
    DynamicList<fileName> files;
    for (const regIOobject* io : fields)
    {
        // as written: compressed (writeCompression on) or not
        const fileName gz = io->name() + ".gz";
        files.append(isFile(timeDir/gz, false) ? gz : fileName(io->name()));
    }
    for (const fileName& folder : folders)
    {
        fileNameList names = readDir(timeDir/folder, fileName::FILE, false);
        sort(names);
        for (const fileName& name : names)
        {
            if (folder == "uniform" && name.find(suspensionIO::stateName) == 0)
            {
                continue;
            }
            files.append(folder/name);
        }
    }
    return fileNameList(std::move(files));
}


//- The sub-dictionary of `files` for the folder of `rel`, added if new
dictionary& folderDict(dictionary& files, const fileName& rel)
{
    dictionary* d = &files;
    if (!rel.hasPath())
    {
        return *d;
    }
    const wordList parts(rel.path().components());
    for (const word& part : parts)
    {
        d = &d->subDictOrAdd(part);
    }
    return *d;
}


//- Each file of `files` (nested as the folders) with its relative path
void forEachListed
(
    const dictionary& files,
    const fileName& folder,
    const std::function<void(const fileName&, const dictionary&)>& f
)
{
    for (const entry& e : files)
    {
        if (!e.isDict())
        {
            continue;
        }
        const fileName rel = folder.empty() ? fileName(e.keyword()) : folder/e.keyword();
        if (e.dict().found("sha1"))
        {
            f(rel, e.dict());
        }
        else
        {
            forEachListed(e.dict(), rel, f);
        }
    }
}


//- The files a state written before the digests needs
bool legacyFilesFound(const fileName& timeDir, string& missing)
{
    const fileName cloudDir = timeDir/cloud::prefix/suspensionIO::cloudName;
    const fileName contactDir = timeDir/cloud::prefix/suspensionIO::contactsName;
    for (const char* f : {"x", "d", "U", "omega", "F", "T", "origId"})
    {
        if (!isFile(cloudDir/f))
        {
            missing = cloudDir/f;
            return false;
        }
    }
    for (const char* f : {"idI", "idJ", "xiT", "xiR"})
    {
        if (!isFile(contactDir/f))
        {
            missing = contactDir/f;
            return false;
        }
    }
    return true;
}


//- Whether timeDir holds any part of a suspension
bool holdsSuspension(const fileName& timeDir)
{
    return
        isFile(timeDir/"uniform"/suspensionIO::stateName)
     || isDir(timeDir/cloud::prefix/suspensionIO::cloudName)
     || isDir(timeDir/cloud::prefix/suspensionIO::contactsName);
}


//- A free name for setting timeDir aside: <time>.incomplete[.k]
fileName asideName(const fileName& timeDir)
{
    fileName aside = timeDir + ".incomplete";
    for (label k = 2; exists(aside, false, false); ++k)
    {
        aside = timeDir + ".incomplete." + Foam::name(k);
    }
    return aside;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::suspensionIO::stored Foam::suspensionIO::check(const fileName& timeDir)
{
    if (!holdsSuspension(timeDir))
    {
        return {stored::absent, ""};
    }
    const fileName stateFile = timeDir/"uniform"/stateName;
    if (!isFile(stateFile, false))
    {
        return
        {
            stored::incomplete,
            "no uniform/" + stateName + ", the file written last"
        };
    }

    // A state edited by hand may not parse: say so instead of stopping
    dictionary state;
    {
        const bool throwing = FatalIOError.throwExceptions();
        const bool throwingFatal = FatalError.throwExceptions();
        try
        {
            const suspension::NonStopArithmetic nonStop;
            IFstream is(stateFile);
            state.read(is);
        }
        catch (const Foam::error& err)
        {
            state.clear();
            state.add("unreadable", err.message());
        }
        FatalIOError.throwExceptions(throwing);
        FatalError.throwExceptions(throwingFatal);
    }
    if (state.found("unreadable"))
    {
        return
        {
            stored::incomplete,
            "uniform/" + stateName + " cannot be read: "
          + state.get<string>("unreadable")
        };
    }

    const dictionary* files = state.findDict("files");
    if (!files)
    {
        string missing;
        if (!legacyFilesFound(timeDir, missing))
        {
            return {stored::incomplete, "no " + missing};
        }
        return
        {
            stored::complete,
            "written before the files' digests: not verified"
        };
    }

    // Each file as listed; named from the case, <time>/<folder>/<file>
    string reason;
    forEachListed
    (
        *files, fileName::null,
        [&](const fileName& rel, const dictionary& listed)
        {
            if (!reason.empty())
            {
                return;
            }
            const fileName path = timeDir/rel;
            const fileName name = timeDir.name()/rel;
            if (!isFile(path, false))
            {
                reason = name + " is missing";
                return;
            }
            // (a string: files beyond 2 GiB overflow a 32-bit label)
            const std::string size = std::to_string(fileSize(path));
            const std::string listedSize = listed.get<string>("size");
            if (size != listedSize)
            {
                reason =
                    name + " holds " + size + " bytes, the state lists "
                  + listedSize;
            }
            else if (digestOf(path) != listed.get<string>("sha1"))
            {
                reason = name + " does not match the SHA-1 digest of the state";
            }
        }
    );
    if (!reason.empty())
    {
        return {stored::incomplete, reason};
    }
    return {stored::complete, ""};
}


bool Foam::suspensionIO::found(const Time& runTime)
{
    return holdsSuspension(runTime.timePath());
}


void Foam::suspensionIO::selectStartTime(const argList& args)
{
    const fileName casePath = args.path();
    const fileName controlFile = casePath/"system"/"controlDict";
    if (!isFile(controlFile))
    {
        return;     // Time says what is missing
    }

    // A number too large for a double is an IOerror naming its entry, not
    // a floating-point trap in the parser
    const dictionary control = [&]()
    {
        const suspension::NonStopArithmetic nonStop;
        IFstream is(controlFile);
        return dictionary(is);
    }();
    const word startFrom =
        control.getOrDefault<word>("startFrom", "latestTime");

    const instantList times = Time::findTimes(casePath, "constant");
    const auto dirOf = [&](const label i) { return casePath/times[i].name(); };

    // The latest complete time at or before time i (-1: none); check()
    // reads every file of the times it passes
    const auto latestComplete = [&](label i)
    {
        while (i >= 0 && check(dirOf(i)).state != stored::complete)
        {
            --i;
        }
        return i;
    };

    if (startFrom == "latestTime")
    {
        const label latest = latestComplete(times.size() - 1);
        if (latest < 0)
        {
            return;     // the cloud says what the start time holds
        }
        for (label i = times.size() - 1; i > latest; --i)
        {
            const fileName dir = dirOf(i);
            stored s = check(dir);
            if (s.state == stored::absent)
            {
                // OpenFOAM writes uniform/time first: a write stopped
                // before the cloud, or before any file
                const bool empty =
                    readDir(dir, fileName::FILE).empty()
                 && readDir(dir/"uniform", fileName::FILE).empty()
                 && readDir(dir, fileName::DIRECTORY).size()
                  <= (isDir(dir/"uniform") ? 1 : 0);
                if (!isFile(dir/"uniform"/"time") && !empty)
                {
                    FatalErrorInFunction
                        << "The latest time " << times[i].name() << " holds"
                        << " no suspension, while " << times[latest].name()
                        << " holds a complete one: remove " << dir
                        << ", or start from a time of your choice (startFrom"
                        << " startTime in " << controlFile << ")" << nl
                        << exit(FatalError);
                }
                s.reason =
                    empty ? "no file: a write stopped at its start"
                  : "uniform/time but no suspension";
            }
            const fileName aside = asideName(dir);
            if (!mv(dir, aside))
            {
                FatalErrorInFunction
                    << "Time " << times[i].name() << " is incomplete ("
                    << s.reason.c_str() << ") and cannot be moved aside to "
                    << aside << ": " << systemError().c_str() << nl
                    << exit(FatalError);
            }
            Info<< "Time " << times[i].name() << " is incomplete ("
                << s.reason.c_str() << "): moved to " << aside.name()
                << " (nothing deleted); starting from "
                << times[latest].name() << ", the latest complete time"
                << nl << endl;
        }
        return;
    }

    // startTime or firstTime: the time Time will take
    label start = -1;
    if (startFrom == "startTime")
    {
        const scalar t = control.get<scalar>("startTime");
        forAll(times, i)
        {
            if (times[i].equal(t))
            {
                start = i;
            }
        }
    }
    else if (startFrom == "firstTime")
    {
        start = times.size() > 1 && times[0].name() == "constant" ? 1 : 0;
    }
    if (start < 0 || start >= times.size())
    {
        return;
    }
    const stored s = check(dirOf(start));
    if (s.state == stored::incomplete)
    {
        const label latest = latestComplete(times.size() - 1);
        FatalIOErrorInFunction(control)
            << "startFrom " << startFrom << " starts from time "
            << times[start].name() << ", which holds an incomplete"
            << " suspension (" << s.reason.c_str() << "); "
            << (latest < 0 ? "no time" : "time " + times[latest].name()).c_str()
            << " holds a complete one" << nl
            << "    Start from a complete time (startTime), or set startFrom"
            << " latestTime, which sets the incomplete latest times aside"
            << nl << exit(FatalIOError);
    }
}


Foam::suspensionIO::state Foam::suspensionIO::readState(const Time& runTime)
{
    // A number too large for a double: an error naming it, not a trap
    const suspension::NonStopArithmetic nonStop;
    const IOdictionary dict
    (
        timeFile(runTime, "uniform", stateName, IOobject::MUST_READ)
    );
    checkEntries
    (
        dict,
        {
            "time", "steps", "nParticles", "nContacts", "box", "offset",
            "strain", "shearRate", "files"
        }
    );

    state s;
    s.time = dict.get<scalar>("time");
    s.steps = dict.get<std::uint64_t>("steps");
    s.nParticles = getLabelAtLeast(dict, "nParticles", 1);
    s.nContacts = getLabelAtLeast(dict, "nContacts", 0);
    s.box = dict.get<vector>("box");
    s.offset = dict.get<scalar>("offset");
    // A state written before the strain was kept ran at the rate 1 (the
    // solver required it): its strain is its time
    s.strain = dict.getOrDefault<scalar>("strain", s.time);
    s.shearRate = dict.getOrDefault<scalar>("shearRate", 1);
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

    // Every value finite (a state written by hand, or corrupted)
    const auto checkFinite = [&](const word& name, const vectorField& f)
    {
        forAll(f, i)
        {
            if (!std::isfinite(f[i].x()) || !std::isfinite(f[i].y()) || !std::isfinite(f[i].z()))
            {
                FatalIOErrorInFunction(read(name).objectPath())
                    << "Particle " << i << " (origId " << id[i] << ") has "
                    << name << " = " << f[i] << "; the values of a stored"
                    << " suspension must be finite" << nl << exit(FatalIOError);
            }
        }
    };
    checkFinite("U", U);
    checkFinite("omega", omega);
    checkFinite("F", F);
    checkFinite("T", T);
    checkFinite("dUdt", dUdt);
    checkFinite("dOmegadt", dOmegadt);

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
        const vector stretch[2] = {xiT[k], xiR[k]};
        for (const vector& v : stretch)
        {
            if (!std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z()))
            {
                FatalIOErrorInFunction(read("xiT").objectPath())
                    << "Contact " << k << " of particles " << idI[k] << " and "
                    << idJ[k] << " has the stretches " << xiT[k] << ", "
                    << xiR[k] << "; they must be finite" << nl
                    << exit(FatalIOError);
            }
        }
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
    const labelList& cells,
    const UList<const regIOobject*>& fields
)
{
    const fullPrecision precision;
    const suspension::Particles& p = sim.particles();
    const fileName timeDir = mesh.time().timePath();
    const fileName stateFile = timeDir/"uniform"/stateName;

    // A time written before (by an earlier run) is no longer complete
    if (isFile(stateFile, false) && !rm(stateFile))
    {
        FatalErrorInFunction
            << "Cannot remove " << stateFile << " before writing the time"
            << " anew: " << systemError().c_str() << nl << exit(FatalError);
    }

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
    if (!cloud.write())
    {
        FatalErrorInFunction
            << "Cannot write the cloud " << cloudName << " of time "
            << mesh.time().timeName() << ": " << systemError().c_str() << nl
            << exit(FatalError);
    }

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

    // The solver's fields (written as regIOobjects, checked below)
    for (const regIOobject* io : fields)
    {
        if (!io->write())
        {
            FatalErrorInFunction
                << "Cannot write " << io->objectPath() << ": "
                << systemError().c_str() << nl << exit(FatalError);
        }
    }

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
    dict.add("strain", sim.strain());
    dict.add("shearRate", sim.shearRate());

    // The files of the time, whole and on disk, with their digests
    dictionary files;
    for (const fileName& rel : committedFiles(timeDir, fields))
    {
        const fileName path = timeDir/rel;
        if (!endsWithDivider(path))
        {
            FatalErrorInFunction
                << "The file " << path << " was not written whole (it does"
                << " not end with OpenFOAM's end divider): is the disk full?"
                << nl << "    The time " << mesh.time().timeName() << " is"
                << " left without its " << stateName << ", so a restart does"
                << " not take it; the earlier times are intact" << nl
                << exit(FatalError);
        }
        dictionary listed;
        listed.add("size", string(std::to_string(fileSize(path))));
        listed.add("sha1", string(digestOf(path)));
        folderDict(files, rel).add(rel.name(), listed);
    }
    dict.add("files", files);
    syncToDisk(timeDir, true);

    // The commit: the state under a temporary name, on disk, renamed
    const fileName tmp = stateFile + ".tmp";
    writeAscii(dict, tmp);
    syncToDisk(tmp);
    if (::rename(tmp.c_str(), stateFile.c_str()) != 0)
    {
        FatalErrorInFunction
            << "Cannot rename " << tmp << " to " << stateFile << ": "
            << systemError().c_str() << nl << exit(FatalError);
    }
    syncToDisk(stateFile.path());
    syncToDisk(timeDir);
}


// ************************************************************************* //
