#include "search/NeighbourSearch.H"

#include "core/Memory.H"
#include "core/Parallel.H"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace suspension
{

namespace
{
    using Contact = KeyedContact;

    //- Throws unless `list` is empty or a consistent list of the particles
    void checkList(const Particles& p, const PairList& list)
    {
        const bool empty = list.offset.empty() && list.j.empty();
        const bool consistent =
            !list.offset.empty()
         && list.nParticles() == p.size()
         && list.offset.back() == list.j.size()
         && list.contactOf.size() == list.j.size();
        if (!empty && !consistent)
        {
            throw std::invalid_argument
            (
                "NeighbourSearch: the PairList (" + std::to_string(list.nParticles())
              + " particles, " + std::to_string(list.nPairs()) + " pairs, "
              + std::to_string(list.contactOf.size()) + " history slots) does not"
                " belong to these " + std::to_string(p.size()) + " particles"
            );
        }
    }
}


std::vector<KeyedContact> NeighbourSearch::contacts
(
    const Particles& p,
    const PairList& list
)
{
    std::vector<KeyedContact> contacts;
    for (std::size_t i = 0; i < list.nParticles(); ++i)
    {
        for (std::size_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
        {
            const ContactState& s = list.history(k);
            if (s.active() && p.countsPair(i, list.j[k]))
            {
                const std::int64_t a = p.id[i];
                const std::int64_t b = p.id[list.j[k]];
                contacts.push_back
                (
                    a < b ? Contact{a, b, s} : Contact{b, a, s.reversed()}
                );
            }
        }
    }
    std::sort(contacts.begin(), contacts.end());
    for (std::size_t c = 1; c < contacts.size(); ++c)
    {
        if (!(contacts[c - 1] < contacts[c]))
        {
            throw std::logic_error
            (
                "NeighbourSearch: pair of ids ("
              + std::to_string(contacts[c].lo) + ", "
              + std::to_string(contacts[c].hi) + ") holds two contact"
                " histories; particle ids must be unique"
            );
        }
    }
    return contacts;
}


namespace
{
    //- Give each slot of the new list the history of its pair; returns the
    //  number of contacts carried
    std::size_t restoreContacts
    (
        const std::vector<Contact>& contacts,
        const Particles& p,
        PairList& list
    )
    {
        std::size_t carried = 0;
        if (contacts.empty())
        {
            return carried;
        }
        for (std::size_t i = 0; i < list.nParticles(); ++i)
        {
            for (std::size_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
            {
                const std::int64_t a = p.id[i];
                const std::int64_t b = p.id[list.j[k]];
                const Contact key{std::min(a, b), std::max(a, b), ContactState()};
                const auto it =
                    std::lower_bound(contacts.begin(), contacts.end(), key);
                if (it != contacts.end() && it->lo == key.lo && it->hi == key.hi)
                {
                    list.setHistory(k, a < b ? it->state : it->state.reversed());
                    carried += p.countsPair(i, list.j[k]);
                }
            }
        }
        return carried;
    }

    //- How many of the contacts have their carrier, lo, owned here
    std::size_t carriedHere
    (
        const Particles& p,
        const std::vector<KeyedContact>& contacts
    )
    {
        if (p.ghost.empty())
        {
            return contacts.size();
        }
        std::vector<std::int64_t> ghosts;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            if (p.ghost[i]) ghosts.push_back(p.id[i]);
        }
        std::sort(ghosts.begin(), ghosts.end());
        std::size_t n = 0;
        for (const KeyedContact& c : contacts)
        {
            n += !std::binary_search(ghosts.begin(), ghosts.end(), c.lo);
        }
        return n;
    }

    //- The rows (offsets, entries: the partners) compacted to the entries
    //  (i, j) with keep(i, j), in order
    template<class Keep>
    void compactRows
    (
        std::vector<std::uint32_t>& offset,
        std::vector<std::uint32_t>& entries,
        Keep keep
    )
    {
        std::uint32_t n = 0;
        std::uint32_t begin = 0;
        for (std::size_t i = 0; i + 1 < offset.size(); ++i)
        {
            const std::uint32_t end = offset[i + 1];
            for (std::uint32_t k = begin; k < end; ++k)
            {
                if (keep(i, entries[k]))
                {
                    entries[n++] = entries[k];
                }
            }
            begin = end;
            offset[i + 1] = n;
        }
        entries.resize(n);
    }

    //- Without the pairs of two ghosts (decomposition/Domain.H): nothing
    //  of theirs is kept
    void dropGhostPairs(const Particles& p, PairList& half)
    {
        if (!p.ghost.empty())
        {
            compactRows(half.offset, half.j, [&p](std::size_t i, std::uint32_t j)
            {
                return !(p.ghost[i] && p.ghost[j]);
            });
        }
    }

    //- The far rows without the ghosts' own rows (decomposition/Domain.H):
    //  a ghost's row is its owner's, summed there; the far list keeps no
    //  slots, so the partners alone are compacted
    void dropGhostRows(const Particles& p, PairRows& rows)
    {
        if (!p.ghost.empty())
        {
            compactRows(rows.offset, rows.partner, [&p](std::size_t i, std::uint32_t)
            {
                return !p.ghost[i];
            });
        }
    }

    //- The slots of the half list `all` with |r| < a_i + a_j + gap, into
    //  the half list `near`
    void nearPairs
    (
        const Particles& p,
        const LeesEdwardsBox& box,
        const PairList& all,
        double gap,
        PairList& near
    )
    {
        const std::size_t N = all.nParticles();
        near = PairList();
        near.offset.assign(N + 1, 0);
        for (std::size_t i = 0; i < N; ++i)
        {
            for (std::uint32_t k = all.offset[i]; k < all.offset[i + 1]; ++k)
            {
                const std::uint32_t j = all.j[k];
                Vec3 r = p.x[j] - p.x[i];
                box.minimumImage(r);
                const double R = p.a[i] + p.a[j] + gap;
                if (r.squaredNorm() < R*R)
                {
                    near.j.push_back(j);
                }
            }
            near.offset[i + 1] = static_cast<std::uint32_t>(near.j.size());
        }
    }
}


NeighbourSearch::NeighbourSearch(const Params& params)
:
    params_(params),
    cells_(),
    path_(),
    maxPath_(0),
    time_(0),
    flowStrain_(0),
    range_(0),
    stats_()
{
    if
    (
        !(params.gap >= 0) || !std::isfinite(params.gap)
     || !(params.skin >= 0) || !std::isfinite(params.skin)
     || !(params.farGap >= 0) || !std::isfinite(params.farGap)
    )
    {
        throw std::invalid_argument
        (
            "NeighbourSearch: gap, farGap and skin must be finite and >= 0,"
            " got gap " + std::to_string(params.gap) + ", farGap "
          + std::to_string(params.farGap) + ", skin "
          + std::to_string(params.skin)
        );
    }
}


void NeighbourSearch::accumulate
(
    const Particles& particles,
    const std::vector<Vec3>& Uinf,
    double dt,
    double maxGradU
)
{
    if (Uinf.size() != particles.size() || !(dt >= 0) || !(maxGradU >= 0))
    {
        throw std::invalid_argument
        (
            "NeighbourSearch::accumulate: need U_inf at each of the "
          + std::to_string(particles.size()) + " particles (got "
          + std::to_string(Uinf.size()) + "), dt >= 0 (got "
          + std::to_string(dt) + ") and maxGradU >= 0 (got "
          + std::to_string(maxGradU) + ")"
        );
    }
    // Not built for these particles: the next update() rebuilds anyway
    if (path_.size() != particles.size())
    {
        return;
    }
    double m = maxPath_;
    #pragma omp parallel for reduction(max:m) schedule(static) \
        if(threaded(path_.size()))
    for (std::size_t i = 0; i < path_.size(); ++i)
    {
        path_[i] += (particles.u[i] - Uinf[i]).norm()*dt;
        m = std::max(m, path_[i]);
    }
    maxPath_ = m;
    time_ += dt;
    flowStrain_ += maxGradU*dt;
}


bool NeighbourSearch::needsRebuild() const
{
    // written so that a NaN path length also asks for a rebuild
    return !cells_ || !(2*maxPath_ + flowStrain_*range_ <= params_.skin);
}


bool NeighbourSearch::update
(
    Particles& particles,
    const LeesEdwardsBox& box,
    PairList& near
)
{
    if (built(particles, box, near) && !needsRebuild())
    {
        return false;
    }
    rebuild(particles, box, near);
    return true;
}


bool NeighbourSearch::built
(
    const Particles& particles,
    const LeesEdwardsBox& box,
    const PairList& near
) const
{
    return cells_
        && path_.size() == particles.size()
        && near.nParticles() == particles.size()
        && box.L() == cells_->L();
}


double NeighbourSearch::searchRange(double aMax) const
{
    return 2*aMax + (std::max(params_.gap, params_.farGap) + params_.skin);
}


void NeighbourSearch::rebuild
(
    Particles& particles,
    const LeesEdwardsBox& box,
    PairList& near
)
{
    checkList(particles, near);
    rebuild(particles, box, near, contacts(particles, near));
}


void NeighbourSearch::rebuild
(
    Particles& particles,
    const LeesEdwardsBox& box,
    PairList& near,
    const std::vector<KeyedContact>& contacts,
    double aMax
)
{
    const bool farList = params_.farGap > params_.gap;
    const double gap = params_.gap + params_.skin;
    const double searchGap = (farList ? params_.farGap : params_.gap) + params_.skin;
    const double range = searchRange(std::max(aMax, particles.maxRadius()));
    if (!cells_ || cells_->range() != range || cells_->L() != box.L())
    {
        cells_.emplace(box, range);
    }
    particles.permute(cells_->sort(particles.x));

    // The old rows released before the new ones are searched
    std::size_t freed = far_.bytes();
    far_ = PairRows();
    if (farList)
    {
        PairList half;
        cells_->findPairs(particles, box, searchGap, params_.stencil, half);
        dropGhostPairs(particles, half);
        nearPairs(particles, box, half, gap, near);
        far_.build(half.offset, half.j, false);
        dropGhostRows(particles, far_);
        freed += half.bytes();
    }
    else
    {
        cells_->findPairs(particles, box, gap, params_.stencil, near);
        dropGhostPairs(particles, near);
    }
    near.transpose();
    near.clearHistory();

    const std::size_t carried = restoreContacts(contacts, particles, near);

    path_.assign(particles.size(), 0.0);
    maxPath_ = 0;
    time_ = 0;
    flowStrain_ = 0;
    range_ = range;

    // What the rebuild freed back to the system, when it is worth a pass
    // over the heap (core/Memory.H)
    if (freed >= largeArrayBytes)
    {
        returnFreedMemory();
    }
    ++stats_.builds;
    stats_.carried = carried;
    stats_.dropped = carriedHere(particles, contacts) - carried;
    stats_.totalDropped += stats_.dropped;
}


std::size_t NeighbourSearch::bytes() const
{
    return (cells_ ? cells_->bytes() : 0) + path_.capacity()*sizeof(double)
         + far_.bytes();
}

} // namespace suspension
