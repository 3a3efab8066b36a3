#include "pstreamCommunicator.H"
#include "Pstream.H"
#include "PstreamBuffers.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include "scalarList.H"

#include <cstdint>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{
    //- The larger of two, NaN if either is
    struct largerOrNaN
    {
        void operator()(Foam::scalar& x, const Foam::scalar& y) const
        {
            x = (x != x || y != y) ? x + y : (x < y ? y : x);
        }
    };

    template<class CombineOp>
    void combine(double* v, std::size_t n, const CombineOp& op)
    {
        if (!Foam::Pstream::parRun())
        {
            return;
        }
        Foam::scalarList values(static_cast<Foam::label>(n));
        std::copy(v, v + n, values.begin());
        Foam::Pstream::listCombineGather(values, op);
        Foam::Pstream::listCombineScatter(values);
        std::copy(values.begin(), values.end(), v);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

int Foam::pstreamCommunicator::rank() const
{
    return Pstream::parRun() ? Pstream::myProcNo() : 0;
}


int Foam::pstreamCommunicator::size() const
{
    return Pstream::parRun() ? Pstream::nProcs() : 1;
}


void Foam::pstreamCommunicator::sum(double* v, std::size_t n) const
{
    combine(v, n, plusEqOp<scalar>());
}


void Foam::pstreamCommunicator::max(double* v, std::size_t n) const
{
    combine(v, n, largerOrNaN());
}


void Foam::pstreamCommunicator::exchange
(
    const std::vector<Buffer>& send,
    std::vector<Buffer>& receive
) const
{
    const int P = size();
    if (int(send.size()) != P)
    {
        FatalErrorInFunction
            << "one buffer per process expected, got " << label(send.size())
            << " for " << P << " processes" << abort(FatalError);
    }
    receive.assign(P, Buffer());
    const int me = rank();
    receive[me] = send[me];
    if (P == 1)
    {
        return;
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    for (int q = 0; q < P; ++q)
    {
        if (q != me && !send[q].empty())
        {
            UOPstream os(q, buffers);
            const std::uint64_t n = send[q].size();
            os.write(reinterpret_cast<const char*>(&n), sizeof(n));
            os.write(send[q].data(), std::streamsize(n));
        }
    }
    labelList sizes;
    buffers.finishedSends(sizes);
    for (int q = 0; q < P; ++q)
    {
        if (q != me && sizes[q] > 0)
        {
            UIPstream is(q, buffers);
            std::uint64_t n = 0;
            is.read(reinterpret_cast<char*>(&n), sizeof(n));
            receive[q].resize(n);
            is.read(receive[q].data(), std::streamsize(n));
        }
    }
}


// ************************************************************************* //
