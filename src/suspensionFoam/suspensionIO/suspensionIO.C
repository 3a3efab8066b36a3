#include "suspensionIO.H"
#include "inputChecks.H"
#include "ambientFlowAdapter.H"
#include "passiveParticleCloud.H"
#include "IOField.H"
#include "CompactIOField.H"
#include "labelFieldIOField.H"
#include "vectorFieldIOField.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
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
#include <filesystem>
#include <fstream>
#include <functional>
#include <unordered_map>
#include <utility>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::suspensionIO::cloudName("suspension");
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


//- The contact history of a time written before it was part of the cloud
const word legacyContacts("suspensionContacts");

IOobject legacyContactFile(const fvMesh& mesh, const word& name)
{
    return timeFile(mesh, cloud::prefix/legacyContacts, name, IOobject::MUST_READ);
}


//- The processor q of a time directory processor<q>/<time>; -1 for one of
//  the whole case
label processorOf(const fileName& timeDir)
{
    const word dir = timeDir.path().name();
    label q = -1;
    if
    (
        dir.size() > 9 && dir.compare(0, 9, "processor") == 0
     && !readLabel(dir.substr(9), q)
    )
    {
        q = -1;
    }
    return q;
}


//- The note of the cloud's centres that ties them to the state of the
//  same write (a state copied by decomposePar or reconstructPar finds
//  files those tools wrote, without it)
string writerNote(const string& writer)
{
    return "written with the suspensionState of writer " + writer;
}


//- Whether the header of file `path` (compressed or not) holds `text`
bool headerHolds(const fileName& path, const std::string& text)
{
    const fileName file = isFile(path, false) ? path : fileName(path + ".gz");
    if (!isFile(file, false))
    {
        return false;
    }
    IFstream is(file.hasExt("gz") ? file.lessExt() : file);
    std::string head(4096, ' ');
    is.stdStream().read(&head[0], head.size());
    head.resize(std::size_t(is.stdStream().gcount()));
    const std::size_t end = head.find("}");
    return head.substr(0, end).find(text) != std::string::npos;
}


//- Read a field of type Fld (an IOField, or a CompactIOField of one list
//  per entry) that must hold n entries, as `source` does
template<class Fld>
Fld readSized(const IOobject& io, const label n, const fileName& source)
{
    Fld fld(io);
    if (fld.size() != n)
    {
        FatalIOErrorInFunction(fld.objectPath())
            << "File " << fld.objectPath() << " holds " << fld.size()
            << " entries, but " << source << " gives " << n
            << " for time " << io.instance() << nl
            << exit(FatalIOError);
    }
    return fld;
}


template<class Type>
Field<Type> readField(const IOobject& io, const label n, const fileName& source)
{
    IOField<Type> fld(readSized<IOField<Type>>(io, n, source));
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
    const fileName& source
)
{
    IOobject probe(io);
    if (!probe.typeHeaderOk<IOField<Type>>(true))
    {
        return Field<Type>(n, Zero);
    }
    return readField<Type>(io, n, source);
}


//- The processes hold `total` of `what` in all, as the state gives
//  (collective); else a FatalIOError naming the state file
void checkTotal
(
    const label n,
    const label total,
    const word& what,
    const suspensionIO::state& s
)
{
    const label sum = returnReduce(n, sumOp<label>());
    if (sum != total)
    {
        FatalIOErrorInFunction(s.file)
            << "The cloud " << suspensionIO::cloudName << " holds " << sum
            << " " << what << (Pstream::parRun() ? " on all processors" : "")
            << ", but " << s.file << " gives " << total << nl
            << exit(FatalIOError);
    }
}


//- Why the last system call failed
std::string systemError()
{
    return errno ? std::strerror(errno) : "unknown error";
}


//- Write io to the file `path` (its objectPath() unless given) as
//  regIOobject::writeObject does (its data as `data` writes it, if given),
//  but flushed and checked before the stream closes: a short write (a full
//  disk, a file size limit) is a FatalError naming the file
void writeChecked
(
    const regIOobject& io,
    const IOstream::streamFormat fmt,
    const IOstream::compressionType cmp,
    const fileName& path = fileName::null,
    const std::function<bool(Ostream&)>& data = nullptr
)
{
    const fileName file = path.empty() ? io.objectPath() : path;
    mkDir(file.path());
    errno = 0;
    bool ok;
    {
        OFstream os(file, fmt, IOstream::currentVersion, cmp);
        ok =
            os.good() && io.writeHeader(os)
         && (data ? data(os) : io.writeData(os));
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


//- Write a field of one list per entry in the compact form (the offsets
//  of the lists, then their values) in either format: what decomposePar
//  and reconstructPar read as a CompactIOField (CompactIOField's own
//  writeObject writes ascii as a list of lists, which reconstructPar
//  leaves out)
template<class Type>
void writeFieldField(const IOobject& io, const Field<Field<Type>>& values)
{
    const Time& runTime = io.time();
    const CompactIOField<Field<Type>, Type> header(io, label(0));
    writeChecked
    (
        header, runTime.writeFormat(), runTime.writeCompression(),
        fileName::null,
        [&](Ostream& os)
        {
            labelList start(values.size() + 1, Zero);
            forAll(values, i)
            {
                start[i + 1] = start[i] + values[i].size();
            }
            Field<Type> elems(start.last());
            label k = 0;
            for (const Field<Type>& v : values)
            {
                for (const Type& e : v)
                {
                    elems[k++] = e;
                }
            }
            os << start << elems;
            return os.good();
        }
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
//  itself or its temporary), of the cloud, and of the cloud's properties
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


//- The files of the cloud a time needs: those a state that cannot vouch
//  for them by digests (written before the digests, or not in this
//  directory) is taken as complete with
bool cloudFilesFound(const fileName& timeDir, string& missing)
{
    const fileName cloudDir = timeDir/cloud::prefix/suspensionIO::cloudName;
    const fileName legacyDir = timeDir/cloud::prefix/legacyContacts;
    DynamicList<fileName> files;
    for (const char* f : {"x", "d", "U", "omega", "F", "T", "origId"})
    {
        files.append(cloudDir/f);
    }
    if (isDir(legacyDir))
    {
        for (const char* f : {"idI", "idJ", "xiT", "xiR"})
        {
            files.append(legacyDir/f);
        }
    }
    else
    {
        for (const char* f : {"contactId", "contactXiT", "contactXiR"})
        {
            files.append(cloudDir/f);
        }
    }
    for (const fileName& f : files)
    {
        if (!isFile(f))
        {
            missing = f;
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
     || isDir(timeDir/cloud::prefix/legacyContacts);
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

    // The state of this directory, or one decomposePar or reconstructPar
    // copied here, whose digests are those of another directory's files:
    // the centres it was written with carry its writer (a state written
    // before the writers: the processor it names)
    const label writtenBy = state.getOrDefault<label>("processor", -1);
    const string writer = state.getOrDefault<string>("writer", string::null);
    const bool own =
        writer.empty()
      ? writtenBy == processorOf(timeDir)
      : headerHolds
        (
            timeDir/cloud::prefix/suspensionIO::cloudName/"x",
            writerNote(writer)
        );
    const dictionary* files = state.findDict("files");
    if (!files || !own)
    {
        string missing;
        if (!cloudFilesFound(timeDir, missing))
        {
            return {stored::incomplete, "no " + missing};
        }
        return
        {
            stored::complete,
            files
          ? "the state of "
          + (writtenBy < 0 ? word("the whole case") : "processor" + Foam::name(writtenBy))
          + ", decomposed or reconstructed: its files are counted, not verified"
          : "written before the files' digests: not verified",
            bool(files)
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
    // The times of this process's case (processor<q> in a parallel run),
    // the controls of the whole case
    const fileName casePath = args.path();
    const fileName controlFile = args.globalPath()/"system"/"controlDict";
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
        // In a parallel run, the latest time complete on every processor:
        // each takes the earliest of their latest, until they agree
        label latest = latestComplete(times.size() - 1);
        const scalar none = -VGREAT;
        const auto value = [&](const label i)
        {
            return i < 0 ? none : times[i].value();
        };
        if (returnReduce(value(latest), maxOp<scalar>()) == none)
        {
            return;     // the cloud says what the start time holds
        }
        for (;;)
        {
            const scalar common = returnReduce(value(latest), minOp<scalar>());
            if (common == none)
            {
                FatalErrorInFunction
                    << "A processor of " << args.globalPath() << " holds no"
                    << " complete time that the others hold: decompose a"
                    << " complete time of the whole case again (decomposePar)"
                    << nl << exit(FatalError);
            }
            while (value(latest) > common)
            {
                latest = latestComplete(latest - 1);
            }
            if (returnReduce(value(latest) == common, andOp<bool>()))
            {
                break;
            }
        }
        for (label i = times.size() - 1; i > latest; --i)
        {
            const fileName dir = dirOf(i);
            stored s = check(dir);
            if (s.state == stored::complete)
            {
                s.reason = "complete here, not on every processor";
            }
            else if (s.state == stored::absent)
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
            // (in a parallel run each process says why of its own)
            OStringStream line;
            line<< "Time " << times[i].name() << " is incomplete ("
                << s.reason.c_str() << "): moved to " << aside.name()
                << " (nothing deleted); starting from "
                << times[latest].name() << ", the latest complete time";
            if (Pstream::parRun())
            {
                Pout<< line.str().c_str() << nl << endl;
            }
            else
            {
                Info<< line.str().c_str() << nl << endl;
            }
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
            "strain", "shearRate", "processors", "processor", "writer", "files"
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
    // The processes of a parallel run hold the state of one suspension
    if (Pstream::parRun())
    {
        scalarList lo
        ({
            s.time, scalar(s.steps), scalar(s.nParticles), scalar(s.nContacts),
            s.box.x(), s.box.y(), s.box.z(), s.offset, s.strain, s.shearRate
        });
        scalarList hi(lo);
        const scalarList mine(lo);
        Pstream::listCombineGather(lo, minEqOp<scalar>());
        Pstream::listCombineScatter(lo);
        Pstream::listCombineGather(hi, maxEqOp<scalar>());
        Pstream::listCombineScatter(hi);
        if (lo != hi)
        {
            FatalIOErrorInFunction(dict)
                << "The state " << s.file << " (time, steps, nParticles,"
                << " nContacts, box, offset, strain, shearRate: " << mine
                << ") is not that of the other processors, which range from "
                << lo << " to " << hi << ": their directories come from"
                << " different runs. Decompose a time of the whole case"
                << " again (decomposePar)" << nl << exit(FatalIOError);
        }
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
    const auto read = [&](const word& name)
    {
        return particleFile(mesh, name, IOobject::MUST_READ);
    };
    const vectorField x(IOField<vector>(read("x")));
    const label n = x.size();
    checkTotal(n, s.nParticles, "particles", s);
    const fileName source = read("x").objectPath();
    const scalarField d(readField<scalar>(read("d"), n, source));
    const vectorField U(readField<vector>(read("U"), n, source));
    const vectorField omega(readField<vector>(read("omega"), n, source));
    const vectorField F(readField<vector>(read("F"), n, source));
    const vectorField T(readField<vector>(read("T"), n, source));
    const vectorField dUdt(readFieldOrZero<vector>(read("dUdt"), n, source));
    const vectorField dOmegadt(readFieldOrZero<vector>(read("dOmegadt"), n, source));
    const labelField id(readField<label>(read("origId"), n, source));

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


namespace
{

//- A contact (I, J) of file `file` as the engine keys it: lower id first,
//  the stretches oriented from it (reversed: negated); its stretches
//  finite and I, J distinct, else a FatalIOError naming the file
suspension::KeyedContact keyed
(
    const label I,
    const label J,
    const vector& xiT,
    const vector& xiR,
    const fileName& file
)
{
    for (const vector& v : {xiT, xiR})
    {
        if (!std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z()))
        {
            FatalIOErrorInFunction(file)
                << "The contact of particles " << I << " and " << J << " in "
                << file << " has the stretches " << xiT << ", " << xiR
                << "; they must be finite" << nl << exit(FatalIOError);
        }
    }
    if (I == J)
    {
        FatalIOErrorInFunction(file)
            << "A contact in " << file << " pairs particle " << I
            << " with itself" << nl << exit(FatalIOError);
    }
    const scalar sign = I < J ? 1 : -1;
    return
    {
        min(I, J), max(I, J),
        suspension::ContactState{toEigen(sign*xiT), toEigen(sign*xiR)}
    };
}


//- The contacts of a time written before they were part of the cloud
std::vector<suspension::KeyedContact> readLegacyContacts
(
    const fvMesh& mesh,
    const suspensionIO::state& s
)
{
    const auto read = [&](const word& name)
    {
        return legacyContactFile(mesh, name);
    };
    const label n = s.nContacts;
    const labelField idI(readField<label>(read("idI"), n, s.file));
    const labelField idJ(readField<label>(read("idJ"), n, s.file));
    const vectorField xiT(readField<vector>(read("xiT"), n, s.file));
    const vectorField xiR(readField<vector>(read("xiR"), n, s.file));
    std::vector<suspension::KeyedContact> contacts;
    forAll(idI, k)
    {
        contacts.push_back
        (
            keyed(idI[k], idJ[k], xiT[k], xiR[k], read("xiT").objectPath())
        );
    }
    return contacts;
}

} // End anonymous namespace


std::vector<suspension::KeyedContact> Foam::suspensionIO::readContacts
(
    const fvMesh& mesh,
    const state& s,
    const suspension::Particles& p
)
{
    const auto read = [&](const word& name)
    {
        return particleFile(mesh, name, IOobject::MUST_READ);
    };
    const fileName idFile = read("contactId").objectPath();
    std::vector<suspension::KeyedContact> contacts;
    if (!isFile(idFile) && isDir(mesh.time().timePath()/cloud::prefix/legacyContacts))
    {
        contacts = readLegacyContacts(mesh, s);
    }
    else
    {
        const label n = label(p.size());
        const fileName source = read("x").objectPath();
        const labelFieldCompactIOField partner
        (
            readSized<labelFieldCompactIOField>(read("contactId"), n, source)
        );
        const vectorFieldCompactIOField xiT
        (
            readSized<vectorFieldCompactIOField>(read("contactXiT"), n, source)
        );
        const vectorFieldCompactIOField xiR
        (
            readSized<vectorFieldCompactIOField>(read("contactXiR"), n, source)
        );
        forAll(partner, i)
        {
            const label I = label(p.id[i]);
            if (xiT[i].size() != partner[i].size() || xiR[i].size() != partner[i].size())
            {
                FatalIOErrorInFunction(xiT.objectPath())
                    << "Particle " << i << " (origId " << I << ") has "
                    << partner[i].size() << " contacts in " << idFile
                    << " but " << xiT[i].size() << " and " << xiR[i].size()
                    << " stretches in " << xiT.objectPath() << " and "
                    << xiR.objectPath() << nl << exit(FatalIOError);
            }
            forAll(partner[i], k)
            {
                if (partner[i][k] < I)
                {
                    FatalIOErrorInFunction(idFile)
                        << "Particle " << i << " (origId " << I << ") carries"
                        << " a contact with particle " << partner[i][k]
                        << " of a lower id; a contact is carried by the"
                        << " lower id of its pair" << nl << exit(FatalIOError);
                }
                contacts.push_back
                (
                    keyed(I, partner[i][k], xiT[i][k], xiR[i][k], idFile)
                );
            }
        }
    }
    checkTotal(label(contacts.size()), s.nContacts, "contacts", s);

    std::sort(contacts.begin(), contacts.end());
    for (std::size_t k = 1; k < contacts.size(); ++k)
    {
        if (!(contacts[k - 1] < contacts[k]))
        {
            FatalIOErrorInFunction(idFile)
                << "The pair (" << contacts[k].lo << ", " << contacts[k].hi
                << ") holds two contact histories" << nl << exit(FatalIOError);
        }
    }

    // The partners are here in a serial run (in a parallel one, on any
    // process)
    if (!Pstream::parRun())
    {
        std::unordered_map<std::int64_t, bool> held;
        for (const std::int64_t id : p.id)
        {
            held.emplace(id, true);
        }
        for (const suspension::KeyedContact& c : contacts)
        {
            for (const std::int64_t id : {c.lo, c.hi})
            {
                if (!held.count(id))
                {
                    FatalIOErrorInFunction(idFile)
                        << "A contact names the particle " << label(id)
                        << ", which the cloud " << cloudName << " does not"
                        << " hold" << nl << exit(FatalIOError);
                }
            }
        }
    }
    return contacts;
}


Foam::labelList Foam::suspensionIO::findCells
(
    const polyMesh& mesh,
    const suspension::Particles& p
)
{
    labelList cells(label(p.size()), -1);
    forAll(cells, i)
    {
        if (p.isGhost(i))
        {
            continue;
        }
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

    // decomposePar links a processor's uniform to the case's (without
    // -copyUniform): this processor's state goes in a folder of its own
    try
    {
        namespace fs = std::filesystem;
        const fs::path uniform(std::string(timeDir/"uniform"));
        if (fs::is_symlink(uniform))
        {
            const fs::path copy(uniform.string() + ".copy");
            fs::remove_all(copy);
            fs::copy(fs::canonical(uniform), copy, fs::copy_options::recursive);
            fs::remove(uniform);
            fs::rename(copy, uniform);
        }
    }
    catch (const std::filesystem::filesystem_error& err)
    {
        FatalErrorInFunction
            << "Cannot make " << timeDir/"uniform" << " (a link to the"
            << " case's) a folder of its own: " << err.what() << nl
            << exit(FatalError);
    }

    // A time written before (by an earlier run) is no longer complete
    if (isFile(stateFile, false) && !rm(stateFile))
    {
        FatalErrorInFunction
            << "Cannot remove " << stateFile << " before writing the time"
            << " anew: " << systemError().c_str() << nl << exit(FatalError);
    }

    // The particles this process owns (all, in a serial run), in the
    // engine's order
    DynamicList<label> owned(label(p.size()));
    std::unordered_map<std::int64_t, label> entryOf;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (!p.isGhost(i))
        {
            entryOf.emplace(p.id[i], owned.size());
            owned.append(label(i));
        }
    }
    const label n = owned.size();

    // The cloud: positions (for ParaView), coordinates, origId
    passiveParticleCloud cloud(mesh, cloudName, IDLList<passiveParticle>());
    for (const label i : owned)
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
    passiveParticle::particleCount_ = returnReduce(nextId, maxOp<label>());
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
    // (an empty cloud writes no particle fields of its own)
    if (n == 0)
    {
        writeField(particleOut("origId"), labelField());
    }
    const auto ownedField = [&](const std::vector<Vec3>& v)
    {
        vectorField f(n);
        forAll(f, k)
        {
            f[k] = Foam::toFoam(v[owned[k]]);
        }
        return f;
    };
    scalarField d(n);
    symmTensorField Sp(n);
    forAll(d, k)
    {
        d[k] = 2*p.a[owned[k]];
        Sp[k] = symm(Foam::toFoam(S[owned[k]]));
    }
    // The writer of this time (the processor, the time and the step), tied
    // to its centres by their note
    const string writer = SHA1
    (
        Foam::name(processorOf(timeDir)) + " " + timeDir.name() + " "
      + std::to_string(steps)
    ).digest().str().substr(0, 16);
    IOobject xOut(particleOut("x"));
    xOut.note() = writerNote(writer);
    writeField(xOut, ownedField(p.x));
    writeField(particleOut("d"), d);
    writeField(particleOut("U"), ownedField(p.u));
    writeField(particleOut("omega"), ownedField(p.omega));
    writeField(particleOut("F"), ownedField(p.F));
    writeField(particleOut("T"), ownedField(p.T));
    writeField(particleOut("dUdt"), ownedField(p.dudt));
    writeField(particleOut("dOmegadt"), ownedField(p.domegadt));
    writeField(particleOut("S"), Sp);

    // The contact history, each contact with the particle of its lower id
    const std::vector<suspension::KeyedContact> contacts =
        suspension::NeighbourSearch::contacts(p, sim.pairs());
    labelList nCarried(n, Zero);
    for (const suspension::KeyedContact& c : contacts)
    {
        ++nCarried[entryOf.at(c.lo)];
    }
    Field<labelField> partner(n);
    Field<vectorField> xiT(n);
    Field<vectorField> xiR(n);
    forAll(nCarried, k)
    {
        partner[k].setSize(nCarried[k]);
        xiT[k].setSize(nCarried[k]);
        xiR[k].setSize(nCarried[k]);
        nCarried[k] = 0;
    }
    for (const suspension::KeyedContact& c : contacts)
    {
        const label k = entryOf.at(c.lo);
        const label m = nCarried[k]++;
        partner[k][m] = label(c.hi);
        xiT[k][m] = toFoam(c.state.xiT);
        xiR[k][m] = toFoam(c.state.xiR);
    }
    writeFieldField(particleOut("contactId"), partner);
    writeFieldField(particleOut("contactXiT"), xiT);
    writeFieldField(particleOut("contactXiR"), xiR);

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
    dict.add("nParticles", returnReduce(n, sumOp<label>()));
    dict.add("nContacts", returnReduce(label(contacts.size()), sumOp<label>()));
    dict.add("box", toFoam(sim.box().L()));
    dict.add("offset", sim.box().offset());
    dict.add("strain", sim.strain());
    dict.add("shearRate", sim.shearRate());
    dict.add("writer", writer);     // (a string: it may start with a digit)
    if (Pstream::parRun())
    {
        dict.add("processors", Pstream::nProcs());
        dict.add("processor", Pstream::myProcNo());
    }

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
