/*---------------------------------------------------------------------------*\
Description
    Fault injection for the case tests (suspensionFoamTest.sh), preloaded
    into a program with LD_PRELOAD: it counts the calls that put data on
    disk (write, writev, pwrite, fsync, syncfs, rename; writes to regular files other
    than standard output and error) and, as the environment asks,

        WSF_FAULT_KILL_AT=k    at the k-th call writes half of its bytes
                               (a torn write) and kills the process with
                               SIGKILL: a crash in the middle of a write
        WSF_FAULT_COUNT=file   at exit, writes the number of calls to file

    The program itself is not changed: this is what a kill -9 or a power
    cut at that moment leaves on disk.
\*---------------------------------------------------------------------------*/
#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace
{

std::atomic<long> calls{0};

long killAt()
{
    static const long k = []
    {
        const char* s = std::getenv("WSF_FAULT_KILL_AT");
        return s ? std::atol(s) : 0L;
    }();
    return k;
}

bool onDisk(int fd)
{
    struct stat st;
    return fd > 2 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
}

//- Count a call; whether it is the one to tear
bool tear()
{
    return ++calls == killAt();
}

template<class F>
F next(const char* name)
{
    return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}

struct Report
{
    ~Report()
    {
        if (const char* file = std::getenv("WSF_FAULT_COUNT"))
        {
            if (FILE* f = std::fopen(file, "w"))
            {
                std::fprintf(f, "%ld\n", calls.load());
                std::fclose(f);
            }
        }
    }
} report;

} // End anonymous namespace


extern "C"
{

ssize_t write(int fd, const void* buf, size_t n)
{
    static const auto real = next<ssize_t (*)(int, const void*, size_t)>("write");
    if (onDisk(fd) && tear())
    {
        real(fd, buf, n/2);
        raise(SIGKILL);
    }
    return real(fd, buf, n);
}

ssize_t pwrite(int fd, const void* buf, size_t n, off_t offset)
{
    static const auto real =
        next<ssize_t (*)(int, const void*, size_t, off_t)>("pwrite");
    if (onDisk(fd) && tear())
    {
        real(fd, buf, n/2, offset);
        raise(SIGKILL);
    }
    return real(fd, buf, n, offset);
}

ssize_t writev(int fd, const struct iovec* iov, int count)
{
    static const auto real =
        next<ssize_t (*)(int, const struct iovec*, int)>("writev");
    if (onDisk(fd) && tear())
    {
        if (count > 0)
        {
            static const auto realWrite =
                next<ssize_t (*)(int, const void*, size_t)>("write");
            realWrite(fd, iov[0].iov_base, iov[0].iov_len/2);
        }
        raise(SIGKILL);
    }
    return real(fd, iov, count);
}

int fsync(int fd)
{
    static const auto real = next<int (*)(int)>("fsync");
    if (tear())
    {
        raise(SIGKILL);
    }
    return real(fd);
}

int syncfs(int fd)
{
    static const auto real = next<int (*)(int)>("syncfs");
    if (tear())
    {
        raise(SIGKILL);
    }
    return real(fd);
}

int rename(const char* from, const char* to)
{
    static const auto real = next<int (*)(const char*, const char*)>("rename");
    if (tear())
    {
        raise(SIGKILL);
    }
    return real(from, to);
}

} // extern "C"
