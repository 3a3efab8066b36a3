#include "decomposition/Domain.H"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>

namespace suspension
{

namespace
{
    using Buffer = Communicator::Buffer;

    template<class T>
    void put(Buffer& b, const T& v)
    {
        static_assert(std::is_arithmetic_v<T>);
        const std::size_t n = b.size();
        b.resize(n + sizeof(T));
        std::memcpy(b.data() + n, &v, sizeof(T));
    }

    void put(Buffer& b, const Vec3& v)
    {
        put(b, v.x());
        put(b, v.y());
        put(b, v.z());
    }

    void put(Buffer& b, const KeyedContact& c)
    {
        put(b, c.lo);
        put(b, c.hi);
        put(b, c.state.xiT);
        put(b, c.state.xiR);
    }

    template<class T>
    T get(const Buffer& b, std::size_t& at)
    {
        if constexpr (std::is_same_v<T, Vec3>)
        {
            const double x = get<double>(b, at);
            const double y = get<double>(b, at);
            return Vec3(x, y, get<double>(b, at));
        }
        else if constexpr (std::is_same_v<T, KeyedContact>)
        {
            KeyedContact c;
            c.lo = get<std::int64_t>(b, at);
            c.hi = get<std::int64_t>(b, at);
            c.state.xiT = get<Vec3>(b, at);
            c.state.xiR = get<Vec3>(b, at);
            return c;
        }
        else
        {
            static_assert(std::is_arithmetic_v<T>);
            if (at + sizeof(T) > b.size())
            {
                throw std::logic_error("Domain: a message ends early");
            }
            T v;
            std::memcpy(&v, b.data() + at, sizeof(T));
            at += sizeof(T);
            return v;
        }
    }

    //- The contacts carried by particle `id`: the range of `contacts`
    //  (sorted) with lo == id
    std::pair<std::size_t, std::size_t> carriedBy
    (
        const std::vector<KeyedContact>& contacts,
        std::int64_t id
    )
    {
        const KeyedContact key{id, std::numeric_limits<std::int64_t>::min(), {}};
        const auto first =
            std::lower_bound(contacts.begin(), contacts.end(), key);
        auto last = first;
        while (last != contacts.end() && last->lo == id)
        {
            ++last;
        }
        return {std::size_t(first - contacts.begin()), std::size_t(last - contacts.begin())};
    }

    //- Particle i with the contacts it carries
    void putParticle
    (
        Buffer& b,
        const Particles& p,
        std::size_t i,
        const std::vector<KeyedContact>& contacts
    )
    {
        put(b, p.id[i]);
        put(b, p.x[i]);
        put(b, p.u[i]);
        put(b, p.omega[i]);
        put(b, p.F[i]);
        put(b, p.T[i]);
        put(b, p.dudt[i]);
        put(b, p.domegadt[i]);
        put(b, p.a[i]);
        put(b, p.m[i]);
        put(b, p.I[i]);
        const auto [first, last] = carriedBy(contacts, p.id[i]);
        put(b, std::uint64_t(last - first));
        for (std::size_t c = first; c < last; ++c)
        {
            put(b, contacts[c]);
        }
    }

    //- Append a particle of a message to p and its contacts to contacts
    std::int64_t getParticle
    (
        const Buffer& b,
        std::size_t& at,
        Particles& p,
        std::uint8_t ghost,
        std::vector<KeyedContact>& contacts
    )
    {
        const std::int64_t id = get<std::int64_t>(b, at);
        p.id.push_back(id);
        p.x.push_back(get<Vec3>(b, at));
        p.u.push_back(get<Vec3>(b, at));
        p.omega.push_back(get<Vec3>(b, at));
        p.F.push_back(get<Vec3>(b, at));
        p.T.push_back(get<Vec3>(b, at));
        p.dudt.push_back(get<Vec3>(b, at));
        p.domegadt.push_back(get<Vec3>(b, at));
        p.a.push_back(get<double>(b, at));
        p.m.push_back(get<double>(b, at));
        p.I.push_back(get<double>(b, at));
        p.ghost.push_back(ghost);
        const std::uint64_t n = get<std::uint64_t>(b, at);
        for (std::uint64_t c = 0; c < n; ++c)
        {
            contacts.push_back(get<KeyedContact>(b, at));
        }
        return id;
    }

    //- Keep the particles i with keep[i]
    void compact(Particles& p, const std::vector<bool>& keep)
    {
        std::vector<std::size_t> order;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            if (keep[i])
            {
                order.push_back(i);
            }
        }
        p.permute(order);
    }

    //- Periodic distance of y from [lo, hi) on a circle of length L
    double distance(double y, double lo, double hi, double L)
    {
        if (y >= lo && y < hi)
        {
            return 0;
        }
        const double below = std::fmod(lo - y + L, L);
        const double above = std::fmod(y - hi + L, L);
        return std::min(below, above);
    }
}


Domain::Domain(const Communicator& comm, const Layout& layout, const Vec3& L)
:
    comm_(comm),
    layout_(layout),
    L_(L),
    sendIds_(comm.size()),
    receiveIds_(comm.size()),
    sendIndex_(comm.size()),
    receiveIndex_(comm.size())
{
    if (!(layout.ny > 0 && layout.nz > 0) || layout.ny*layout.nz != comm.size())
    {
        throw std::invalid_argument
        (
            "Domain: a layout of " + std::to_string(layout.ny) + " x "
          + std::to_string(layout.nz) + " slabs (y x z) for "
          + std::to_string(comm.size()) + " processes; ny nz must be the"
            " number of processes"
        );
    }
}


void Domain::slab(int q, double lo[2], double hi[2]) const
{
    const int qy = q % layout_.ny;
    const int qz = q/layout_.ny;
    lo[0] = qy*L_.y()/layout_.ny;
    hi[0] = qy + 1 == layout_.ny ? L_.y() : (qy + 1)*L_.y()/layout_.ny;
    lo[1] = qz*L_.z()/layout_.nz;
    hi[1] = qz + 1 == layout_.nz ? L_.z() : (qz + 1)*L_.z()/layout_.nz;
}


bool Domain::within(const Vec3& x, int q, double range) const
{
    double lo[2], hi[2];
    slab(q, lo, hi);
    return distance(x.y(), lo[0], hi[0], L_.y()) < range
        && distance(x.z(), lo[1], hi[1], L_.z()) < range;
}


int Domain::owner(const Vec3& x) const
{
    // The slab whose [lo, hi) holds x, found as slab() computes the bounds
    auto index = [](double v, double L, int n)
    {
        int k = std::min(n - 1, std::max(0, static_cast<int>(v/L*n)));
        while (k > 0 && v < k*L/n) --k;
        while (k + 1 < n && v >= (k + 1)*L/n) ++k;
        return k;
    };
    return index(x.y(), L_.y(), layout_.ny)
         + layout_.ny*index(x.z(), L_.z(), layout_.nz);
}


void Domain::distribute
(
    Particles& p,
    std::vector<KeyedContact>& contacts,
    double range
)
{
    const int P = comm_.size();
    const int me = comm_.rank();
    std::sort(contacts.begin(), contacts.end());

    // 1. The owned particles only
    {
        std::vector<bool> keep(p.size());
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            keep[i] = !p.isGhost(i);
        }
        compact(p, keep);
        p.ghost.assign(p.size(), 0);
    }

    // 2. Migration
    std::vector<KeyedContact> kept;
    {
        std::vector<Buffer> send(P), receive;
        std::vector<bool> keep(p.size());
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            const int q = owner(p.x[i]);
            keep[i] = q == me;
            if (keep[i])
            {
                const auto [first, last] = carriedBy(contacts, p.id[i]);
                kept.insert(kept.end(), contacts.begin() + first, contacts.begin() + last);
            }
            else
            {
                putParticle(send[q], p, i, contacts);
            }
        }
        comm_.exchange(send, receive);
        compact(p, keep);
        for (int q = 0; q < P; ++q)
        {
            std::size_t at = 0;
            while (at < receive[q].size())
            {
                getParticle(receive[q], at, p, 0, kept);
            }
        }
        std::sort(kept.begin(), kept.end());
    }

    // 3. Ghosts, with the contacts their owners keep
    const std::size_t nOwned = p.size();
    contacts = kept;
    {
        std::vector<Buffer> send(P), receive;
        for (int q = 0; q < P; ++q)
        {
            sendIds_[q].clear();
            receiveIds_[q].clear();
            if (q == me)
            {
                continue;
            }
            for (std::size_t i = 0; i < nOwned; ++i)
            {
                if (within(p.x[i], q, range))
                {
                    putParticle(send[q], p, i, kept);
                    sendIds_[q].push_back(p.id[i]);
                }
            }
        }
        comm_.exchange(send, receive);
        for (int q = 0; q < P; ++q)
        {
            std::size_t at = 0;
            while (at < receive[q].size())
            {
                receiveIds_[q].push_back(getParticle(receive[q], at, p, 1, contacts));
            }
        }
    }
    std::sort(contacts.begin(), contacts.end());
    index(p);
}


void Domain::index(const Particles& p)
{
    std::unordered_map<std::int64_t, std::uint32_t> at;
    at.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        at.emplace(p.id[i], static_cast<std::uint32_t>(i));
    }
    auto map = [&](const std::vector<std::int64_t>& ids, std::vector<std::uint32_t>& index)
    {
        index.resize(ids.size());
        for (std::size_t k = 0; k < ids.size(); ++k)
        {
            index[k] = at.at(ids[k]);
        }
    };
    for (int q = 0; q < comm_.size(); ++q)
    {
        map(sendIds_[q], sendIndex_[q]);
        map(receiveIds_[q], receiveIndex_[q]);
    }
}


void Domain::refresh(std::vector<double*> fields, std::size_t width) const
{
    const int P = comm_.size();
    std::vector<Buffer> send(P), receive;
    for (int q = 0; q < P; ++q)
    {
        Buffer& b = send[q];
        b.reserve(sendIndex_[q].size()*fields.size()*width*sizeof(double));
        for (const std::uint32_t i : sendIndex_[q])
        {
            for (const double* f : fields)
            {
                for (std::size_t c = 0; c < width; ++c)
                {
                    put(b, f[i*width + c]);
                }
            }
        }
    }
    comm_.exchange(send, receive);
    for (int q = 0; q < P; ++q)
    {
        std::size_t at = 0;
        for (const std::uint32_t i : receiveIndex_[q])
        {
            for (double* f : fields)
            {
                for (std::size_t c = 0; c < width; ++c)
                {
                    f[i*width + c] = get<double>(receive[q], at);
                }
            }
        }
    }
}


void Domain::refresh(Particles& p) const
{
    auto entries = [](std::vector<Vec3>& v)
    {
        return reinterpret_cast<double*>(v.data());
    };
    static_assert(sizeof(Vec3) == 3*sizeof(double), "Vec3 is three doubles");
    refresh({entries(p.x), entries(p.u), entries(p.omega)}, 3);
}


void Domain::refresh(double* v, std::size_t width) const
{
    refresh(std::vector<double*>{v}, width);
}


void Domain::fillFromGhosts
(
    double* v,
    std::size_t width,
    std::vector<unsigned char>& known
) const
{
    const int P = comm_.size();
    std::vector<Buffer> send(P), receive;
    for (int q = 0; q < P; ++q)
    {
        const std::vector<std::uint32_t>& ghosts = receiveIndex_[q];
        for (std::uint32_t k = 0; k < ghosts.size(); ++k)
        {
            const std::uint32_t i = ghosts[k];
            if (known[i])
            {
                put(send[q], k);
                for (std::size_t c = 0; c < width; ++c)
                {
                    put(send[q], v[i*width + c]);
                }
            }
        }
    }
    comm_.exchange(send, receive);
    for (int q = 0; q < P; ++q)
    {
        std::size_t at = 0;
        while (at < receive[q].size())
        {
            const std::uint32_t k = get<std::uint32_t>(receive[q], at);
            const std::uint32_t i = sendIndex_[q].at(k);
            const bool take = !known[i];
            for (std::size_t c = 0; c < width; ++c)
            {
                const double value = get<double>(receive[q], at);
                if (take)
                {
                    v[i*width + c] = value;
                }
            }
            known[i] = 1;
        }
    }
}


std::size_t Domain::nGhosts() const
{
    std::size_t n = 0;
    for (const std::vector<std::int64_t>& ids : receiveIds_)
    {
        n += ids.size();
    }
    return n;
}


std::vector<double> Domain::distinctRadii(const std::vector<double>& a) const
{
    std::vector<double> distinct(a);
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    std::vector<Buffer> send(comm_.size()), receive;
    for (Buffer& b : send)
    {
        for (const double r : distinct)
        {
            put(b, r);
        }
    }
    comm_.exchange(send, receive);
    std::vector<double> all;
    for (const Buffer& b : receive)
    {
        std::size_t at = 0;
        while (at < b.size())
        {
            all.push_back(get<double>(b, at));
        }
    }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
}

} // namespace suspension
