#include "coarseGraining.H"
#include "inputChecks.H"
#include "mathematicalConstants.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Integral of the unit Hann window of width 1 from -1/2 to u
Foam::scalar cumulativeKernel(const Foam::scalar u)
{
    using Foam::constant::mathematical::twoPi;
    if (u <= -0.5)
    {
        return 0;
    }
    if (u >= 0.5)
    {
        return 1;
    }
    return u + 0.5 + std::sin(twoPi*u)/twoPi;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::coarseGraining::weights
(
    const direction d,
    const scalar s,
    const bool periodic,
    DynamicList<label>& index,
    DynamicList<scalar>& w
) const
{
    index.clear();
    w.clear();
    const scalarList& e = grid_.edges(d);
    const label n = grid_.n(d);
    for (label m = periodic ? -1 : 0; m <= (periodic ? 1 : 0); ++m)
    {
        const scalar c = s + m*grid_.box()[d];
        const scalar lo = c - 0.5*width_;
        const scalar hi = c + 0.5*width_;
        label k = label(std::upper_bound(e.begin(), e.end(), lo) - e.begin()) - 1;
        for (k = max(k, label(0)); k < n && e[k] < hi; ++k)
        {
            const scalar wk =
                cumulativeKernel((e[k + 1] - c)/width_)
              - cumulativeKernel((e[k] - c)/width_);
            if (wk > 0)
            {
                index.append(k);
                w.append(wk);
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coarseGraining::coarseGraining
(
    const fvMesh& mesh,
    const dictionary& dict,
    const vector& box,
    const scalar aMax
)
:
    grid_(mesh, box, "The coarse-graining of the particle stress"),
    width_
    (
        getScalarIn
        (
            dict, "width", interval(2*aMax, true, cmptMin(box), true)
        )
    )
{
    checkEntries(dict, {"width"});
}


// ************************************************************************* //
