#include "search/CellList.H"

#include "core/Parallel.H"
#include "core/Scratch.H"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace suspension
{

namespace
{
    //- Cells exceed the pair range by this relative margin (round-off)
    constexpr double cellMargin = 1e-9;

    //- Largest number of cells one stencil visits: 3 strips crossing the
    //  sheared boundary (4 cells each) and 6 ordinary strips (3 cells each)
    constexpr int maxStencilCells = 30;

    //- Cells (dxLo..dxHi, dy, dz) relative to the own cell
    struct Strip
    {
        int dy;
        int dz;
        int dxLo;
        int dxHi;
    };

    //- Own cell, dx = +1; dz = +1; the whole layer dy = +1 (13 + own)
    constexpr std::array<Strip, 5> halfStrips
    {{
        {0, 0, 0, 1},
        {0, 1, -1, 1},
        {1, -1, -1, 1}, {1, 0, -1, 1}, {1, 1, -1, 1}
    }};

    //- All 27 cells
    constexpr std::array<Strip, 9> fullStrips
    {{
        {-1, -1, -1, 1}, {-1, 0, -1, 1}, {-1, 1, -1, 1},
        {0, -1, -1, 1}, {0, 0, -1, 1}, {0, 1, -1, 1},
        {1, -1, -1, 1}, {1, 0, -1, 1}, {1, 1, -1, 1}
    }};

    //- The bits of v (up to 21) spread to every third bit
    std::uint64_t spreadBits(std::uint64_t v)
    {
        std::uint64_t r = 0;
        for (int b = 0; b < 21; ++b)
        {
            r |= ((v >> b) & 1u) << (3*b);
        }
        return r;
    }

    //- The (x, y, z) indices of cell c = x + n_x (y + n_y z)
    Eigen::Vector3i coordinates(const Eigen::Vector3i& n, std::uint32_t c)
    {
        const int ci = static_cast<int>(c);
        return Eigen::Vector3i(ci % n.x(), (ci/n.x()) % n.y(), ci/(n.x()*n.y()));
    }

    //- Morton (Z-order) key of the cell (x, y, z): their bits interleaved
    std::uint64_t mortonKey(int x, int y, int z)
    {
        return spreadBits(std::uint64_t(x))
            | spreadBits(std::uint64_t(y)) << 1
            | spreadBits(std::uint64_t(z)) << 2;
    }

    //- Floor of i/n for n > 0
    int floorDiv(int i, int n)
    {
        return i >= 0 ? i/n : -((n - 1 - i)/n);
    }

    std::string str(const Vec3& v)
    {
        return "(" + std::to_string(v.x()) + " " + std::to_string(v.y()) + " "
            + std::to_string(v.z()) + ")";
    }

    //- A cell of the stencil and the image shift of its particles: the
    //  partner j is seen at x_j + shift
    struct NeighbourCell
    {
        std::uint32_t cell;
        Vec3 shift;
    };

    //- Cells searched from cell c, with their images. `shift` =
    //  floor(delta/h_x) places the x-window of the rows across the sheared
    //  boundary (CellList.H).
    template<std::size_t S>
    int neighbourCells
    (
        const Eigen::Vector3i& n,
        const Vec3& L,
        double delta,
        int shift,
        const Eigen::Vector3i& c,
        const std::array<Strip, S>& strips,
        std::array<NeighbourCell, maxStencilCells>& cells
    )
    {
        int count = 0;
        for (const Strip& s : strips)
        {
            int jy = c.y() + s.dy;
            int xBegin = c.x() + s.dxLo;
            int width = s.dxHi - s.dxLo + 1;
            Vec3 image = Vec3::Zero();
            if (jy == n.y())            // image above, displaced by +delta
            {
                jy = 0;
                xBegin = c.x() - shift - 2;
                width = 4;
                image = Vec3(delta, L.y(), 0);
            }
            else if (jy == -1)          // image below, displaced by -delta
            {
                jy = n.y() - 1;
                xBegin = c.x() + shift - 1;
                width = 4;
                image = Vec3(-delta, -L.y(), 0);
            }
            const int kz = floorDiv(c.z() + s.dz, n.z());
            const int jz = c.z() + s.dz - kz*n.z();
            image.z() += kz*L.z();
            for (int k = 0; k < width; ++k)
            {
                const int kx = floorDiv(xBegin + k, n.x());
                const int jx = xBegin + k - kx*n.x();
                cells[count++] = NeighbourCell
                {
                    static_cast<std::uint32_t>((jz*n.y() + jy)*n.x() + jx),
                    image + Vec3(kx*L.x(), 0, 0)
                };
            }
        }
        return count;
    }

    //- Chunks of work for the threads; the list does not depend on it
    std::size_t nChunks()
    {
        return 8*static_cast<std::size_t>(omp_get_max_threads());
    }

    //- Build the CSR list from chunks of consecutive rows in parallel.
    //  fill(k, partners, count) appends the partners of rows
    //  [rowBegin[k], rowBegin[k+1]) to `partners`, row by row, and stores
    //  the number of partners of row i in count[i]. The rows are
    //  concatenated in order, so the result is independent of the threads.
    template<class Fill>
    void assemble
    (
        const std::vector<std::size_t>& rowBegin,
        const Fill& fill,
        PairList& list
    )
    {
        const std::size_t N = rowBegin.back();
        const std::size_t K = rowBegin.size() - 1;
        std::vector<std::vector<std::uint32_t>> partners(K);
        std::vector<std::uint32_t> count(N);

        #pragma omp parallel for schedule(dynamic) if(threaded(N))
        for (std::size_t k = 0; k < K; ++k)
        {
            fill(k, partners[k], count);
        }

        list.offset.resize(N + 1);
        std::size_t total = 0;
        for (std::size_t i = 0; i < N; ++i)
        {
            list.offset[i] = static_cast<std::uint32_t>(total);
            total += count[i];
        }
        if (total > std::numeric_limits<std::uint32_t>::max())
        {
            throw std::overflow_error
            (
                "CellList: " + std::to_string(total)
              + " pairs overflow the 32-bit PairList offsets"
            );
        }
        list.offset[N] = static_cast<std::uint32_t>(total);

        resizeScratch(list.j, total);
        #pragma omp parallel for schedule(static) if(threaded(N))
        for (std::size_t k = 0; k < K; ++k)
        {
            std::copy
            (
                partners[k].begin(), partners[k].end(),
                list.j.begin() + list.offset[rowBegin[k]]
            );
        }
        list.offsetT.clear();
        list.slotT.clear();
        list.contactOf.clear();
        list.contacts.clear();
    }

    void checkCount(std::size_t N)
    {
        if (N >= std::numeric_limits<std::uint32_t>::max())
        {
            throw std::overflow_error
            (
                "CellList: " + std::to_string(N)
              + " particles overflow the 32-bit pair indices"
            );
        }
    }
}


CellList::CellList(const LeesEdwardsBox& box, double range)
:
    L_(box.L()),
    range_(range),
    n_(Eigen::Vector3i::Zero()),
    h_(Vec3::Zero()),
    cellStart_(),
    cellAt_(),
    rank_()
{
    if (!(range > 0) || !std::isfinite(range))
    {
        throw std::invalid_argument
        (
            "CellList: the pair range (cut-off) must be positive and finite, got "
          + std::to_string(range)
        );
    }
    if (!fits(L_, range))
    {
        throw std::invalid_argument
        (
            "CellList: box " + str(L_) + " too small for the cut-off "
          + std::to_string(range) + " (2 a_max + gap + skin): every box length"
            " must be at least 3 cut-offs ("
          + std::to_string(smallestLength(range)) + ")"
        );
    }
    const Vec3 cells = L_/(range*(1 + cellMargin));
    if (cells.prod() > std::numeric_limits<std::uint32_t>::max())
    {
        throw std::invalid_argument
        (
            "CellList: box " + str(L_) + " holds too many cells of size "
          + std::to_string(range)
        );
    }
    for (int d = 0; d < 3; ++d)
    {
        n_[d] = static_cast<int>(std::floor(cells[d]));
        h_[d] = L_[d]/n_[d];
    }

    // The cells in Morton order: rank by the interleaved bits of (x, y, z)
    const std::size_t nCells = static_cast<std::size_t>(n_.prod());
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(nCells);
    for (std::size_t c = 0; c < nCells; ++c)
    {
        const Eigen::Vector3i x = coordinates(n_, static_cast<std::uint32_t>(c));
        keys[c] = {mortonKey(x.x(), x.y(), x.z()), static_cast<std::uint32_t>(c)};
    }
    std::sort(keys.begin(), keys.end());
    cellAt_.resize(nCells);
    rank_.resize(nCells);
    for (std::size_t k = 0; k < nCells; ++k)
    {
        cellAt_[k] = keys[k].second;
        rank_[keys[k].second] = static_cast<std::uint32_t>(k);
    }
}


bool CellList::fits(const Vec3& L, double range)
{
    return (L/(range*(1 + cellMargin))).minCoeff() >= 3;
}


double CellList::smallestLength(double range)
{
    return 3*range*(1 + cellMargin);
}


std::uint32_t CellList::cellOf(const Vec3& x) const
{
    Eigen::Vector3i c;
    for (int d = 0; d < 3; ++d)
    {
        if (!(x[d] >= 0 && x[d] < L_[d]))
        {
            throw std::invalid_argument
            (
                "CellList: particle at " + str(x) + " outside the box "
              + str(L_) + "; wrap it first (LeesEdwardsBox::wrap)"
            );
        }
        c[d] = std::min(static_cast<int>(x[d]/h_[d]), n_[d] - 1);
    }
    return static_cast<std::uint32_t>((c.z()*n_.y() + c.y())*n_.x() + c.x());
}


std::vector<std::size_t> CellList::sort(const std::vector<Vec3>& x)
{
    const std::size_t N = x.size();
    checkCount(N);
    const std::size_t nCells = static_cast<std::size_t>(n_.prod());

    // counts, prefix sum, stable scatter
    std::vector<std::uint32_t> cell(N);
    cellStart_.assign(nCells + 1, 0);
    for (std::size_t i = 0; i < N; ++i)
    {
        cell[i] = rank_[cellOf(x[i])];
        ++cellStart_[cell[i] + 1];
    }
    for (std::size_t c = 0; c < nCells; ++c)
    {
        cellStart_[c + 1] += cellStart_[c];
    }
    std::vector<std::uint32_t> next(cellStart_.begin(), cellStart_.end() - 1);
    std::vector<std::size_t> order(N);
    for (std::size_t i = 0; i < N; ++i)
    {
        order[next[cell[i]]++] = i;
    }
    return order;
}


void CellList::checkSorted(const std::vector<Vec3>& x) const
{
    const std::size_t nCells = static_cast<std::size_t>(n_.prod());
    bool sorted = cellStart_.size() == nCells + 1 && cellStart_.back() == x.size();
    for (std::size_t c = 0; sorted && c < nCells; ++c)
    {
        for (std::size_t i = cellStart_[c]; i < cellStart_[c + 1]; ++i)
        {
            sorted = sorted && rank_[cellOf(x[i])] == c;
        }
    }
    if (!sorted)
    {
        throw std::logic_error
        (
            "CellList::findPairs: particles not in the order of the last"
            " sort() (call sort() and Particles::permute first)"
        );
    }
}


void CellList::findPairs
(
    const Particles& particles,
    const LeesEdwardsBox& box,
    double gap,
    Stencil stencil,
    PairList& list
) const
{
    if (stencil == Stencil::bruteForce)
    {
        bruteForcePairs(particles, box, gap, list);
        return;
    }
    if (box.L() != L_)
    {
        throw std::invalid_argument
        (
            "CellList::findPairs: box " + str(box.L())
          + " differs from the lattice's box " + str(L_)
        );
    }
    if (!(2*particles.maxRadius() + gap <= range_))
    {
        throw std::invalid_argument
        (
            "CellList::findPairs: pair range 2 a_max + gap = "
          + std::to_string(2*particles.maxRadius() + gap)
          + " exceeds the lattice's range " + std::to_string(range_)
        );
    }
    checkSorted(particles.x);

    const bool full = stencil == Stencil::full;
    const double delta = box.offset();
    const int shift = static_cast<int>(std::floor(delta/h_.x()));
    const std::size_t nCells = static_cast<std::size_t>(n_.prod());

    // chunks of whole cells, so that each chunk holds consecutive rows
    const std::size_t K = std::min(nChunks(), nCells);
    std::vector<std::size_t> cellBegin(K + 1), rowBegin(K + 1);
    for (std::size_t k = 0; k <= K; ++k)
    {
        cellBegin[k] = k*nCells/K;
        rowBegin[k] = cellStart_[cellBegin[k]];
    }

    auto fill = [&]
    (
        std::size_t k,
        std::vector<std::uint32_t>& partners,
        std::vector<std::uint32_t>& count
    )
    {
        std::array<NeighbourCell, maxStencilCells> cells;
        for (std::size_t c = cellBegin[k]; c < cellBegin[k + 1]; ++c)
        {
            const Eigen::Vector3i coords = coordinates(n_, cellAt_[c]);
            const int nNb = full
              ? neighbourCells(n_, L_, delta, shift, coords, fullStrips, cells)
              : neighbourCells(n_, L_, delta, shift, coords, halfStrips, cells);

            for (std::size_t i = cellStart_[c]; i < cellStart_[c + 1]; ++i)
            {
                const std::size_t before = partners.size();
                for (int b = 0; b < nNb; ++b)
                {
                    // |x_j + shift - x_i| < a_i + a_j + gap
                    const Vec3 xi = particles.x[i] - cells[b].shift;
                    const std::uint32_t nb = rank_[cells[b].cell];
                    std::size_t jBegin = cellStart_[nb];
                    if (full || nb == c)
                    {
                        jBegin = std::max<std::size_t>(jBegin, i + 1);
                    }
                    for (std::size_t j = jBegin; j < cellStart_[nb + 1]; ++j)
                    {
                        const double R = particles.a[i] + particles.a[j] + gap;
                        if ((particles.x[j] - xi).squaredNorm() < R*R)
                        {
                            partners.push_back(static_cast<std::uint32_t>(j));
                        }
                    }
                }
                count[i] = static_cast<std::uint32_t>(partners.size() - before);
            }
        }
    };

    assemble(rowBegin, fill, list);
}


std::size_t CellList::bytes() const
{
    return (cellStart_.capacity() + cellAt_.capacity() + rank_.capacity())
        *sizeof(std::uint32_t);
}


void bruteForcePairs
(
    const Particles& particles,
    const LeesEdwardsBox& box,
    double gap,
    PairList& list
)
{
    const std::size_t N = particles.size();
    checkCount(N);
    const std::size_t K = std::max<std::size_t>(1, std::min(nChunks(), N));
    std::vector<std::size_t> rowBegin(K + 1);
    for (std::size_t k = 0; k <= K; ++k)
    {
        rowBegin[k] = k*N/K;
    }

    auto fill = [&]
    (
        std::size_t k,
        std::vector<std::uint32_t>& partners,
        std::vector<std::uint32_t>& count
    )
    {
        for (std::size_t i = rowBegin[k]; i < rowBegin[k + 1]; ++i)
        {
            const std::size_t before = partners.size();
            for (std::size_t j = i + 1; j < N; ++j)
            {
                Vec3 r = particles.x[j] - particles.x[i];
                box.minimumImage(r);
                const double R = particles.a[i] + particles.a[j] + gap;
                if (r.squaredNorm() < R*R)
                {
                    partners.push_back(static_cast<std::uint32_t>(j));
                }
            }
            count[i] = static_cast<std::uint32_t>(partners.size() - before);
        }
    };

    assemble(rowBegin, fill, list);
}

} // namespace suspension
